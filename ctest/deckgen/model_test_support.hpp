// SPDX-License-Identifier: GPL-3.0-or-later
// What the deckgen model tests share: the committed geometry sources, loaded once, and the
// nodes of the elements of chosen parts.
#pragma once

#include "hbm/deckgen/fe_model.hpp"
#include "hbm/deckgen/geometry_sources.hpp"

#include <filesystem>
#include <set>
#include <vector>

namespace hbm::deckgen::test {

// geometry/ of the source tree (HBM_SOURCE_DIR), loaded on first use.
inline const GeometrySources& committed_geometry() {
  static const GeometrySources g = load_geometry(std::filesystem::path(HBM_SOURCE_DIR) / "geometry");
  return g;
}

// Nodes used by the elements (springs included) of the parts `pick(part index)` selects.
template <class Pick>
std::set<int> nodes_of(const FeModel& m, Pick pick) {
  std::set<int> out;
  auto add = [&](const auto& elements, const std::vector<int>& part_of) {
    for (std::size_t e = 0; e < elements.size(); ++e)
      if (pick(part_of[e]))
        for (int n : elements[e]) out.insert(n);
  };
  add(m.bricks, m.brick_part);
  add(m.tetras, m.tetra_part);
  add(m.shells, m.shell_part);
  add(m.trias, m.tria_part);
  add(m.springs, m.spring_part);
  return out;
}

}  // namespace hbm::deckgen::test
