// SPDX-License-Identifier: GPL-3.0-or-later
// ISO/TS 18571 rating (see iso18571.hpp for the formulas).
#include "hbm/corridors/iso18571.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace hbm::corridors {
namespace {

double pearson(const double* a, const double* b, std::size_t n) {
  double ma = 0.0, mb = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    ma += a[i];
    mb += b[i];
  }
  ma /= static_cast<double>(n);
  mb /= static_cast<double>(n);
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double da = a[i] - ma, db = b[i] - mb;
    sab += da * db;
    saa += da * da;
    sbb += db * db;
  }
  if (saa <= 0.0 || sbb <= 0.0) return (saa <= 0.0 && sbb <= 0.0) ? 1.0 : 0.0;
  return sab / std::sqrt(saa * sbb);
}

double clip01(double v) { return std::clamp(v, 0.0, 1.0); }

}  // namespace

double iso18571_corridor_score(const std::vector<double>& x, const std::vector<double>& y,
                               double a0, double b0, double exponent) {
  double xnorm = 0.0;
  for (double v : x) xnorm = std::max(xnorm, std::abs(v));
  const double inner = a0 * xnorm, outer = b0 * xnorm;
  double sum = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double d = std::abs(x[i] - y[i]);
    double c;
    if (d <= inner)
      c = 1.0;
    else if (d >= outer)
      c = 0.0;
    else
      c = std::pow((outer - d) / (outer - inner), exponent);
    sum += c;
  }
  return x.empty() ? 0.0 : sum / static_cast<double>(x.size());
}

long iso18571_best_shift(const std::vector<double>& x, const std::vector<double>& y,
                         double max_fraction) {
  const auto n = static_cast<long>(x.size());
  const long nmax = static_cast<long>(std::floor(max_fraction * static_cast<double>(n)));
  long best = 0;
  double best_rho = -std::numeric_limits<double>::infinity();
  for (long k = 0; k <= nmax && k < n - 1; ++k) {
    for (int sgn : {+1, -1}) {
      if (k == 0 && sgn < 0) continue;
      const long s = sgn * k;
      const std::size_t len = static_cast<std::size_t>(n - k);
      const double* xa = x.data() + (s < 0 ? k : 0);
      const double* ya = y.data() + (s > 0 ? k : 0);
      const double rho = pearson(xa, ya, len);
      if (rho > best_rho + 1e-14) {  // strictly better: ties keep the smaller |shift|
        best_rho = rho;
        best = s;
      }
    }
  }
  return best;
}

void iso18571_shifted_pair(const std::vector<double>& x, const std::vector<double>& y, long n,
                           std::vector<double>& xs, std::vector<double>& ys) {
  const long len = static_cast<long>(x.size()) - std::abs(n);
  xs.assign(x.begin() + (n < 0 ? -n : 0), x.begin() + (n < 0 ? -n : 0) + len);
  ys.assign(y.begin() + (n > 0 ? n : 0), y.begin() + (n > 0 ? n : 0) + len);
}

double iso18571_magnitude_error(const std::vector<double>& x, const std::vector<double>& y,
                                double band_fraction) {
  const long m = static_cast<long>(x.size());
  if (m == 0) return 0.0;
  const long r = std::max<long>(1, static_cast<long>(std::ceil(band_fraction * static_cast<double>(m))));
  const long w = 2 * r + 1;  // band width: column j in [i - r, i + r]
  const double inf = std::numeric_limits<double>::infinity();
  // direction of the best predecessor: 0 diagonal, 1 from (i-1, j), 2 from (i, j-1)
  std::vector<std::uint8_t> dir(static_cast<std::size_t>(m * w), 0);
  std::vector<double> prev(static_cast<std::size_t>(w), inf), cur(static_cast<std::size_t>(w), inf);
  auto at = [&](std::vector<double>& row, long i, long j) -> double& {
    return row[static_cast<std::size_t>(j - i + r)];
  };
  for (long i = 0; i < m; ++i) {
    std::fill(cur.begin(), cur.end(), inf);
    for (long j = std::max<long>(0, i - r); j <= std::min<long>(m - 1, i + r); ++j) {
      const double d = x[static_cast<std::size_t>(i)] - y[static_cast<std::size_t>(j)];
      const double cost = d * d;
      if (i == 0 && j == 0) {
        at(cur, i, j) = cost;
        continue;
      }
      double best = inf;
      std::uint8_t bd = 0;
      if (i > 0 && j > 0 && std::abs((j - 1) - (i - 1)) <= r) {
        best = at(prev, i - 1, j - 1);
        bd = 0;
      }
      if (i > 0 && std::abs(j - (i - 1)) <= r && at(prev, i - 1, j) < best) {
        best = at(prev, i - 1, j);
        bd = 1;
      }
      if (j > 0 && std::abs((j - 1) - i) <= r && at(cur, i, j - 1) < best) {
        best = at(cur, i, j - 1);
        bd = 2;
      }
      at(cur, i, j) = best + cost;
      dir[static_cast<std::size_t>(i * w + (j - i + r))] = bd;
    }
    std::swap(prev, cur);
  }
  // backtrack from (m-1, m-1)
  double num = 0.0, den = 0.0;
  long i = m - 1, j = m - 1;
  while (true) {
    num += std::abs(y[static_cast<std::size_t>(j)] - x[static_cast<std::size_t>(i)]);
    den += std::abs(x[static_cast<std::size_t>(i)]);
    if (i == 0 && j == 0) break;
    const std::uint8_t d = dir[static_cast<std::size_t>(i * w + (j - i + r))];
    if (i == 0)
      --j;
    else if (j == 0)
      --i;
    else if (d == 0) {
      --i;
      --j;
    } else if (d == 1)
      --i;
    else
      --j;
  }
  if (den <= 0.0) return num > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  return num / den;
}

std::vector<double> iso18571_smoothed_derivative(const std::vector<double>& x, double dt) {
  const std::size_t n = x.size();
  std::vector<double> d(n, 0.0), s(n, 0.0);
  if (n < 2) return s;
  d[0] = (x[1] - x[0]) / dt;
  d[n - 1] = (x[n - 1] - x[n - 2]) / dt;
  for (std::size_t i = 1; i + 1 < n; ++i) d[i] = (x[i + 1] - x[i - 1]) / (2.0 * dt);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t half = std::min<std::size_t>({4, i, n - 1 - i});
    double sum = 0.0;
    for (std::size_t k = i - half; k <= i + half; ++k) sum += d[k];
    s[i] = sum / static_cast<double>(2 * half + 1);
  }
  return s;
}

double iso18571_slope_error(const std::vector<double>& x, const std::vector<double>& y) {
  const auto dx = iso18571_smoothed_derivative(x);
  const auto dy = iso18571_smoothed_derivative(y);
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < dx.size(); ++i) {
    num += std::abs(dy[i] - dx[i]);
    den += std::abs(dx[i]);
  }
  if (den <= 0.0) return num > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  return num / den;
}

std::string iso18571_grade(double r) {
  if (r > 0.94) return "excellent";
  if (r > 0.80) return "good";
  if (r > 0.58) return "fair";
  return "poor";
}

Iso18571Result iso18571_rating(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size())
    throw std::invalid_argument("ISO 18571: reference and comparison differ in length");
  if (x.size() < 10) throw std::invalid_argument("ISO 18571: fewer than 10 samples");
  Iso18571Result r;
  r.corridor = iso18571_corridor_score(x, y);
  r.shift = iso18571_best_shift(x, y);
  const double limit = 0.2 * static_cast<double>(x.size());
  r.phase = clip01(1.0 - static_cast<double>(std::abs(r.shift)) / limit);
  std::vector<double> xs, ys;
  iso18571_shifted_pair(x, y, r.shift, xs, ys);
  r.magnitude_error = iso18571_magnitude_error(xs, ys);
  r.magnitude = clip01(1.0 - r.magnitude_error / 0.5);
  r.slope_error = iso18571_slope_error(xs, ys);
  r.slope = clip01(1.0 - r.slope_error / 2.0);
  r.overall = 0.4 * r.corridor + 0.2 * r.phase + 0.2 * r.magnitude + 0.2 * r.slope;
  r.grade = iso18571_grade(r.overall);
  return r;
}

}  // namespace hbm::corridors
