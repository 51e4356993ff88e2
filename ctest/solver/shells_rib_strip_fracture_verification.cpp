// SPDX-License-Identifier: GPL-3.0-or-later
// Verification of the rib fracture model's equivalent strip (hbm-deckgen --rib-fracture,
// deckgen/include/hbm/deckgen/rib_fracture.hpp) in the solver's own 3-node shell.
//
// A real rib section (hollow ellipse, width w in the bending direction) yields when its
// outer fibre reaches eps_y, i.e. at the curvature kappa_y = eps_y / (w / 2), and breaks at
// kappa_u = eps_u / (w / 2). The model carries the rib as a strip of thickness
// t_eq = sqrt(12 I / A) whose modulus is scaled to keep E I; rib_fracture.hpp scales the
// strip's yield stress and failure plastic strain so that its outer Gauss point yields and
// fails at those same curvatures. Here a strip of rib 5's mid-rib section (13 x 6 mm,
// 1.0 mm cortex, geometry/rib_cage.csv) and the bone of geometry/rib_fracture.csv at 45
// years is bent in pure bending (clamped end, prescribed end rotation, quasi-static) through
// the DKT triangle and its three-point Gauss integration, as in the body model; checked:
//  - the elastic moment M = E I_real kappa (2 %),
//  - the first plastic strain at kappa_y (3 %),
//  - the first element deletion (P_thick_fail 0.5: both outer points) at kappa_u (3 %).
#include "shells_harness.hpp"

// The strip section and plasticity formulas under test (plain arithmetic, shared with deckgen).
#include "../../deckgen/include/hbm/deckgen/rib_fracture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

using namespace hbm::solver::shells;
using hbm::solver::shells::test::build_strip;
using hbm::solver::shells::test::ShellHarness;

namespace {

struct BendingResult {
  double EI_measured = 0, EI_real = 0;
  double kappa_first_yield = 0, kappa_y = 0;
  double kappa_first_deletion = 0, kappa_u = 0;
};

BendingResult bend_rib_strip_to_fracture() {
  // Rib 5, mid-rib (geometry/rib_cage.csv): height 13, width 6, cortex 1.0 mm.
  const double h = 13, w = 6, tc = 1.0;
  const double A = hbm::deckgen::hollow_ellipse_area(h, w, tc), I = hbm::deckgen::hollow_ellipse_inertia(h, w, tc);
  const double t_eq = hbm::deckgen::equivalent_rib_thickness(h, w, tc);
  const double band = 20.0;              // strip width (the rib's band height in the model)
  const double s = A / (band * t_eq);    // modulus and density scale
  // Bone (geometry/rib_fracture.csv, E from materials.csv rib_cortical), GPa.
  hbm::deckgen::RibBoneFailure bone;
  bone.E = 14.7;
  bone.yield_stress = 0.1014;
  bone.plastic_modulus = 2.493;
  bone.log_median_intercept = -2.9866;
  bone.log_median_age_slope = -0.013;
  const double age = 45;
  const auto sp = hbm::deckgen::strip_plasticity(bone, age, s, t_eq / w, hbm::deckgen::three_point_outer_zeta());

  const double L = 60;
  const int nx = 12, ny = 1;  // one triangle pair across, as the model's rib bands
  ShellHarness hs;
  build_strip(hs, true, L, band, nx, ny, t_eq);
  hs.g.mat.law = ShellLaw::JohnsonCook;
  hs.g.mat.rho = 2e-6 * s;
  hs.g.mat.E = bone.E * s;
  hs.g.mat.nu = 0.3;
  hs.g.mat.plasticity.jc.a = sp.yield_stress;
  hs.g.mat.plasticity.jc.b = sp.plastic_modulus;
  hs.g.mat.plasticity.jc.n = 1.0;
  hs.g.mat.plasticity.eps_p_max = sp.eps_p_max;
  hs.g.sec.set_points(3);
  hs.g.sec.fail_points = 2;  // P_thick_fail 0.5 of 3 points
  hs.finish();
  auto id = [&](int i, int j) { return i * (ny + 1) + j; };
  // Root: x, z and the rotation about y held, the rotation about x free, so that the
  // anticlastic curvature is not restrained there either (a clamp would make the root
  // plane strain and fail it first); y held at one node against rigid motion.
  for (int j = 0; j <= ny; ++j) hs.fixed[id(0, j)][0] = hs.fixed[id(0, j)][2] = hs.fixed[id(0, j)][4] = 1;
  hs.fixed[id(0, 0)][1] = 1;
  for (int j = 0; j <= ny; ++j) hs.fixed[id(nx, j)][4] = 1;  // prescribed rotation about y

  BendingResult r;
  r.EI_real = bone.E * I;
  r.kappa_y = bone.yield_strain() / (w / 2);
  r.kappa_u = bone.ultimate_strain(age) / (w / 2);
  // Quasi-static: end rotation at a rate ramped in over two periods of the cantilever's
  // first mode, to 1.15 kappa_u L over 40 periods, with light mass-proportional damping.
  const double EI_strip = hs.g.mat.E * band * t_eq * t_eq * t_eq / 12;
  const double f1 = 1.875 * 1.875 / (2 * std::numbers::pi * L * L) * std::sqrt(EI_strip / (hs.g.mat.rho * band * t_eq));
  const double T1 = 1 / f1, t_load = 40 * T1;
  const double theta_end = 1.15 * r.kappa_u * L;
  const double wmax = theta_end / (t_load - T1);
  double theta = 0;
  auto rate = [&](double tt) { return wmax * (tt < 2 * T1 ? 0.5 * (1 - std::cos(std::numbers::pi * tt / (2 * T1))) : 1.0); };
  auto prescribed = [&](std::size_t n, int c, double tt) {
    return (c == 4 && static_cast<int>(n) >= id(nx, 0)) ? rate(tt) : 0.0;
  };
  hs.damping = 0.05 * 2 * std::numbers::pi * f1;
  hs.forces(0.0);
  double dt = 1e300;
  for (double d : hs.g.dt_elem) dt = std::min(dt, d);
  dt *= 0.8;
  double ei_sum = 0;
  int ei_n = 0;
  while (hs.time < t_load && r.kappa_first_deletion == 0) {
    theta += rate(hs.time + 0.5 * dt) * dt;
    const ShellKernelTotals tot = hs.step(dt, prescribed);
    const double kappa = theta / L;
    double M = 0;
    for (int j = 0; j <= ny; ++j) M += hs.reaction[id(nx, j)][4];
    if (kappa > 0.3 * r.kappa_y && kappa < 0.7 * r.kappa_y) {  // elastic range, after the ramp
      ei_sum += std::abs(M) / kappa;
      ++ei_n;
    }
    if (r.kappa_first_yield == 0)
      for (double e : hs.g.epsp)
        if (e > 0) {
          r.kappa_first_yield = kappa;
          break;
        }
    if (tot.newly_deleted) r.kappa_first_deletion = kappa;
  }
  r.EI_measured = ei_n ? ei_sum / ei_n : 0;
  std::printf("rib 5 strip (t_eq %.3f mm, fibre ratio %.3f): E I %.2f vs %.2f kN mm^2; first yield at kappa %.5f /mm "
              "(section %.5f); first deletion at %.5f /mm (section %.5f, eps_u %.4f at %.0f y)\n",
              t_eq, t_eq / w, r.EI_measured, r.EI_real, r.kappa_first_yield, r.kappa_y, r.kappa_first_deletion, r.kappa_u,
              bone.ultimate_strain(age), age);
  return r;
}

}  // namespace

TEST(RibStripFracture, YieldsAndBreaksAtTheRealSectionsCurvatures) {
  const BendingResult r = bend_rib_strip_to_fracture();
  EXPECT_NEAR(r.EI_measured / r.EI_real, 1.0, 0.02);
  ASSERT_GT(r.kappa_first_yield, 0.0) << "the strip never yielded";
  EXPECT_NEAR(r.kappa_first_yield / r.kappa_y, 1.0, 0.03);
  ASSERT_GT(r.kappa_first_deletion, 0.0) << "no element was deleted";
  EXPECT_NEAR(r.kappa_first_deletion / r.kappa_u, 1.0, 0.03);
}
