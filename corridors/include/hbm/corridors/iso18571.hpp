// SPDX-License-Identifier: GPL-3.0-or-later
// ISO/TS 18571 objective rating of a comparison signal y (model) against a reference x
// (test), both sampled on the same uniform grid over the same interval (N samples).
//   Z  corridor score: inner half-width a0 max|x|, outer b0 max|x| (a0 = 0.05, b0 = 0.5);
//      per sample 1 inside the inner, 0 outside the outer, else ((outer-|x-y|)/(outer-inner))^2
//   EP phase score: y shifted by n samples (|n| <= 0.2 N, ends truncated), n* maximises the
//      Pearson correlation (ties: smallest |n|); EP = 1 - |n*|/(0.2 N), 0 at the limit
//   EM magnitude score: dynamic time warping of the shifted pair (squared local cost,
//      Sakoe-Chiba band ceil(0.1 M)); e_M = sum|y_w - x_w| / sum|x_w|; EM = 1 - e_M/0.5
//   ES slope score: central-difference derivatives of the shifted pair, 9-point moving
//      average (1, 3, 5, 7 points at the ends); e_S = sum|y'-x'|/sum|x'|; ES = 1 - e_S/2
//   R = 0.4 Z + 0.2 EP + 0.2 EM + 0.2 ES; grade: > 0.94 excellent, > 0.80 good,
//      > 0.58 fair, else poor.
// Source: ISO/TS 18571:2014 as summarised in shared/notes/ratings-and-criteria.md.
#pragma once

#include <string>
#include <vector>

namespace hbm::corridors {

struct Iso18571Result {
  double corridor = 0.0;   ///< Z
  double phase = 0.0;      ///< EP
  double magnitude = 0.0;  ///< EM
  double slope = 0.0;      ///< ES
  double overall = 0.0;    ///< R
  long shift = 0;          ///< n*: samples by which y lags x (negative: y leads)
  double magnitude_error = 0.0;  ///< e_M
  double slope_error = 0.0;      ///< e_S
  std::string grade;
};

/// Corridor score Z of y against x (same length).
double iso18571_corridor_score(const std::vector<double>& x, const std::vector<double>& y,
                               double a0 = 0.05, double b0 = 0.5, double exponent = 2.0);

/// Shift n* (samples, y lagging x when positive) maximising the Pearson correlation over
/// |n| <= floor(max_fraction N); ties keep the smallest |n|.
long iso18571_best_shift(const std::vector<double>& x, const std::vector<double>& y,
                         double max_fraction = 0.2);

/// Truncated pair after applying shift n: xs[i] = x[i], ys[i] = y[i+n] for n >= 0;
/// xs[i] = x[i-n], ys[i] = y[i] for n < 0.
void iso18571_shifted_pair(const std::vector<double>& x, const std::vector<double>& y, long n,
                           std::vector<double>& xs, std::vector<double>& ys);

/// e_M of the pair by dynamic time warping (squared cost, band radius ceil(band_fraction M)).
double iso18571_magnitude_error(const std::vector<double>& x, const std::vector<double>& y,
                                double band_fraction = 0.1);

/// Smoothed central-difference derivative (9-point moving average, shorter at the ends).
std::vector<double> iso18571_smoothed_derivative(const std::vector<double>& x, double dt = 1.0);

/// e_S of the pair.
double iso18571_slope_error(const std::vector<double>& x, const std::vector<double>& y);

/// Full rating; x and y must have the same length >= 10 (throws std::invalid_argument).
Iso18571Result iso18571_rating(const std::vector<double>& x, const std::vector<double>& y);

/// Grade name for an overall rating R.
std::string iso18571_grade(double r);

}  // namespace hbm::corridors
