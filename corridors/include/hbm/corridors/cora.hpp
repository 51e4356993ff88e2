// SPDX-License-Identifier: GPL-3.0-or-later
// CORA (CORrelation and Analysis), Gehre, Gades, Wernicke, ESV 2009 paper 09-0407, as
// summarised in shared/notes/ratings-and-criteria.md. Defaults below are marked [check]
// there: they were recalled from the literature, not read in the CORA manual.
//   interval: from where |x| first reaches 3 % of max|x| to where it last is >= 7.5 %
//   corridor rating Z: as ISO/TS 18571 (a0 = 0.05, b0 = 0.5, exponent 2) on the interval
//   cross-correlation: K(m) = sum x_i y_(i+m) / sqrt(sum x_i^2 sum y_(i+m)^2) over the
//     interval, |m| <= 12 % of the interval; m* maximises K
//   EP = 1 if |m*| <= 1 % of the interval, 0 if >= 12 %, linear between
//   EG = min(sum x^2, sum y^2) / max(...)  (y shifted by m*)
//   EV = ((K(m*) + 1) / 2)^10
//   E = 0.5 EV + 0.25 EG + 0.25 EP;  total = 0.5 Z + 0.5 E
#pragma once

#include <vector>

namespace hbm::corridors {

struct CoraOptions {
  double start_threshold = 0.03;  ///< interval starts where |x| >= this * max|x|
  double end_threshold = 0.075;   ///< interval ends where |x| is last >= this * max|x|
  double a0 = 0.05, b0 = 0.5, corridor_exponent = 2.0;
  double max_shift = 0.12;   ///< fraction of the interval
  double free_shift = 0.01;  ///< shifts below this fraction score EP = 1
  double progression_exponent = 10.0;
};

struct CoraResult {
  double corridor = 0.0;     ///< Z
  double phase = 0.0;        ///< EP
  double size = 0.0;         ///< EG
  double progression = 0.0;  ///< EV
  double cross_correlation = 0.0;  ///< E
  double overall = 0.0;
  long shift = 0;  ///< m* in samples (y lags x when positive)
  std::size_t begin = 0, end = 0;  ///< evaluation interval [begin, end) in samples
};

/// CORA rating of y against x (same uniform grid, same length >= 10).
CoraResult cora_rating(const std::vector<double>& x, const std::vector<double>& y,
                       const CoraOptions& options = {});

}  // namespace hbm::corridors
