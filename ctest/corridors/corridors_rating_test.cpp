// SPDX-License-Identifier: GPL-3.0-or-later
// ISO/TS 18571 and CORA on constructed signals whose scores a formula fixes:
//  identical signals -> every score 1 exactly;
//  y(t) = x(t - k dt) -> EP = 1 - k / (0.2 N), EM = ES = 1 (to rounding);
//  y = s x (rectangular pulse) -> EM = 1 - |s - 1| / 0.5, ES = 1 - |s - 1| / 2,
//    Z = mean of ((0.5 - |s-1|)/(0.45))^2 over the pulse and 1 elsewhere;
//  y = x + noise below a0 max|x| -> Z = 1 and e_S = sum|D(noise)| / sum|D(x)| exactly;
//  CORA: identical -> 1; scaling -> EG = s^2 or 1/s^2, EV = EP = 1; shift by m -> EP linear.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "hbm/corridors/cora.hpp"
#include "hbm/corridors/iso18571.hpp"

using namespace hbm::corridors;

namespace {

// skewed smooth pulse (t/tau)^2 exp(-t/tau), not periodic, so correlation has one maximum
double pulse(double t) {
  if (t <= 0.0) return 0.0;
  const double u = t / 0.08;
  return u * u * std::exp(-u);
}

std::vector<double> sampled(std::size_t n, double shift_samples = 0.0, double scale = 1.0) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i)
    v[i] = scale * pulse((static_cast<double>(i) - shift_samples) / static_cast<double>(n - 1));
  return v;
}

std::vector<double> rectangle(std::size_t n, std::size_t a, std::size_t b, double c) {
  std::vector<double> v(n, 0.0);
  for (std::size_t i = a; i < b; ++i) v[i] = c;
  return v;
}

}  // namespace

TEST(Iso18571, IdenticalSignalsRateOneExactly) {
  const auto x = sampled(1000);
  const auto r = iso18571_rating(x, x);
  EXPECT_EQ(r.corridor, 1.0);
  EXPECT_EQ(r.phase, 1.0);
  EXPECT_EQ(r.magnitude, 1.0);
  EXPECT_EQ(r.slope, 1.0);
  EXPECT_EQ(r.overall, 1.0);
  EXPECT_EQ(r.grade, "excellent");
}

TEST(Iso18571, PureShiftGivesPhaseScoreFromFormula) {
  const std::size_t n = 1000;
  const auto x = sampled(n);
  for (long k : {5L, 30L, -40L, 120L}) {
    const auto y = sampled(n, static_cast<double>(k));
    const auto r = iso18571_rating(x, y);
    EXPECT_EQ(r.shift, k);
    const double expected = 1.0 - static_cast<double>(std::abs(k)) / (0.2 * static_cast<double>(n));
    EXPECT_NEAR(r.phase, expected, 1e-12) << "k = " << k;
    EXPECT_NEAR(r.magnitude, 1.0, 1e-9) << "k = " << k;  // the shifted pair coincides
    EXPECT_NEAR(r.slope, 1.0, 1e-9) << "k = " << k;
  }
  // beyond the 20 % limit the phase score is 0
  const auto far = iso18571_rating(x, sampled(n, 250.0));
  EXPECT_EQ(far.phase, 0.0);
}

TEST(Iso18571, PureScalingGivesMagnitudeAndSlopeFromFormula) {
  const std::size_t n = 1000;
  const auto x = rectangle(n, 200, 600, 2.0);
  for (double s : {0.9, 1.1, 1.2, 1.4}) {
    std::vector<double> y(x);
    for (double& v : y) v *= s;
    const auto r = iso18571_rating(x, y);
    EXPECT_EQ(r.shift, 0);
    EXPECT_NEAR(r.magnitude, 1.0 - std::abs(s - 1.0) / 0.5, 1e-12) << "s = " << s;
    EXPECT_NEAR(r.slope, 1.0 - std::abs(s - 1.0) / 2.0, 1e-12) << "s = " << s;
    // corridor: |x - y| = |s-1| c on the 400 pulse samples, inner 0.05 c, outer 0.5 c
    const double d = std::abs(s - 1.0);
    const double c = d <= 0.05 ? 1.0 : (d >= 0.5 ? 0.0 : std::pow((0.5 - d) / 0.45, 2));
    EXPECT_NEAR(r.corridor, (400.0 * c + 600.0) / 1000.0, 1e-12) << "s = " << s;
  }
}

TEST(Iso18571, NoiseKeepsSlopeScoreBoundedAndCorridorAtOne) {
  const std::size_t n = 1000;
  const auto x = sampled(n);
  double xmax = 0.0;
  for (double v : x) xmax = std::max(xmax, std::abs(v));
  std::uint64_t state = 12345;
  std::vector<double> noise(n);
  for (double& v : noise) {  // deterministic uniform noise in [-1, 1]
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    v = static_cast<double>(state >> 11) / static_cast<double>(1ULL << 53) * 2.0 - 1.0;
  }
  double previous = 1.0;
  for (double eps : {0.001, 0.01, 0.04}) {
    std::vector<double> y(n);
    for (std::size_t i = 0; i < n; ++i) y[i] = x[i] + eps * xmax * noise[i];
    const auto r = iso18571_rating(x, y);
    ASSERT_EQ(r.shift, 0) << "eps " << eps;
    // noise below the inner corridor (0.05 max|x|): every sample scores 1
    EXPECT_EQ(r.corridor, 1.0) << "eps " << eps;
    // the smoothed derivative is linear, so e_S is the noise's derivative sum over x's
    const auto dn = iso18571_smoothed_derivative(noise);
    const auto dx = iso18571_smoothed_derivative(x);
    double sn = 0.0, sx = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      sn += std::abs(eps * xmax * dn[i]);
      sx += std::abs(dx[i]);
    }
    EXPECT_NEAR(r.slope, std::clamp(1.0 - sn / sx / 2.0, 0.0, 1.0), 1e-9) << "eps " << eps;
    EXPECT_GE(r.slope, 0.0);
    EXPECT_LE(r.slope, previous);  // more noise, lower slope score
    previous = r.slope;
  }
}

TEST(Iso18571, GradeThresholds) {
  EXPECT_EQ(iso18571_grade(0.95), "excellent");
  EXPECT_EQ(iso18571_grade(0.94), "good");
  EXPECT_EQ(iso18571_grade(0.81), "good");
  EXPECT_EQ(iso18571_grade(0.80), "fair");
  EXPECT_EQ(iso18571_grade(0.59), "fair");
  EXPECT_EQ(iso18571_grade(0.58), "poor");
}

TEST(Iso18571, OverallIsWeightedSum) {
  const auto x = sampled(800);
  const auto y = sampled(800, 12.0, 1.15);
  const auto r = iso18571_rating(x, y);
  EXPECT_NEAR(r.overall, 0.4 * r.corridor + 0.2 * r.phase + 0.2 * r.magnitude + 0.2 * r.slope, 1e-15);
  EXPECT_GT(r.overall, 0.0);
  EXPECT_LT(r.overall, 1.0);
}

TEST(Cora, IdenticalSignalsRateOne) {
  const auto x = sampled(1000);
  const auto r = cora_rating(x, x);
  EXPECT_DOUBLE_EQ(r.overall, 1.0);
  EXPECT_DOUBLE_EQ(r.size, 1.0);
  EXPECT_DOUBLE_EQ(r.progression, 1.0);
  EXPECT_DOUBLE_EQ(r.phase, 1.0);
}

TEST(Cora, ScalingGivesSizeRatingFromFormula) {
  const auto x = sampled(1000);
  for (double s : {0.8, 1.25, 1.5}) {
    const auto y = sampled(1000, 0.0, s);
    const auto r = cora_rating(x, y);
    const double eg = s < 1.0 ? s * s : 1.0 / (s * s);
    EXPECT_NEAR(r.size, eg, 1e-12) << "s = " << s;
    EXPECT_NEAR(r.progression, 1.0, 1e-12) << "s = " << s;
    EXPECT_EQ(r.shift, 0);
    EXPECT_NEAR(r.cross_correlation, 0.5 + 0.25 * eg + 0.25, 1e-12) << "s = " << s;
  }
}

TEST(Cora, ShiftGivesPhaseRatingFromFormula) {
  const std::size_t n = 1000;
  const auto x = sampled(n);
  const auto base = cora_rating(x, x);
  const double len = static_cast<double>(base.end - base.begin);
  for (long m : {3L, 25L, 50L}) {
    const auto r = cora_rating(x, sampled(n, static_cast<double>(m)));
    EXPECT_EQ(r.shift, m);
    const double delta = static_cast<double>(m) / len;
    const double ep = delta <= 0.01 ? 1.0 : (delta >= 0.12 ? 0.0 : (0.12 - delta) / 0.11);
    EXPECT_NEAR(r.phase, ep, 1e-12) << "m = " << m;
    EXPECT_NEAR(r.progression, 1.0, 1e-9) << "m = " << m;
  }
}
