// SPDX-License-Identifier: GPL-3.0-or-later
// Default behaviour shared by all element groups: slot allocation, deactivation of the
// elements inside a rigid body, VTK cell of an element (duplicate nodes of degenerate
// bricks collapsed to wedge / tetra), and the default cell fields.
#include "hbm/solver/element_group.hpp"

#include <algorithm>

namespace hbm::solver {

void ElementGroup::allocate_slots(bool rotational) {
  const std::size_t n_slots = n_elements * nodes_per_element;
  slot_force.resize(n_slots);
  slot_stiffness.assign(n_slots, 0.0);
  if (rotational) {
    slot_moment.resize(n_slots);
    slot_rot_stiffness.assign(n_slots, 0.0);
  }
  if (alive.size() != n_elements) alive.assign(n_elements, 1);
}

void ElementGroup::deactivate(std::span<const std::uint8_t> inside) {
  const std::size_t npe = nodes_per_element;
  for (std::size_t e = 0; e < n_elements && e < inside.size(); ++e) {
    if (!inside[e] || !alive[e]) continue;
    alive[e] = 0;
    ++n_deactivated;
    for (std::size_t s = e * npe; s < (e + 1) * npe; ++s) {
      slot_force.x[s] = slot_force.y[s] = slot_force.z[s] = 0.0;
      slot_stiffness[s] = 0.0;
      if (has_rotation_slots()) {
        slot_moment.x[s] = slot_moment.y[s] = slot_moment.z[s] = 0.0;
        slot_rot_stiffness[s] = 0.0;
      }
    }
  }
}

void ElementGroup::force_chunk_elements(std::size_t ch, std::vector<Index>& out) const {
  out.clear();
  for (std::size_t e = ch * kChunk; e < std::min(n_elements, (ch + 1) * kChunk); ++e)
    out.push_back(static_cast<Index>(e));
}

VtkCellType ElementGroup::vtk_cell(std::size_t e, Index* nodes, int& n_nodes) const {
  const std::size_t npe = nodes_per_element;
  const Index* c = connectivity.data() + e * npe;
  if (npe == 8) {
    // Degenerate bricks: prism n1 n2 n3 n3 / n5 n6 n7 n7, tetra n1 n2 n3 n3 / n4 n4 n4 n4.
    const bool top_tri = c[2] == c[3], bot_tri = c[6] == c[7];
    const bool apex = c[4] == c[5] && c[5] == c[6] && c[6] == c[7];
    if (top_tri && apex) {
      nodes[0] = c[0]; nodes[1] = c[1]; nodes[2] = c[2]; nodes[3] = c[4];
      n_nodes = 4;
      return VtkCellType::Tetra;
    }
    if (top_tri && bot_tri) {
      nodes[0] = c[0]; nodes[1] = c[1]; nodes[2] = c[2];
      nodes[3] = c[4]; nodes[4] = c[5]; nodes[5] = c[6];
      n_nodes = 6;
      return VtkCellType::Wedge;
    }
    std::copy(c, c + 8, nodes);
    n_nodes = 8;
    return VtkCellType::Hexahedron;
  }
  std::copy(c, c + npe, nodes);
  n_nodes = static_cast<int>(npe);
  switch (npe) {
    case 2: return VtkCellType::Line;
    case 3: return VtkCellType::Triangle;
    case 4: return solid_cells() ? VtkCellType::Tetra : VtkCellType::Quad;
    default: return VtkCellType::Hexahedron;
  }
}

void ElementGroup::cell_field(CellField field, std::span<double> out) const {
  for (std::size_t e = 0; e < out.size(); ++e)
    out[e] = (field == CellField::Eroded && e < alive.size()) ? (alive[e] ? 0.0 : 1.0) : 0.0;
}

}  // namespace hbm::solver
