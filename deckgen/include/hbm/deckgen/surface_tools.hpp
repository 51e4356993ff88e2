// SPDX-License-Identifier: GPL-3.0-or-later
// Surface operations done with CGAL: closed-surface extraction from a hexahedral region
// (its boundary quads), inside/outside tests (Side_of_triangle_mesh), self-intersection and
// closedness checks (Polygon_mesh_processing), enclosed volume.
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace hbm::deckgen {

struct TriSurface {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
};

// Boundary faces (faces used by exactly one hexahedron) of a set of hexahedra, as quads
// with outward normals (node order of the element convention n1-n4 bottom, n5-n8 top).
std::vector<std::array<int, 4>> hex_boundary_faces(const std::vector<std::array<int, 8>>& hexes);
// The same for positively oriented tetras: triangles as quads with n4 = n3.
std::vector<std::array<int, 4>> tet_boundary_faces(const std::vector<std::array<int, 4>>& tets);

// Triangulated surface from quads (index into `nodes`); quads split along the shorter diagonal.
TriSurface triangulate(const std::vector<Eigen::Vector3d>& nodes, const std::vector<std::array<int, 4>>& quads);

struct SurfaceReport {
  bool closed = false;
  bool self_intersecting = false;
  double volume = 0;  // mm^3, if closed
  std::size_t triangles = 0;
};
SurfaceReport check_surface(const TriSurface& s);

// For each query point: distance to the surface (CGAL AABB tree).
std::vector<double> distance_to_surface(const TriSurface& s, const std::vector<Eigen::Vector3d>& queries);

// For each query point: true if strictly inside the closed surface.
std::vector<bool> inside_surface(const TriSurface& s, const std::vector<Eigen::Vector3d>& queries);

}  // namespace hbm::deckgen
