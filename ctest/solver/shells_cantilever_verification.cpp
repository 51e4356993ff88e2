// SPDX-License-Identifier: GPL-3.0-or-later
// Verification (label verification), kernel level: a cantilever plate strip
// (L = 100 mm, b = 10 mm, t = 1 mm, steel E = 210 GPa, nu = 0.3, rho = 7.85e-6 kg/mm^3),
// clamped at x = 0, meshed 20 x 2 in quads (Belytschko-Tsay) and in triangles (DKT).
//  1. Static tip deflection under a tip load P (ramped, then held with mass-proportional
//     damping: dynamic relaxation) against beam theory delta = P L^3 / (3 E I),
//     I = b t^3 / 12, within 3%. (Free long edges: the anticlastic curvature is free and
//     linear plate theory gives E, not E/(1-nu^2), for the strip.)
//  2. First bending frequency of the free vibration after releasing the load, against
//     f1 = 1.8751^2 / (2 pi L^2) sqrt(E I / (rho b t)), within 3%.
#include "shells_harness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace hbm::solver::shells;
using hbm::solver::shells::test::build_strip;
using hbm::solver::shells::test::ShellHarness;

namespace {

struct CantileverResult {
  double delta = 0, freq = 0;
};

CantileverResult run_cantilever(bool tria) {
  const double L = 100, b = 10, t = 1, E = 210, nu = 0.3, rho = 7.85e-6;
  const int nx = 20, ny = 2;
  ShellHarness h;
  build_strip(h, tria, L, b, nx, ny, t);
  h.g.mat.law = ShellLaw::Elastic;
  h.g.mat.rho = rho;
  h.g.mat.E = E;
  h.g.mat.nu = nu;
  h.g.sec.set_points(3);
  h.finish();
  for (int j = 0; j <= ny; ++j) h.fixed[j].fill(1);
  const double I = b * t * t * t / 12;
  const double P = 3 * E * I * 0.5 / (L * L * L);  // about 0.5 mm deflection
  std::vector<int> tip;
  for (int j = 0; j <= ny; ++j) tip.push_back(nx * (ny + 1) + j);
  const int mid_tip = nx * (ny + 1) + ny / 2;
  const double f1 = 1.87510407 * 1.87510407 / (2 * std::numbers::pi * L * L) *
                    std::sqrt(E * I / (rho * b * t));
  const double w1 = 2 * std::numbers::pi * f1;
  h.forces(0.0);
  double dt = 1e300;
  for (double d : h.g.dt_elem) dt = std::min(dt, d);
  dt *= 0.8;
  // 1. Dynamic relaxation: ramp over 2 periods, damping 0.8 w1, hold 8 periods.
  h.damping = 0.8 * w1;
  const double T1 = 1.0 / f1, t_ramp = 2 * T1, t_end = 10 * T1;
  while (h.time < t_end) {
    const double s = std::min(1.0, h.time / t_ramp);
    for (int k = 0; k <= ny; ++k)
      h.fext[tip[k]][2] = s * P / ny * ((k == 0 || k == ny) ? 0.5 : 1.0);
    h.step(dt);
  }
  CantileverResult r;
  r.delta = h.z[mid_tip];
  // 2. Release: free vibration, no damping; period from upward zero crossings.
  h.damping = 0;
  for (int k = 0; k <= ny; ++k) h.fext[tip[k]][2] = 0;
  std::vector<double> crossings;
  double zprev = h.z[mid_tip], tprev = h.time;
  const double t_stop = h.time + 4.5 * T1;
  while (h.time < t_stop) {
    h.step(dt);
    const double zc = h.z[mid_tip];
    if (zprev < 0 && zc >= 0) crossings.push_back(tprev + (h.time - tprev) * (-zprev) / (zc - zprev));
    zprev = zc;
    tprev = h.time;
  }
  if (crossings.size() >= 2)
    r.freq = (crossings.size() - 1) / (crossings.back() - crossings.front());
  return r;
}

void check(bool tria) {
  const double L = 100, b = 10, t = 1, E = 210, rho = 7.85e-6;
  const double I = b * t * t * t / 12;
  const double P = 3 * E * I * 0.5 / (L * L * L);
  const double delta_beam = P * L * L * L / (3 * E * I);
  const double f_beam = 1.87510407 * 1.87510407 / (2 * std::numbers::pi * L * L) *
                        std::sqrt(E * I / (rho * b * t));
  const CantileverResult r = run_cantilever(tria);
  std::printf("%s: tip deflection %.6f mm (beam %.6f, %+.2f%%), f1 %.6f kHz (beam %.6f, %+.2f%%)\n",
              tria ? "SH3N DKT" : "SHELL BT", r.delta, delta_beam,
              100 * (r.delta / delta_beam - 1), r.freq, f_beam, 100 * (r.freq / f_beam - 1));
  EXPECT_NEAR(r.delta, delta_beam, 0.03 * delta_beam);
  EXPECT_NEAR(r.freq, f_beam, 0.03 * f_beam);
}

}  // namespace

TEST(ShellCantilever, QuadStaticDeflectionAndFirstFrequency) { check(false); }
TEST(ShellCantilever, TriaStaticDeflectionAndFirstFrequency) { check(true); }
