// SPDX-License-Identifier: GPL-3.0-or-later
// Shell mesh of a rigid pendulum impactor: a flat circular face (triangles around the
// centre, quads outside) and a cylindrical rim swept back from the face edge, so the
// face edge is not a free shell edge that could snag skin nodes. Local node indices.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace hbm::deckgen::loadcases {

struct ImpactorDisc {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> trias;
  double area() const;  // total shell area (mm^2)
};

// face_centre: centre of the face; back: unit vector from the face into the impactor
// (opposite to the direction of travel); radius of the face; rim_depth behind the face.
ImpactorDisc make_impactor_disc(const Eigen::Vector3d& face_centre, const Eigen::Vector3d& back, double radius,
                                double rim_depth, int rings = 6, int sectors = 24, int rim_rows = 2);

}  // namespace hbm::deckgen::loadcases
