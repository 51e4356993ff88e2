// SPDX-License-Identifier: GPL-3.0-or-later
// Injury criteria (see injury_criteria.hpp).
#include "hbm/corridors/injury_criteria.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <stdexcept>

namespace hbm::corridors {

WindowValue head_injury_criterion(const std::vector<double>& t_ms, const std::vector<double>& a_g,
                                  double window_ms) {
  const std::size_t n = t_ms.size();
  WindowValue best;
  if (n < 2) return best;
  // trapezoidal running integral of a over time in seconds
  std::vector<double> integral(n, 0.0);
  for (std::size_t i = 1; i < n; ++i)
    integral[i] = integral[i - 1] + 0.5 * (a_g[i] + a_g[i - 1]) * (t_ms[i] - t_ms[i - 1]) * 1e-3;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    for (std::size_t j = i + 1; j < n && t_ms[j] - t_ms[i] <= window_ms * (1.0 + 1e-12); ++j) {
      const double dt = (t_ms[j] - t_ms[i]) * 1e-3;
      const double mean = (integral[j] - integral[i]) / dt;
      if (mean <= 0.0) continue;
      const double hic = dt * std::pow(mean, 2.5);
      if (hic > best.value) best = {hic, t_ms[i], t_ms[j]};
    }
  }
  return best;
}

double a3ms_cumulative(const std::vector<double>& t_ms, const std::vector<double>& a, double duration_ms) {
  if (t_ms.size() < 2) return 0.0;
  const double dt = (t_ms.back() - t_ms.front()) / static_cast<double>(t_ms.size() - 1);
  std::vector<double> m(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) m[i] = std::abs(a[i]);
  std::sort(m.begin(), m.end(), std::greater<>());
  // each sample stands for dt of exceedance: need k samples with k dt >= duration
  const auto k = static_cast<std::size_t>(std::ceil(duration_ms / dt - 1e-9));
  if (k == 0) return m.front();
  if (k > m.size()) return 0.0;
  return m[k - 1];
}

WindowValue a3ms_continuous(const std::vector<double>& t_ms, const std::vector<double>& a, double duration_ms) {
  WindowValue best;
  const std::size_t n = t_ms.size();
  std::deque<std::size_t> q;  // indices of a sliding-window minimum of |a|
  std::size_t i = 0;
  for (std::size_t j = 0; j < n; ++j) {
    while (!q.empty() && std::abs(a[q.back()]) >= std::abs(a[j])) q.pop_back();
    q.push_back(j);
    while (t_ms[j] - t_ms[i] > duration_ms * (1.0 + 1e-12)) {
      ++i;
      if (q.front() < i) q.pop_front();
    }
    if (t_ms[j] - t_ms[i] >= duration_ms * (1.0 - 1e-9)) {
      const double v = std::abs(a[q.front()]);
      if (v > best.value) best = {v, t_ms[i], t_ms[j]};
    }
  }
  return best;
}

WindowValue signed_peak(const std::vector<double>& t_ms, const std::vector<double>& y) {
  WindowValue p;
  double m = -1.0;
  for (std::size_t i = 0; i < y.size(); ++i)
    if (std::abs(y[i]) > m) {
      m = std::abs(y[i]);
      p.value = y[i];
      p.t1 = p.t2 = t_ms[i];
    }
  return p;
}

std::vector<double> viscous_criterion(const std::vector<double>& t_ms, const std::vector<double>& d,
                                      double scale_factor, double d0_mm) {
  const std::size_t n = d.size();
  std::vector<double> vc(n, 0.0);
  if (n < 5) return vc;
  const double h = (t_ms.back() - t_ms.front()) / static_cast<double>(n - 1);
  for (std::size_t i = 2; i + 2 < n; ++i) {
    const double v = (8.0 * (d[i + 1] - d[i - 1]) - (d[i + 2] - d[i - 2])) / (12.0 * h);
    vc[i] = scale_factor * v * d[i] / d0_mm;
  }
  return vc;
}

NijResult neck_injury_criterion(const std::vector<double>& t_ms, const std::vector<double>& fz,
                                const std::vector<double>& my, const std::vector<double>& fx,
                                double e_m, const NijIntercepts& c) {
  NijResult r;
  for (std::size_t i = 0; i < t_ms.size(); ++i) {
    const double m = my[i] - (fx.empty() ? 0.0 : e_m * fx[i]);
    const bool tension = fz[i] >= 0.0, flexion = m >= 0.0;
    const double nz = tension ? fz[i] / c.tension_N : -fz[i] / c.compression_N;
    const double nm = flexion ? m / c.flexion_Nm : -m / c.extension_Nm;
    const double v = nz + nm;
    double& slot = tension ? (flexion ? r.ntf : r.nte) : (flexion ? r.ncf : r.nce);
    slot = std::max(slot, v);
    if (v > r.value) {
      r.value = v;
      r.t_ms = t_ms[i];
      r.mode = tension ? (flexion ? "NTF" : "NTE") : (flexion ? "NCF" : "NCE");
    }
  }
  return r;
}

}  // namespace hbm::corridors
