// SPDX-License-Identifier: GPL-3.0-or-later
// Injury criteria against closed forms and risk functions at their defining points.
//  HIC of a half-sine a(t) = A sin(pi t / T): for a symmetric window of width w the integral
//  is (2 A T / pi) sin(u), u = pi w / (2 T), so HIC(w) = (2AT/pi)^2.5 sin(u)^2.5 / w^1.5.
//  dHIC/du = 0 gives tan u = 5u/3 (u* = 1.0517, w* = 0.6695 T); when w* exceeds the window
//  limit the window itself is the optimum.
//  a3ms of the half-sine: the time above level L is T - (2T/pi) asin(L/A); 3 ms of it gives
//  L = A sin(pi (T - 3 ms) / (2T)).
//  VC of d = D sin(w t): V = D w cos(w t), so max VC = SF D^2 w / (2 D0).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hbm/corridors/injury_criteria.hpp"
#include "hbm/corridors/risk_functions.hpp"

using namespace hbm::corridors;

namespace {

constexpr double pi = std::numbers::pi;

double hic_half_sine_closed_form(double a_g, double t_s, double window_s) {
  // solve tan u = 5u/3 on (0.9, 1.3) by bisection
  double lo = 0.9, hi = 1.3;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::tan(mid) - 5.0 * mid / 3.0 > 0.0 ? hi : lo) = mid;
  }
  double u = 0.5 * (lo + hi);
  double w = 2.0 * t_s * u / pi;
  if (w > window_s) {
    w = window_s;
    u = pi * w / (2.0 * t_s);
  }
  return std::pow(2.0 * a_g * t_s / pi, 2.5) * std::pow(std::sin(u), 2.5) / std::pow(w, 1.5);
}

void half_sine(double a, double t_ms, double dt_ms, std::vector<double>& t, std::vector<double>& y) {
  t.clear();
  y.clear();
  for (double ti = -5.0; ti <= t_ms + 5.0 + 1e-9; ti += dt_ms) {
    t.push_back(ti);
    y.push_back(ti > 0.0 && ti < t_ms ? a * std::sin(pi * ti / t_ms) : 0.0);
  }
}

}  // namespace

TEST(Hic, HalfSineMatchesClosedForm) {
  std::vector<double> t, a;
  struct Case {
    double amplitude_g, duration_ms, window_ms;
  };
  for (const Case c : {Case{80.0, 10.0, 15.0}, Case{50.0, 40.0, 15.0}, Case{50.0, 40.0, 36.0}, Case{120.0, 6.0, 36.0}}) {
    half_sine(c.amplitude_g, c.duration_ms, 0.01, t, a);
    const auto h = head_injury_criterion(t, a, c.window_ms);
    const double expected = hic_half_sine_closed_form(c.amplitude_g, c.duration_ms * 1e-3, c.window_ms * 1e-3);
    EXPECT_NEAR(h.value, expected, 2e-3 * expected)
        << "A " << c.amplitude_g << " g, T " << c.duration_ms << " ms, window " << c.window_ms << " ms";
    // optimal window is centred on the peak
    EXPECT_NEAR(0.5 * (h.t1 + h.t2), 0.5 * c.duration_ms, 0.02);
    EXPECT_LE(h.t2 - h.t1, c.window_ms + 1e-9);
  }
}

TEST(A3ms, HalfSineMatchesClosedForm) {
  std::vector<double> t, a;
  for (double T : {10.0, 20.0, 60.0}) {
    half_sine(60.0, T, 0.01, t, a);
    const double expected = 60.0 * std::sin(pi * (T - 3.0) / (2.0 * T));
    // sampling at 0.01 ms moves the 3 ms level by at most A (pi/T) 0.01 ms
    const double tol = 60.0 * pi / T * 0.011;
    EXPECT_NEAR(a3ms_cumulative(t, a), expected, tol) << "T = " << T;
    // a single hump: the continuous and cumulative variants coincide
    EXPECT_NEAR(a3ms_continuous(t, a).value, expected, tol) << "T = " << T;
  }
}

TEST(ViscousCriterion, SinusoidMatchesClosedForm) {
  const double d_amp = 40.0, w = 2.0 * pi / 60.0;  // mm, rad/ms (60 ms period)
  std::vector<double> t, d;
  for (int i = 0; i <= 3000; ++i) {
    t.push_back(i * 0.01);
    d.push_back(d_amp * std::sin(w * t.back()));
  }
  const auto vc = viscous_criterion(t, d, 1.3, 229.0);
  const double expected = 1.3 * d_amp * d_amp * w / (2.0 * 229.0);  // mm/ms = m/s
  double mx = 0.0;
  for (double v : vc) mx = std::max(mx, v);
  EXPECT_NEAR(mx, expected, 1e-6 * expected);
}

TEST(Nij, InterceptsGiveOne) {
  const std::vector<double> t{0.0, 1.0, 2.0};
  // pure tension at the tension intercept
  auto r = neck_injury_criterion(t, {0.0, 6806.0, 0.0}, {0.0, 0.0, 0.0}, {});
  EXPECT_NEAR(r.value, 1.0, 1e-12);
  EXPECT_EQ(r.mode, "NTF");  // zero moment counts as flexion
  // half the compression intercept plus half the extension intercept
  r = neck_injury_criterion(t, {0.0, -3080.0, 0.0}, {0.0, -67.5, 0.0}, {});
  EXPECT_NEAR(r.value, 1.0, 1e-12);
  EXPECT_EQ(r.mode, "NCE");
  EXPECT_NEAR(r.t_ms, 1.0, 0.0);
  // occipital condyle correction My - e Fx: Fx = 1000 N gives -17.78 N m (extension)
  r = neck_injury_criterion(t, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 1000.0, 0.0});
  EXPECT_NEAR(r.value, 17.78 / 135.0, 1e-12);
  EXPECT_EQ(r.mode, "NTE");
}

TEST(RiskFunctions, LaituriAtAge35IsTheNcapChestCurve) {
  // NHTSA NCAP (2008) Hybrid III chest: p = 1/(1+exp(10.5456 - 1.568 d^0.4612)) [check];
  // Laituri 2005 at age 35: 12.597 - 0.05861 * 35 = 10.54565.
  for (double d : {20.0, 40.0, 63.0, 80.0}) {
    const double ncap = 1.0 / (1.0 + std::exp(10.5456 - 1.568 * std::pow(d, 0.4612)));
    // NCAP rounds the constant to 4 decimals (|error| <= 5e-5), so p differs by <= 5e-5 p(1-p)
    EXPECT_NEAR(chest_deflection_ais3_risk_laituri2005(d, 35.0), ncap, 1.3e-5) << "d = " << d;
  }
  // 50 % point: 1.568 d^0.4612 = 12.597 - 0.05861 age
  const double age = 45.0;
  const double d50 = std::pow((12.597 - 0.05861 * age) / 1.568, 1.0 / 0.4612);
  EXPECT_NEAR(chest_deflection_ais3_risk_laituri2005(d50, age), 0.5, 1e-12);
  EXPECT_GT(chest_deflection_ais3_risk_laituri2005(50.0, 70.0), chest_deflection_ais3_risk_laituri2005(50.0, 30.0));
}

TEST(RiskFunctions, HicAndNijFiftyPercentPoints) {
  EXPECT_NEAR(hic15_ais3_risk_nhtsa(std::exp(7.45231)), 0.5, 1e-12);  // lognormal median
  EXPECT_NEAR(hic15_ais3_risk_nhtsa(std::exp(7.45231 + 0.73998)), standard_normal_cdf(1.0), 1e-12);
  EXPECT_NEAR(standard_normal_cdf(1.0), 0.841344746, 1e-9);
  EXPECT_NEAR(nij_ais3_risk_nhtsa(3.2269 / 1.9688), 0.5, 1e-12);
  EXPECT_LT(hic15_ais3_risk_nhtsa(700.0), hic15_ais3_risk_nhtsa(1000.0));
}
