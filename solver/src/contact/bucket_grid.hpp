// SPDX-License-Identifier: GPL-3.0-or-later
// Uniform bucket grid over axis-aligned boxes (contact segments inflated by gap + search
// margin). Each box is registered in every cell it overlaps, so a point query needs a
// single cell and then a box test per entry. Cells are stored in compressed rows (CSR);
// the grid is rebuilt from scratch at each contact sort, which is rare (see
// PenaltyContact: only when some node may have moved more than half the margin).
#pragma once

#include "hbm/solver/types.hpp"
#include "vec3.hpp"

#include <cstdint>
#include <vector>

namespace hbm::solver::contact {

struct Box {
  V3 lo, hi;
  bool contains(V3 p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
           p.z <= hi.z;
  }
};

class BucketGrid {
 public:
  // Cell edge is about `cell_hint` (typically the mean inflated box size), enlarged when
  // needed so that the grid never has more than max(64, 8 * boxes.size()) cells.
  void build(const std::vector<Box>& boxes, double cell_hint);
  // Calls visit(box_index) for every box that contains p (each box at most once).
  template <class Visit>
  void for_each_containing(V3 p, const std::vector<Box>& boxes, Visit&& visit) const {
    if (boxes.empty() || !bounds_.contains(p)) return;
    const std::size_t c = cell_of(p);
    for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
      const Index b = entries_[k];
      if (boxes[static_cast<std::size_t>(b)].contains(p)) visit(b);
    }
  }
  std::size_t n_cells() const { return start_.empty() ? 0 : start_.size() - 1; }
  std::size_t n_entries() const { return entries_.size(); }

 private:
  std::size_t cell_of(V3 p) const;
  int clamp_cell(double coord, double lo, int n) const;
  Box bounds_;
  double inv_h_ = 1;
  int nx_ = 0, ny_ = 0, nz_ = 0;
  std::vector<std::uint32_t> start_;  // CSR row starts, size n_cells + 1
  std::vector<Index> entries_;        // box indices per cell
};

}  // namespace hbm::solver::contact
