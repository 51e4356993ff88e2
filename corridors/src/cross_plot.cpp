// SPDX-License-Identifier: GPL-3.0-or-later
// Parameterisations of force-deflection curves for rating (see cross_plot.hpp).
#include "hbm/corridors/cross_plot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "hbm/corridors/cfc_filter.hpp"

namespace hbm::corridors {

ParameterisedCurves parameterise_loading(const Polyline& reference, const Polyline& model,
                                         std::size_t n) {
  const Polyline ref = loading_branch(reference);
  const Polyline mdl = loading_branch(model);
  if (ref.x.size() < 2) throw std::invalid_argument("reference loading branch has < 2 points");
  if (mdl.x.size() < 2) throw std::invalid_argument("model loading branch has < 2 points (no deflection?)");
  ParameterisedCurves out;
  out.reference_reach = ref.x.back();
  out.model_reach = mdl.x.back();
  const double s0 = std::max(ref.x.front(), mdl.x.front());
  const double s1 = ref.x.back();
  if (!(s1 > s0)) throw std::invalid_argument("model loading branch starts beyond the reference's largest deflection");
  out.abscissa.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    out.abscissa[i] = s0 + (s1 - s0) * static_cast<double>(i) / static_cast<double>(n - 1);
  out.reference = resample_linear(ref.x, ref.y, out.abscissa);
  out.model = resample_linear(mdl.x, mdl.y, out.abscissa);
  for (std::size_t i = 0; i < n; ++i)
    if (out.abscissa[i] > mdl.x.back()) out.model[i] = 0.0;  // never reached by the model
  return out;
}

namespace {

std::vector<double> arc_fraction(const Polyline& p, double xs, double ys) {
  std::vector<double> s(p.x.size(), 0.0);
  for (std::size_t i = 1; i < p.x.size(); ++i)
    s[i] = s[i - 1] + std::hypot((p.x[i] - p.x[i - 1]) / xs, (p.y[i] - p.y[i - 1]) / ys);
  if (s.back() > 0.0)
    for (double& v : s) v /= s.back();
  return s;
}

}  // namespace

ParameterisedCurves parameterise_arc_length(const Polyline& reference, const Polyline& model,
                                            std::size_t n) {
  if (reference.x.size() < 2 || model.x.size() < 2)
    throw std::invalid_argument("arc-length parameterisation needs 2 points per curve");
  double xs = 0.0, ys = 0.0;
  for (std::size_t i = 0; i < reference.x.size(); ++i) {
    xs = std::max(xs, std::abs(reference.x[i]));
    ys = std::max(ys, std::abs(reference.y[i]));
  }
  if (!(xs > 0.0) || !(ys > 0.0)) throw std::invalid_argument("reference curve is all zero");
  ParameterisedCurves out;
  out.reference_reach = *std::max_element(reference.x.begin(), reference.x.end());
  out.model_reach = *std::max_element(model.x.begin(), model.x.end());
  out.abscissa.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.abscissa[i] = static_cast<double>(i) / static_cast<double>(n - 1);
  auto sample = [&](const Polyline& p) {
    const auto s = arc_fraction(p, xs, ys);
    // arc fraction is non-decreasing; drop repeated values so interpolation is defined
    std::vector<double> ss, yy;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (ss.empty() || s[i] > ss.back()) {
        ss.push_back(s[i]);
        yy.push_back(p.y[i]);
      }
    return resample_linear(ss, yy, out.abscissa);
  };
  out.reference = sample(reference);
  out.model = sample(model);
  return out;
}

}  // namespace hbm::corridors
