// SPDX-License-Identifier: GPL-3.0-or-later
// Strain-rate filter of LAW36 (OpenRadioss mstrain_rate.F): r_n = a r + (1 - a) r_{n-1},
// a = min(1, 2 pi F_cut dt). Under a constant rate r from rest the recursion has the closed
// form r_n = r (1 - (1 - a)^n); at a solid material point under an imposed constant shear
// rate the yield stress follows the curves interpolated at that r_n, step by step.
#include "hbm/solver/function_curve.hpp"
#include "solid/solid_material.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace hbm::solver;

TEST(MaterialStrainRateFilter, ConstantRateFollowsTheClosedForm) {
  const double omega = 2.0 * std::numbers::pi * 0.5, dt = 1.5e-3, r = 0.02;  // F_cut 0.5 /ms
  const double a = omega * dt;
  double state = 0.0;
  for (int n = 1; n <= 2000; ++n) {
    const double got = filtered_strain_rate(omega, dt, r, state);
    EXPECT_NEAR(got, r * (1.0 - std::pow(1.0 - a, n)), 1e-12 * r) << "step " << n;
    EXPECT_EQ(got, state);
  }
  // a capped at 1: a cutoff above 1 / (2 pi dt) passes the rate of the step unchanged.
  state = 5.0;
  EXPECT_EQ(filtered_strain_rate(1.0 / dt * 3.0, dt, r, state), r);
}

TEST(MaterialStrainRateFilter, SolidYieldStressFollowsTheFilteredRate) {
  // LAW36, perfectly plastic curves: 3e-4 at rate 0, 6e-4 at rate R = 0.05 /ms (GPa, ms).
  const FunctionCurve low(1, "static", {0.0, 1.0}, {3e-4, 3e-4});
  const FunctionCurve high(2, "fast", {0.0, 1.0}, {6e-4, 6e-4});
  SolidMaterial m;
  m.law = SolidLaw::Tabulated;
  m.set_elastic(0.2, 0.3);
  m.plasticity.kind = PlasticityLaw::Kind::Tabulated;
  m.plasticity.tab.curves = {&low, &high};
  m.plasticity.tab.scales = {1.0, 1.0};
  m.plasticity.tab.rates = {0.0, 0.05};
  m.plasticity.rate_filter = 2.0 * std::numbers::pi * 0.5;  // F_cut 0.5 /ms
  const double dt = 1.5e-3, dxy = 0.0173205080756888;       // D_xy [1/ms]
  // sqrt(2/3 D':D') with D':D' = 2 D_xy^2: r = 0.02 /ms, 40 % of R.
  const double r = std::sqrt(4.0 / 3.0) * dxy;
  const double a = m.plasticity.rate_filter * dt;
  double sig[6] = {0, 0, 0, 0, 0, 0}, ep = 0.0, rate = 0.0, out[6];
  const double d[6] = {0, 0, 0, dxy, 0, 0};
  int plastic_steps = 0;
  for (int n = 1; n <= 1500; ++n) {
    const SolidPointState st{sig, nullptr, &ep, &rate};
    const double dl = update_solid_stress(m, st, d, 0.0, 0.0, 0.0, dt, out);
    const double rn = r * (1.0 - std::pow(1.0 - a, n));
    EXPECT_NEAR(rate, rn, 1e-12 * r) << "step " << n;
    if (dl > 0.0) {  // on the yield surface: von Mises = sigma_y(r_n)
      ++plastic_steps;
      const double sy = 3e-4 + 3e-4 * rn / 0.05;
      EXPECT_NEAR(std::sqrt(3.0) * out[3], sy, 1e-9 * sy) << "step " << n;
    }
  }
  EXPECT_GT(plastic_steps, 1000);
  // Without the filter the yield stress is the one at r from the first plastic step on
  // (after 200 steps, 0.3 ms, the filtered rate is 0.61 r: yield 6 % lower).
  SolidMaterial raw = m;
  raw.plasticity.rate_filter = 0.0;
  double sig_raw[6] = {0, 0, 0, 0, 0, 0}, ep_raw = 0.0;
  for (int n = 1; n <= 200; ++n) {
    const SolidPointState st{sig_raw, nullptr, &ep_raw};
    update_solid_stress(raw, st, d, 0.0, 0.0, 0.0, dt, out);
  }
  EXPECT_NEAR(std::sqrt(3.0) * out[3], 3e-4 + 3e-4 * r / 0.05, 1e-9);
}

// Johnson-Cook SIG_max0 and the rate term f = 1 + c ln(rate / eps_dot0) (OpenRadioss m2law.F):
// ICC 0/1 caps the yield at SIG_max0 f, ICC 2 at SIG_max0. a = 1, b = 0, c = 0.1, rate e^2
// eps_dot0: f = 1.2; SIG_max0 = 1.1 -> yield 1.2 (ICC 1), 1.1 (ICC 2).
TEST(MaterialStrainRateFilter, JohnsonCookSigMaxFollowsIcc) {
  JohnsonCookHardening jc;
  jc.a = 1.0;
  jc.b = 0.0;
  jc.c = 0.1;
  jc.eps_dot0 = 1.0;
  jc.sig_max = 1.1;
  const double rate = std::exp(2.0);
  EXPECT_NEAR(jc.yield_stress(0.01, rate), 1.2, 1e-12);
  jc.rate_scales_sig_max = false;
  EXPECT_NEAR(jc.yield_stress(0.01, rate), 1.1, 1e-12);
  // With hardening, the slope is 0 once capped: a + b eps_p^n = 1 + 0.2 sqrt(0.25) = 1.1.
  jc.b = 0.2;
  jc.n = 0.5;
  jc.rate_scales_sig_max = true;
  EXPECT_NEAR(jc.yield_stress(0.25, rate), 1.1 * 1.2, 1e-12);
  EXPECT_GT(jc.slope(0.2, rate), 0.0);
  EXPECT_EQ(jc.slope(0.3, rate), 0.0);
}
