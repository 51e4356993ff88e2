// SPDX-License-Identifier: GPL-3.0-or-later
// /FUNCT evaluation: piecewise linear, end segments extended linearly (Radioss rule).
#include "hbm/solver/function_curve.hpp"

#include <algorithm>
#include <utility>

namespace hbm::solver {

FunctionCurve::FunctionCurve(std::int64_t id, std::string title, std::vector<double> x,
                             std::vector<double> y)
    : id_(id), title_(std::move(title)), x_(std::move(x)), y_(std::move(y)) {
  area_.assign(x_.size(), 0.0);
  for (std::size_t i = 1; i < x_.size(); ++i)
    area_[i] = area_[i - 1] + 0.5 * (y_[i - 1] + y_[i]) * (x_[i] - x_[i - 1]);
}

double FunctionCurve::antiderivative(double x) const {
  if (x_.empty()) return 0.0;
  if (x_.size() == 1) return y_[0] * (x - x_[0]);
  const std::size_t i = segment_of(x);
  const double dx = x_[i + 1] - x_[i];
  const double slope = dx > 0 ? (y_[i + 1] - y_[i]) / dx : 0.0;
  const double u = x - x_[i];
  return area_[i] + y_[i] * u + 0.5 * slope * u * u;
}

std::size_t FunctionCurve::segment_of(double x) const {
  if (x_.size() < 2) return 0;
  // First point with abscissa > x; the segment starts one before, clamped to the ends.
  const auto it = std::upper_bound(x_.begin(), x_.end(), x);
  std::size_t i = static_cast<std::size_t>(it - x_.begin());
  i = (i == 0) ? 0 : i - 1;
  return std::min(i, x_.size() - 2);
}

static double interpolate(const std::vector<double>& xs, const std::vector<double>& ys,
                          std::size_t i, double x) {
  const double dx = xs[i + 1] - xs[i];
  if (dx <= 0) return ys[i + 1];  // vertical step: take the later value
  return ys[i] + (ys[i + 1] - ys[i]) * (x - xs[i]) / dx;
}

double FunctionCurve::operator()(double x) const {
  if (x_.empty()) return 0.0;
  if (x_.size() == 1) return y_[0];
  return interpolate(x_, y_, segment_of(x), x);
}

double FunctionCurve::slope(double x) const {
  if (x_.size() < 2) return 0.0;
  const std::size_t i = segment_of(x);
  const double dx = x_[i + 1] - x_[i];
  return dx > 0 ? (y_[i + 1] - y_[i]) / dx : 0.0;
}

double FunctionCurve::eval_from(double x, std::size_t& segment) const {
  if (x_.size() < 2) return (*this)(x);
  std::size_t i = std::min(segment, x_.size() - 2);
  while (i + 2 < x_.size() && x >= x_[i + 1]) ++i;
  while (i > 0 && x < x_[i]) --i;
  segment = i;
  return interpolate(x_, y_, i, x);
}

}  // namespace hbm::solver
