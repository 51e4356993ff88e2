// SPDX-License-Identifier: GPL-3.0-or-later
// /FUNCT: a piecewise linear function y(x) given by points with increasing abscissae.
// Outside [x_first, x_last] the first / last segment is extended linearly, as Radioss
// does (a single point is a constant). Deck authors who want a constant beyond the range
// repeat the last ordinate with a larger abscissa. Evaluation is a binary search; for
// time functions evaluated each cycle `eval_from` continues from the last segment.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace hbm::solver {

class FunctionCurve {
 public:
  FunctionCurve() = default;
  FunctionCurve(std::int64_t id, std::string title, std::vector<double> x, std::vector<double> y);

  std::int64_t id() const { return id_; }
  const std::string& title() const { return title_; }
  std::size_t n_points() const { return x_.size(); }
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }

  double operator()(double x) const;                     // value, extrapolated linearly
  double slope(double x) const;                          // dy/dx of the segment at x
  // Same as operator() with a hint: `segment` is the segment used last time (updated).
  double eval_from(double x, std::size_t& segment) const;
  // Exact integral of y from a to b (with the same linear extension outside the range).
  double integral(double a, double b) const { return antiderivative(b) - antiderivative(a); }
  double antiderivative(double x) const;  // integral from x_first to x

 private:
  std::size_t segment_of(double x) const;  // i such that x in [x_i, x_{i+1}], clamped
  std::int64_t id_ = 0;
  std::string title_;
  std::vector<double> x_, y_;
  std::vector<double> area_;  // integral from x_0 to x_i
};

}  // namespace hbm::solver
