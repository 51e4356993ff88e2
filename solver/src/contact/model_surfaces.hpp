// SPDX-License-Identifier: GPL-3.0-or-later
// The model's contact geometry, gathered once in the build phase from the element
// cards: every solid (/BRICK, /TETRA4) with its part and bulk modulus, every shell
// (/SHELL, /SH3N) with its part, Young's modulus and thickness, and the outer faces of
// all solids (faces used by exactly one solid element of the whole model, outward).
// Contact surfaces are then cut from it: /SURF/PART = outer faces of the listed parts'
// solids + their shells; /SURF/SEG = the listed segments, matched to an outer solid face
// (one-sided, its K0) or a shell (two-sided, its K0 and thickness).
#pragma once

#include "contact_surface.hpp"
#include "hbm/solver/build_context.hpp"

#include <array>
#include <map>
#include <vector>

namespace hbm::solver::contact {

// Young's modulus and bulk modulus of a material card (/MAT/LAW1, LAW2, LAW34, LAW36);
// false if the law is not one of these.
bool material_moduli(const hbm::deck::Card& mat, double& young, double& bulk);

class ModelSurfaces {
 public:
  explicit ModelSurfaces(BuildContext& ctx);

  // Segments of the listed parts (indices into Model::parts).
  ContactSurface of_parts(const std::vector<Index>& parts) const;
  // Given segments (4 node indices, n4 == n3 for triangles). Segments found on no
  // element get K0 = 0 and are two-sided; their count is returned in `n_orphans`.
  ContactSurface of_segments(const std::vector<std::array<Index, 4>>& segs,
                             std::size_t& n_orphans) const;
  // Half the largest shell thickness at each node (Igap 1 secondary gap) [length].
  std::vector<double> node_half_thickness(const std::vector<Index>& nodes) const;
  // Largest K0 of the outer faces and shells at each node (Istf 2..5) [force/length].
  std::vector<double> node_stiffness(const std::vector<Index>& nodes) const;

 private:
  ContactSurface faces_;                  // outer faces of all solids
  std::vector<Index> face_part_;          // part of each outer face
  ContactSurface shells_;                 // all shell segments
  std::vector<Index> shell_part_;
  std::map<std::array<Index, 4>, std::size_t> face_key_, shell_key_;  // sorted nodes -> index
  std::size_t n_nodes_ = 0;
};

std::array<Index, 4> segment_key(std::array<Index, 4> nodes);

}  // namespace hbm::solver::contact
