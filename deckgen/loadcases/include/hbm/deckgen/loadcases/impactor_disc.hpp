// SPDX-License-Identifier: GPL-3.0-or-later
// Shell mesh of a rigid pendulum impactor: a cylinder of outer radius R whose impacting end
// is a flat right-angle face with a rounded edge of radius r (49 CFR 572.36(a), the Hybrid
// III thorax probe: 6 in diameter cylinder, flat face, 0.5 in edge radius; the 6 in is the
// cylinder's diameter, so the flat part has radius R - r). Meshed as the flat face
// (triangles around the centre, quads outside), the fillet (a quarter torus swept in a few
// rows from the face plane to the cylinder) and a cylindrical rim behind it, so the face
// edge is neither a sharp rim that pinches the skin nor a free shell edge. r = 0 gives the
// sharp-edged disc (face and rim only). Local node indices.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace hbm::deckgen::loadcases {

struct ImpactorShape {
  double radius = 76;       // outer radius R of the cylinder (mm)
  double edge_radius = 0;   // fillet radius r between the flat face and the cylinder (mm), 0 <= r < R
  double rim_depth = 20;    // cylinder length meshed behind the fillet (mm)
  int rings = 6;            // radial rows of the flat face
  int sectors = 36;         // around the axis
  int fillet_rows = 4;      // rows of the fillet (r > 0)
  int rim_rows = 2;         // rows of the cylindrical rim

  // Set-back of the impactor surface behind the face plane, measured along the axis, at
  // distance rho from the axis: 0 on the flat part, r - sqrt(r^2 - (rho - (R - r))^2) on
  // the fillet, +infinity beyond R (outside the footprint).
  double setback(double rho) const;
};

struct ImpactorDisc {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> trias;
  double area() const;  // total shell area (mm^2)
};

// face_centre: centre of the flat face; back: unit vector from the face into the impactor
// (opposite to the direction of travel). Throws std::invalid_argument on a shape that
// cannot be meshed (r < 0, r >= R, fewer than 3 sectors, no rings, no fillet rows with r > 0).
ImpactorDisc make_impactor_disc(const Eigen::Vector3d& face_centre, const Eigen::Vector3d& back, const ImpactorShape& shape);

}  // namespace hbm::deckgen::loadcases
