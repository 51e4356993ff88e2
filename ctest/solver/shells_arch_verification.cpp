// SPDX-License-Identifier: GPL-3.0-or-later
// Verification (label verification), kernel level: a rib-like curved shell arch.
// A half-ring band (radius R = 60 mm to the mid-surface, band height b = 10 mm, wall
// t = 2 mm, cortical-bone-like E = 10 GPa, nu = 0.3), the posterior end clamped (spine),
// the anterior end loaded towards the posterior end along the chord (anterior-posterior
// compression of a rib). Castigliano on the curved beam, with M = P R sin(phi),
// N = -P sin(phi), V = P cos(phi):
//   delta = pi P R / 2 (R^2 / (E I) + 1 / (E A) + 1 / (k G A)),  I = b t^3 / 12, A = b t.
// The static stiffness P / delta (dynamic relaxation) matches within 10%, for a mesh of
// triangles (DKT, as the rib cage) and of quads (Belytschko-Tsay).
#include "shells_harness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace hbm::solver::shells;
using hbm::solver::shells::test::ShellHarness;

namespace {

double arch_stiffness_ratio(bool tria) {
  const double R = 60, b = 10, t = 2, E = 10, nu = 0.3, rho = 2e-6;
  const int nphi = 36, ny = 2;
  const double pi = std::numbers::pi;
  ShellHarness h;
  for (int i = 0; i <= nphi; ++i)
    for (int j = 0; j <= ny; ++j) {
      const double phi = pi * i / nphi;
      h.add_node(R * std::cos(phi), R * std::sin(phi), b * j / ny);
    }
  auto id = [&](int i, int j) { return i * (ny + 1) + j; };
  h.g.kind = tria ? ShellKind::TriaDKT : ShellKind::QuadBT;
  for (int i = 0; i < nphi; ++i)
    for (int j = 0; j < ny; ++j) {
      const int a = id(i, j), bb = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (!tria) {
        h.add_element({a, bb, c, d}, t);
      } else if ((i + j) % 2 == 0) {
        h.add_element({a, bb, c}, t);
        h.add_element({a, c, d}, t);
      } else {
        h.add_element({a, bb, d}, t);
        h.add_element({bb, c, d}, t);
      }
    }
  h.g.mat.law = ShellLaw::Elastic;
  h.g.mat.rho = rho;
  h.g.mat.E = E;
  h.g.mat.nu = nu;
  h.g.sec.set_points(3);
  h.finish();
  for (int j = 0; j <= ny; ++j) h.fixed[id(0, j)].fill(1);
  const double I = b * t * t * t / 12, A = b * t, G = E / (2 * (1 + nu));
  const double compliance = pi * R / 2 * (R * R / (E * I) + 1 / (E * A) + 1 / (5.0 / 6.0 * G * A));
  const double P = 0.5 / compliance;  // about 0.5 mm
  // Lowest mode estimate for the damping: k = 1/compliance, a third of the mass moving.
  const double mass = rho * pi * R * b * t;
  const double w1 = std::sqrt(1 / compliance / (mass / 3));
  h.forces(0.0);
  double dt = 1e300;
  for (double d : h.g.dt_elem) dt = std::min(dt, d);
  dt *= 0.8;
  h.damping = 0.8 * w1;
  const double T1 = 2 * pi / w1, t_ramp = 2 * T1, t_end = 12 * T1;
  double prev = 0, change = 1;
  while (h.time < t_end) {
    const double s = std::min(1.0, h.time / t_ramp);
    for (int j = 0; j <= ny; ++j)
      h.fext[id(nphi, j)][0] = s * P / ny * ((j == 0 || j == ny) ? 0.5 : 1.0);
    h.step(dt);
  }
  const double delta = h.x[id(nphi, ny / 2)] - (-R);
  // Converged: one more period changes the deflection by < 0.1%.
  const double t2 = h.time + T1;
  prev = delta;
  while (h.time < t2) h.step(dt);
  change = std::abs(h.x[id(nphi, ny / 2)] + R - prev) / std::abs(prev);
  EXPECT_LT(change, 1e-3);
  const double k_fe = P / delta, k_beam = 1 / compliance;
  std::printf("%s: arch stiffness %.6f kN/mm (curved beam %.6f kN/mm, %+.2f%%)\n",
              tria ? "SH3N DKT" : "SHELL BT", k_fe, k_beam, 100 * (k_fe / k_beam - 1));
  return k_fe / k_beam;
}

}  // namespace

TEST(ShellArch, TriaRibArchStiffnessMatchesCastigliano) {
  EXPECT_NEAR(arch_stiffness_ratio(true), 1.0, 0.10);
}
TEST(ShellArch, QuadRibArchStiffnessMatchesCastigliano) {
  EXPECT_NEAR(arch_stiffness_ratio(false), 1.0, 0.10);
}
