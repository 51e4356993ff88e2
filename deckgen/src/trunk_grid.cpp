// SPDX-License-Identifier: GPL-3.0-or-later
// Trunk O-grid construction (see trunk_grid.hpp).
#include "hbm/deckgen/trunk_grid.hpp"

#include <cmath>
#include <stdexcept>

namespace hbm::deckgen {

namespace {

double sgnpow(double v, double e) { return std::copysign(std::pow(std::abs(v), e), v); }

Eigen::Vector3d tri_cross(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return (b - a).cross(c - a);
}

}  // namespace

Eigen::Vector2d superellipse_half_point(double x_c, double hd, double hw, double n, double s, double widest_forward) {
  // Polyline of the left half, parameter t in [0, pi]; arc length by summation. The widest
  // point sits widest_forward ahead of the centre: the front quarter spans hd - w, the back
  // quarter hd + w (two superellipse quarters joined at the widest point, same tangent).
  const double w = widest_forward;
  constexpr int kSamples = 360;
  static thread_local std::vector<Eigen::Vector2d> pts;
  static thread_local std::vector<double> len;
  pts.resize(kSamples + 1);
  len.resize(kSamples + 1);
  for (int i = 0; i <= kSamples; ++i) {
    double t = M_PI * i / kSamples;
    double c = std::cos(t);
    pts[static_cast<std::size_t>(i)] = {x_c + w + (c >= 0 ? hd - w : hd + w) * sgnpow(c, 2.0 / n), hw * sgnpow(std::sin(t), 2.0 / n)};
    len[static_cast<std::size_t>(i)] = i == 0 ? 0.0 : len[static_cast<std::size_t>(i - 1)] + (pts[static_cast<std::size_t>(i)] - pts[static_cast<std::size_t>(i - 1)]).norm();
  }
  double target = s * len.back();
  for (int i = 1; i <= kSamples; ++i) {
    auto k = static_cast<std::size_t>(i);
    if (len[k] >= target) {
      double f = (target - len[k - 1]) / std::max(1e-12, len[k] - len[k - 1]);
      return pts[k - 1] + f * (pts[k] - pts[k - 1]);
    }
  }
  return pts.back();
}

TrunkGrid::TrunkGrid(FeModel& model, const SectionTable& sections, std::vector<GridLevel> levels, GridParams p)
    : model_(model), sections_(sections), levels_(std::move(levels)), p_(p) {
  if (p_.n % 8 != 0 || p_.n < 8) throw std::invalid_argument("TrunkGrid: N must be a multiple of 8");
  const int L = static_cast<int>(levels_.size());
  z_uniform_.resize(levels_.size());
  for (int l = 0; l < L; ++l) {
    auto k = static_cast<std::size_t>(l);
    if (l == 0 || l == L - 1) z_uniform_[k] = levels_[k].z_spine;
    else z_uniform_[k] = 0.25 * (levels_[k - 1].z_spine + 2 * levels_[k].z_spine + levels_[k + 1].z_spine);
  }
  const int N = p_.n, m = N / 4, half = N / 2;
  for (int l = 0; l < L; ++l) {
    const GridLevel& lv = levels_[static_cast<std::size_t>(l)];
    first_.push_back(static_cast<int>(model_.nodes.size()));
    // Inner block (m+1)^2 nodes, a along x (back to front), b along y (right to left).
    TrunkSection s0 = sections_.at(lv.z_spine);
    double xb = lv.x_spine + lv.body_radius;
    double xf = lv.x_spine + p_.block_front * s0.wall_depth;
    double yh = p_.block_half_width * s0.wall_half_width;
    // The back edge of the block bulges backwards only at the midline (the vertebral body):
    // x_back(v) = xb + (xc - xb) v^2, v in [-1, 1], so the block corners sit well inside the
    // wall and the O-grid corner cells keep their angles.
    const double xc = lv.x_spine + p_.block_corner_back * s0.wall_depth;
    for (int a = 0; a <= m; ++a)
      for (int b = 0; b <= m; ++b) {
        double v = -1 + 2.0 * b / m;
        double xback = xb + (std::max(xc, xb) - xb) * v * v;
        double x = xback + (xf - xback) * a / m, y = yh * v;
        model_.add_node({x, y, level_height(l, x, y)});
      }
    // Rings 1..3: left half j = 0..N/2 computed, right half mirrored.
    std::vector<Eigen::Vector3d> wall(static_cast<std::size_t>(N)), skin(static_cast<std::size_t>(N));
    for (int j = 0; j <= half; ++j) {
      double s = static_cast<double>(j) / half;
      Eigen::Vector3d w(lv.x_spine, 0, lv.z_spine), k = w;
      for (int it = 0; it < 4; ++it) {
        TrunkSection sw = sections_.at(w.z());
        Eigen::Vector2d q = superellipse_half_point(lv.x_spine + sw.wall_depth / 2, sw.wall_depth / 2, sw.wall_half_width, sw.wall_exponent, s);
        w = {q.x(), q.y(), level_height(l, q.x(), q.y())};
        TrunkSection sk = sections_.at(k.z());
        Eigen::Vector2d r = superellipse_half_point(lv.x_spine - sk.back + sk.half_depth, sk.half_depth, sk.half_width, sk.exponent, s,
                                                    sk.widest_forward);
        k = {r.x(), r.y(), level_height(l, r.x(), r.y())};
      }
      wall[static_cast<std::size_t>(j)] = w;
      skin[static_cast<std::size_t>(j)] = k;
      if (j > 0 && j < half) {
        wall[static_cast<std::size_t>(N - j)] = {w.x(), -w.y(), w.z()};
        skin[static_cast<std::size_t>(N - j)] = {k.x(), -k.y(), k.z()};
      }
    }
    for (int r = 1; r <= 3; ++r)
      for (int j = 0; j < N; ++j) {
        auto k = static_cast<std::size_t>(j);
        Eigen::Vector3d q = r == 1 ? wall[k] : r == 3 ? skin[k] : wall[k] + p_.flesh_fraction * (skin[k] - wall[k]);
        if (r == 2) q.z() = level_height(l, q.x(), q.y());
        model_.add_node(q);
      }
  }
  enforce_min_thickness();
}

void TrunkGrid::enforce_min_thickness() {
  // Away from the spine (relaxation weight below 1/2) a layer is kept at least 30 % of the
  // evenly spaced height thick: tilt changes between levels can otherwise fold thin layers
  // at the front of the trunk. Nodes are pushed up level by level.
  const int L = static_cast<int>(levels_.size());
  const int per_level = (m() + 1) * (m() + 1) + 3 * p_.n;
  for (int l = 1; l < L; ++l) {
    auto k = static_cast<std::size_t>(l);
    double min_t = 0.3 * (z_uniform_[k] - z_uniform_[k - 1]);
    const GridLevel& lv = levels_[k];
    for (int i = 0; i < per_level; ++i) {
      auto& top = model_.nodes[static_cast<std::size_t>(first_[k] + i)];
      const auto& bot = model_.nodes[static_cast<std::size_t>(first_[k - 1] + i)];
      double d = std::hypot(top.x() - lv.x_spine, top.y());
      double w = d <= lv.body_radius ? 1.0 : std::exp(-std::pow((d - lv.body_radius) / p_.relax_length, 2));
      if (w < 0.5 && top.z() < bot.z() + min_t) top.z() = bot.z() + min_t;
    }
  }
}

double TrunkGrid::level_height(int l, double x, double y) const {
  const GridLevel& lv = levels_[static_cast<std::size_t>(l)];
  double base = lv.z_spine - std::tan(lv.tilt) * (x - lv.x_spine);
  double d = std::hypot(x - lv.x_spine, y);
  double w = d <= lv.body_radius ? 1.0 : std::exp(-std::pow((d - lv.body_radius) / p_.relax_length, 2));
  return base + (1 - w) * (z_uniform_[static_cast<std::size_t>(l)] - lv.z_spine);
}

int TrunkGrid::block_node(int l, int a, int b) const {
  return first_[static_cast<std::size_t>(l)] + a * (m() + 1) + b;
}

int TrunkGrid::ring_node(int l, int r, int j) const {
  const int N = p_.n, m = N / 4;
  j = ((j % N) + N) % N;
  if (r > 0) return first_[static_cast<std::size_t>(l)] + (m + 1) * (m + 1) + (r - 1) * N + j;
  // Block boundary walk: j = 0 front midline (a = m, b = m/2), counter-clockwise seen
  // from above (towards +y first).
  const int h = m / 2;
  int a = 0, b = 0;
  if (j <= h) { a = m; b = h + j; }
  else if (j <= h + m) { a = m - (j - h); b = m; }
  else if (j <= h + 2 * m) { a = 0; b = m - (j - h - m); }
  else if (j <= h + 3 * m) { a = j - h - 2 * m; b = 0; }
  else { a = m; b = j - h - 3 * m; }
  return block_node(l, a, b);
}

std::array<int, 8> TrunkGrid::oriented(std::array<int, 8> h) const {
  // Signed volume via the two diagonal tetrahedra decomposition sign: use the Jacobian at
  // the centre (sum of edge vectors).
  auto P = [&](int i) { return model_.nodes[static_cast<std::size_t>(h[static_cast<std::size_t>(i)])]; };
  Eigen::Vector3d e1 = (P(1) + P(2) + P(6) + P(5)) - (P(0) + P(3) + P(7) + P(4));
  Eigen::Vector3d e2 = (P(3) + P(2) + P(6) + P(7)) - (P(0) + P(1) + P(5) + P(4));
  Eigen::Vector3d e3 = (P(4) + P(5) + P(6) + P(7)) - (P(0) + P(1) + P(2) + P(3));
  if (e1.cross(e2).dot(e3) < 0) {
    std::swap(h[1], h[3]);
    std::swap(h[5], h[7]);
  }
  return h;
}

std::array<int, 8> TrunkGrid::ring_cell(int l, int r, int j) const {
  return oriented({ring_node(l, r, j), ring_node(l, r + 1, j), ring_node(l, r + 1, j + 1), ring_node(l, r, j + 1),
                   ring_node(l + 1, r, j), ring_node(l + 1, r + 1, j), ring_node(l + 1, r + 1, j + 1), ring_node(l + 1, r, j + 1)});
}

std::array<int, 8> TrunkGrid::block_cell(int l, int a, int b) const {
  return oriented({block_node(l, a, b), block_node(l, a + 1, b), block_node(l, a + 1, b + 1), block_node(l, a, b + 1),
                   block_node(l + 1, a, b), block_node(l + 1, a + 1, b), block_node(l + 1, a + 1, b + 1), block_node(l + 1, a, b + 1)});
}

std::array<int, 4> TrunkGrid::ring_face_span(int l, int l_top, int r, int j) const {
  std::array<int, 4> q{ring_node(l, r, j), ring_node(l, r, j + 1), ring_node(l_top, r, j + 1), ring_node(l_top, r, j)};
  auto P = [&](int i) { return model_.nodes[static_cast<std::size_t>(q[static_cast<std::size_t>(i)])]; };
  Eigen::Vector3d nrm = tri_cross(P(0), P(1), P(2)) + tri_cross(P(0), P(2), P(3));
  Eigen::Vector3d c = 0.25 * (P(0) + P(1) + P(2) + P(3));
  const GridLevel& lv = levels_[static_cast<std::size_t>(l)];
  TrunkSection s = sections_.at(lv.z_spine);
  Eigen::Vector3d axis(lv.x_spine + s.wall_depth / 2, 0, c.z());
  if (nrm.dot(c - axis) < 0) std::swap(q[1], q[3]);
  return q;
}

std::vector<int> TrunkGrid::level_nodes(int l) const {
  std::vector<int> v;
  int count = (m() + 1) * (m() + 1) + 3 * p_.n;
  for (int i = 0; i < count; ++i) v.push_back(first_[static_cast<std::size_t>(l)] + i);
  return v;
}

bool TrunkGrid::is_column_cell(int r, int j) const {
  int N = p_.n;
  j = ((j % N) + N) % N;
  return r <= 1 && (j == N / 2 - 1 || j == N / 2);
}

}  // namespace hbm::deckgen
