// SPDX-License-Identifier: GPL-3.0-or-later
// CORA rating (see cora.hpp).
#include "hbm/corridors/cora.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "hbm/corridors/iso18571.hpp"

namespace hbm::corridors {

CoraResult cora_rating(const std::vector<double>& x, const std::vector<double>& y,
                       const CoraOptions& o) {
  if (x.size() != y.size()) throw std::invalid_argument("CORA: signals differ in length");
  if (x.size() < 10) throw std::invalid_argument("CORA: fewer than 10 samples");
  const std::size_t n = x.size();
  double xmax = 0.0;
  for (double v : x) xmax = std::max(xmax, std::abs(v));
  CoraResult r;
  r.begin = 0;
  r.end = n;
  if (xmax > 0.0) {
    for (std::size_t i = 0; i < n; ++i)
      if (std::abs(x[i]) >= o.start_threshold * xmax) {
        r.begin = i;
        break;
      }
    for (std::size_t i = n; i-- > r.begin;)
      if (std::abs(x[i]) >= o.end_threshold * xmax) {
        r.end = i + 1;
        break;
      }
  }
  if (r.end < r.begin + 2) r.end = std::min(n, r.begin + 2);
  const std::vector<double> xi(x.begin() + static_cast<long>(r.begin), x.begin() + static_cast<long>(r.end));
  const std::vector<double> yi(y.begin() + static_cast<long>(r.begin), y.begin() + static_cast<long>(r.end));
  r.corridor = iso18571_corridor_score(xi, yi, o.a0, o.b0, o.corridor_exponent);

  const auto len = static_cast<long>(r.end - r.begin);
  const long mmax = static_cast<long>(std::floor(o.max_shift * static_cast<double>(len)));
  auto y_at = [&](long k) { return (k >= 0 && k < static_cast<long>(n)) ? y[static_cast<std::size_t>(k)] : 0.0; };
  double best_k = -std::numeric_limits<double>::infinity();
  double best_yy = 0.0;
  double xx = 0.0;
  for (double v : xi) xx += v * v;
  for (long a = 0; a <= mmax; ++a) {
    for (int sgn : {+1, -1}) {
      if (a == 0 && sgn < 0) continue;
      const long m = sgn * a;
      double xy = 0.0, yy = 0.0;
      for (long i = 0; i < len; ++i) {
        const double yv = y_at(static_cast<long>(r.begin) + i + m);
        xy += xi[static_cast<std::size_t>(i)] * yv;
        yy += yv * yv;
      }
      const double k = (xx > 0.0 && yy > 0.0) ? xy / std::sqrt(xx * yy) : ((xx == 0.0 && yy == 0.0) ? 1.0 : 0.0);
      if (k > best_k + 1e-14) {
        best_k = k;
        r.shift = m;
        best_yy = yy;
      }
    }
  }
  const double delta = static_cast<double>(std::abs(r.shift)) / static_cast<double>(len);
  if (delta <= o.free_shift)
    r.phase = 1.0;
  else if (delta >= o.max_shift)
    r.phase = 0.0;
  else
    r.phase = (o.max_shift - delta) / (o.max_shift - o.free_shift);
  const double lo = std::min(xx, best_yy), hi = std::max(xx, best_yy);
  r.size = hi > 0.0 ? lo / hi : 1.0;
  r.progression = std::pow(std::clamp((best_k + 1.0) / 2.0, 0.0, 1.0), o.progression_exponent);
  r.cross_correlation = 0.5 * r.progression + 0.25 * r.size + 0.25 * r.phase;
  r.overall = 0.5 * r.corridor + 0.5 * r.cross_correlation;
  return r;
}

}  // namespace hbm::corridors
