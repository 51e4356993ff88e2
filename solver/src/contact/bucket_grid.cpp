// SPDX-License-Identifier: GPL-3.0-or-later
// Uniform bucket grid: counting pass, prefix sum, filling pass (no per-cell vectors).
#include "bucket_grid.hpp"

#include <algorithm>
#include <cmath>

namespace hbm::solver::contact {

int BucketGrid::clamp_cell(double coord, double lo, int n) const {
  const int i = static_cast<int>(std::floor((coord - lo) * inv_h_));
  return std::clamp(i, 0, n - 1);
}

std::size_t BucketGrid::cell_of(V3 p) const {
  const int i = clamp_cell(p.x, bounds_.lo.x, nx_);
  const int j = clamp_cell(p.y, bounds_.lo.y, ny_);
  const int k = clamp_cell(p.z, bounds_.lo.z, nz_);
  return (static_cast<std::size_t>(k) * ny_ + j) * nx_ + i;
}

void BucketGrid::build(const std::vector<Box>& boxes, double cell_hint) {
  start_.clear();
  entries_.clear();
  if (boxes.empty()) return;
  bounds_ = boxes[0];
  for (const Box& b : boxes) {
    bounds_.lo = {std::min(bounds_.lo.x, b.lo.x), std::min(bounds_.lo.y, b.lo.y),
                  std::min(bounds_.lo.z, b.lo.z)};
    bounds_.hi = {std::max(bounds_.hi.x, b.hi.x), std::max(bounds_.hi.y, b.hi.y),
                  std::max(bounds_.hi.z, b.hi.z)};
  }
  const V3 ext = bounds_.hi - bounds_.lo;
  double h = cell_hint > 0 ? cell_hint : std::max({ext.x, ext.y, ext.z, 1e-30});
  const double max_cells = std::max(64.0, 8.0 * static_cast<double>(boxes.size()));
  auto count = [&](double hh) {
    return (std::floor(ext.x / hh) + 1) * (std::floor(ext.y / hh) + 1) * (std::floor(ext.z / hh) + 1);
  };
  while (count(h) > max_cells) h *= 1.25;
  inv_h_ = 1.0 / h;
  nx_ = static_cast<int>(std::floor(ext.x / h)) + 1;
  ny_ = static_cast<int>(std::floor(ext.y / h)) + 1;
  nz_ = static_cast<int>(std::floor(ext.z / h)) + 1;
  const std::size_t n_cells = static_cast<std::size_t>(nx_) * ny_ * nz_;
  start_.assign(n_cells + 1, 0);
  auto for_cells = [&](const Box& b, auto&& f) {
    const int i0 = clamp_cell(b.lo.x, bounds_.lo.x, nx_), i1 = clamp_cell(b.hi.x, bounds_.lo.x, nx_);
    const int j0 = clamp_cell(b.lo.y, bounds_.lo.y, ny_), j1 = clamp_cell(b.hi.y, bounds_.lo.y, ny_);
    const int k0 = clamp_cell(b.lo.z, bounds_.lo.z, nz_), k1 = clamp_cell(b.hi.z, bounds_.lo.z, nz_);
    for (int k = k0; k <= k1; ++k)
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) f((static_cast<std::size_t>(k) * ny_ + j) * nx_ + i);
  };
  for (const Box& b : boxes) for_cells(b, [&](std::size_t c) { ++start_[c + 1]; });
  for (std::size_t c = 0; c < n_cells; ++c) start_[c + 1] += start_[c];
  entries_.resize(start_[n_cells]);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t b = 0; b < boxes.size(); ++b)
    for_cells(boxes[b], [&](std::size_t c) { entries_[fill[c]++] = static_cast<Index>(b); });
}

}  // namespace hbm::solver::contact
