// SPDX-License-Identifier: GPL-3.0-or-later
// SAE J211-1 CFC filter checks. Gain: sinusoids of known frequency are filtered and their
// amplitude measured in the middle of the record; the gain must lie inside the J211 gain
// corridor (as recalled [check], docs/corridors.md): within +0.5/-1 dB up to F_H = CFC,
// +0.5/-4 dB at F_N (100, 300, 1000, 1650 Hz for CFC 60, 180, 600, 1000), and at most
// 0.5 - 9 dB/octave above F_N. It must also equal the exact gain of the forward-backward
// bilinear Butterworth, 1 / (1 + (tan(pi f T) / tan(pi fd T))^4) with fd = 2.0775 CFC, to 0.2 %.
// Phase: a symmetric pulse keeps its peak time (one pass alone would delay it).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hbm/corridors/cfc_filter.hpp"

using namespace hbm::corridors;

namespace {

double measured_gain(double cfc, double fs, double f) {
  const double dt = 1.0 / fs;
  const double duration = std::max(0.5, 40.0 / f);
  const auto n = static_cast<std::size_t>(duration * fs);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = std::sin(2.0 * std::numbers::pi * f * static_cast<double>(i) * dt);
  const auto y = cfc_filter(x, dt, cfc);
  // RMS over the middle half (many periods) -> amplitude ratio
  double sx = 0.0, sy = 0.0;
  for (std::size_t i = n / 4; i < 3 * n / 4; ++i) {
    sx += x[i] * x[i];
    sy += y[i] * y[i];
  }
  return std::sqrt(sy / sx);
}

double exact_gain(double cfc, double fs, double f) {
  const double t = 1.0 / fs;
  const double r = std::tan(std::numbers::pi * f * t) / std::tan(std::numbers::pi * 2.0775 * cfc * t);
  return 1.0 / (1.0 + std::pow(r, 4));
}

double db(double g) { return 20.0 * std::log10(g); }

struct ClassCase {
  double cfc, fn, fs;
};

}  // namespace

TEST(CfcFilter, GainInsideJ211CorridorAndEqualToButterworth) {
  for (const ClassCase c : {ClassCase{60, 100, 10000}, ClassCase{180, 300, 10000}, ClassCase{600, 1000, 20000},
                            ClassCase{1000, 1650, 20000}}) {
    for (double ratio : {0.05, 0.1, 0.25, 0.5, 0.75, 1.0}) {
      const double f = ratio * c.cfc;
      const double g = measured_gain(c.cfc, c.fs, f);
      SCOPED_TRACE("CFC " + std::to_string(c.cfc) + " at " + std::to_string(f) + " Hz: gain " + std::to_string(db(g)) + " dB");
      EXPECT_LE(db(g), 0.5);   // corridor upper limit
      EXPECT_GE(db(g), -1.0);  // corridor lower limit up to F_H
      EXPECT_NEAR(g, exact_gain(c.cfc, c.fs, f), 2e-3 * exact_gain(c.cfc, c.fs, f));
    }
    const double gn = measured_gain(c.cfc, c.fs, c.fn);
    EXPECT_LE(db(gn), 0.5) << "CFC " << c.cfc << " at F_N";
    EXPECT_GE(db(gn), -4.0) << "CFC " << c.cfc << " at F_N";
    const double g2 = measured_gain(c.cfc, c.fs, 2.0 * c.fn);
    EXPECT_LE(db(g2), 0.5 - 9.0) << "CFC " << c.cfc << " one octave above F_N";
  }
}

TEST(CfcFilter, CoefficientsMatchAppendixCFormula) {
  // CFC 60 at 10 kHz: wd = 2 pi 60 2.0775, wa = tan(wd T/2); a0 = wa^2/(1+sqrt2 wa+wa^2)
  const auto c = j211_coefficients(60.0, 1e-4);
  const double wa = std::tan(2.0 * std::numbers::pi * 60.0 * 2.0775 * 1e-4 / 2.0);
  const double den = 1.0 + std::sqrt(2.0) * wa + wa * wa;
  EXPECT_NEAR(c.a0, wa * wa / den, 1e-15);
  EXPECT_NEAR(c.a1, 2.0 * c.a0, 1e-15);
  // unit DC gain of one pass: (a0 + a1 + a2) / (1 - b1 - b2) = 1
  EXPECT_NEAR((c.a0 + c.a1 + c.a2) / (1.0 - c.b1 - c.b2), 1.0, 1e-12);
}

TEST(CfcFilter, ZeroPhaseKeepsPeakOfSymmetricPulse) {
  const double fs = 10000.0, dt = 1.0 / fs;
  const std::size_t n = 2001, ic = 1000;  // peak at sample 1000 (100 ms)
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = (static_cast<double>(i) - static_cast<double>(ic)) * dt;
    x[i] = std::exp(-0.5 * std::pow(t / 2e-3, 2));  // Gaussian, sigma 2 ms
  }
  for (double cfc : {60.0, 180.0, 600.0}) {
    const auto y = cfc_filter(x, dt, cfc);
    std::size_t im = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (y[i] > y[im]) im = i;
    EXPECT_EQ(im, ic) << "CFC " << cfc;
    // symmetric output: y[ic - k] == y[ic + k]
    for (std::size_t k = 1; k < 200; k += 17) EXPECT_NEAR(y[ic - k], y[ic + k], 1e-9) << "CFC " << cfc << " k " << k;
  }
  // one forward pass alone delays the peak: the backward pass is what cancels the phase
  const auto single = j211_single_pass(x, j211_coefficients(60.0, dt));
  std::size_t is = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (single[i] > single[is]) is = i;
  EXPECT_GT(is, ic);
}

TEST(CfcFilter, RejectsTooLowSamplingRate) {
  std::vector<double> x(100, 1.0);
  EXPECT_THROW(cfc_filter(x, 1.0 / 3000.0, 1000.0), std::invalid_argument);  // needs > 4155 Hz
}

TEST(Resample, LinearInterpolationAndGrid) {
  const std::vector<double> t{0.0, 1.0, 3.0}, y{0.0, 2.0, 6.0};
  const auto r = resample_linear(t, y, {0.5, 2.0, 3.0, 4.0});
  EXPECT_DOUBLE_EQ(r[0], 1.0);
  EXPECT_DOUBLE_EQ(r[1], 4.0);
  EXPECT_DOUBLE_EQ(r[2], 6.0);
  EXPECT_DOUBLE_EQ(r[3], 6.0);  // held outside
  const auto g = uniform_grid(0.0, 1.0, 0.1);
  EXPECT_EQ(g.size(), 11u);
  EXPECT_TRUE(is_uniform(g));
  EXPECT_FALSE(is_uniform({0.0, 1.0, 3.0}));
}
