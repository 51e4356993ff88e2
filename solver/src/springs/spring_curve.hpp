// SPDX-License-Identifier: GPL-3.0-or-later
// Piecewise-linear curve as the spring laws read it (/FUNCT points): value and slope at x,
// with linear extrapolation by the first / last segment outside the abscissa range, as
// Radioss spring curves do (vinter2). A curve with one point is a constant. The points
// live in storage owned by the model; the view is two pointers and a count, cheap to copy
// into a kernel.
#pragma once

#include <cstddef>

namespace hbm::solver::springs {

struct CurveView {
  const double* x = nullptr;  // abscissae, strictly increasing
  const double* y = nullptr;  // ordinates
  std::size_t n = 0;          // number of points; 0 = no curve

  bool empty() const { return n == 0; }

  // Segment index k such that x[k] <= xv < x[k+1], clamped to [0, n-2].
  std::size_t segment(double xv) const {
    std::size_t lo = 0, hi = n - 1;  // invariant: answer in [lo, hi-1]
    if (xv <= x[0]) return 0;
    if (xv >= x[n - 1]) return n - 2;
    while (hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      if (x[mid] <= xv) lo = mid; else hi = mid;
    }
    return lo;
  }
  // y(xv), linear inside, linear extrapolation outside.
  double operator()(double xv) const {
    if (n == 1) return y[0];
    const std::size_t k = segment(xv);
    const double t = (xv - x[k]) / (x[k + 1] - x[k]);
    return y[k] + t * (y[k + 1] - y[k]);
  }
  // dy/dx at xv (slope of the segment used by operator()).
  double slope(double xv) const {
    if (n == 1) return 0.0;
    const std::size_t k = segment(xv);
    return (y[k + 1] - y[k]) / (x[k + 1] - x[k]);
  }
  // Largest |slope| over the curve: the stiffness bound for the stable time step.
  double max_abs_slope() const {
    double s = 0;
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double sk = (y[k + 1] - y[k]) / (x[k + 1] - x[k]);
      s = sk > s ? sk : (-sk > s ? -sk : s);
    }
    return s;
  }
};

}  // namespace hbm::solver::springs
