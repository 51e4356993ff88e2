// SPDX-License-Identifier: GPL-3.0-or-later
// SAE J211-1 Appendix C filter and linear resampling (see cfc_filter.hpp).
#include "hbm/corridors/cfc_filter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace hbm::corridors {

J211Coefficients j211_coefficients(double cfc, double dt_s) {
  const double wd = 2.0 * std::numbers::pi * cfc * 2.0775;
  const double wa = std::sin(wd * dt_s / 2.0) / std::cos(wd * dt_s / 2.0);
  const double den = 1.0 + std::numbers::sqrt2 * wa + wa * wa;
  J211Coefficients c{};
  c.a0 = wa * wa / den;
  c.a1 = 2.0 * c.a0;
  c.a2 = c.a0;
  c.b1 = -2.0 * (wa * wa - 1.0) / den;
  c.b2 = (-1.0 + std::numbers::sqrt2 * wa - wa * wa) / den;
  return c;
}

std::vector<double> j211_single_pass(const std::vector<double>& x, const J211Coefficients& c) {
  std::vector<double> y(x.size());
  if (x.empty()) return y;
  // start from the steady state of a constant input equal to x[0] (DC gain is 1)
  double x1 = x[0], x2 = x[0], y1 = x[0], y2 = x[0];
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double yi = c.a0 * x[i] + c.a1 * x1 + c.a2 * x2 + c.b1 * y1 + c.b2 * y2;
    x2 = x1;
    x1 = x[i];
    y2 = y1;
    y1 = yi;
    y[i] = yi;
  }
  return y;
}

std::vector<double> cfc_filter(const std::vector<double>& x, double dt_s, double cfc) {
  if (!(cfc > 0.0)) throw std::invalid_argument("CFC must be positive");
  if (!(dt_s > 0.0)) throw std::invalid_argument("sample interval must be positive");
  const double fs = 1.0 / dt_s;
  if (fs <= 2.0 * 2.0775 * cfc)
    throw std::invalid_argument("sampling rate " + std::to_string(fs) + " Hz is too low for CFC " +
                                std::to_string(cfc) + " (needs more than " +
                                std::to_string(2.0 * 2.0775 * cfc) + " Hz)");
  const std::size_t n = x.size();
  if (n < 3) return x;
  const auto c = j211_coefficients(cfc, dt_s);
  const std::size_t pad =
      std::min<std::size_t>(n - 1, static_cast<std::size_t>(std::ceil(2.0 * fs / cfc)));
  std::vector<double> ext;
  ext.reserve(n + 2 * pad);
  for (std::size_t k = pad; k >= 1; --k) ext.push_back(2.0 * x[0] - x[k]);
  ext.insert(ext.end(), x.begin(), x.end());
  for (std::size_t k = 1; k <= pad; ++k) ext.push_back(2.0 * x[n - 1] - x[n - 1 - k]);
  auto fwd = j211_single_pass(ext, c);
  std::reverse(fwd.begin(), fwd.end());
  auto bwd = j211_single_pass(fwd, c);
  std::reverse(bwd.begin(), bwd.end());
  return std::vector<double>(bwd.begin() + static_cast<long>(pad),
                             bwd.begin() + static_cast<long>(pad + n));
}

std::vector<double> resample_linear(const std::vector<double>& t, const std::vector<double>& y,
                                    const std::vector<double>& t_new) {
  std::vector<double> out(t_new.size());
  if (t.empty()) return out;
  std::size_t j = 0;
  for (std::size_t i = 0; i < t_new.size(); ++i) {
    const double tq = t_new[i];
    if (tq <= t.front()) {
      out[i] = y.front();
      continue;
    }
    if (tq >= t.back()) {
      out[i] = y.back();
      continue;
    }
    if (j > 0 && t[j] > tq) j = 0;  // queries not sorted: restart the scan
    while (j + 1 < t.size() && t[j + 1] < tq) ++j;
    const double t0 = t[j], t1 = t[j + 1];
    const double w = t1 > t0 ? (tq - t0) / (t1 - t0) : 1.0;
    out[i] = y[j] + w * (y[j + 1] - y[j]);
  }
  return out;
}

std::vector<double> uniform_grid(double t0, double t1, double dt) {
  std::vector<double> g;
  if (!(dt > 0.0) || t1 < t0) return g;
  const auto n = static_cast<std::size_t>(std::floor((t1 - t0) / dt * (1.0 + 1e-12) + 1e-9)) + 1;
  g.reserve(n);
  for (std::size_t i = 0; i < n; ++i) g.push_back(t0 + static_cast<double>(i) * dt);
  return g;
}

bool is_uniform(const std::vector<double>& t) {
  if (t.size() < 3) return true;
  const double dt = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  if (!(dt > 0.0)) return false;
  for (std::size_t i = 1; i < t.size(); ++i)
    if (std::abs((t[i] - t[i - 1]) - dt) > 1e-6 * dt + 1e-12 * std::abs(t[i])) return false;
  return true;
}

}  // namespace hbm::corridors
