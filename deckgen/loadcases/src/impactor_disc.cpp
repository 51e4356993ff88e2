// SPDX-License-Identifier: GPL-3.0-or-later
// Impactor face and rim mesh (see impactor_disc.hpp).
#include "hbm/deckgen/loadcases/impactor_disc.hpp"

#include <Eigen/Geometry>

#include <cmath>

namespace hbm::deckgen::loadcases {

double ImpactorDisc::area() const {
  double a = 0;
  for (const auto& q : quads)
    a += 0.5 * (nodes[static_cast<std::size_t>(q[2])] - nodes[static_cast<std::size_t>(q[0])])
                   .cross(nodes[static_cast<std::size_t>(q[3])] - nodes[static_cast<std::size_t>(q[1])])
                   .norm();
  for (const auto& t : trias)
    a += 0.5 * (nodes[static_cast<std::size_t>(t[1])] - nodes[static_cast<std::size_t>(t[0])])
                   .cross(nodes[static_cast<std::size_t>(t[2])] - nodes[static_cast<std::size_t>(t[0])])
                   .norm();
  return a;
}

ImpactorDisc make_impactor_disc(const Eigen::Vector3d& face_centre, const Eigen::Vector3d& back, double radius,
                                double rim_depth, int rings, int sectors, int rim_rows) {
  const Eigen::Vector3d u = back.normalized();
  // e1, e2: in-plane axes of the face (any pair orthogonal to u).
  const Eigen::Vector3d helper = std::abs(u.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d e1 = helper.cross(u).normalized();
  const Eigen::Vector3d e2 = u.cross(e1);
  ImpactorDisc d;
  d.nodes.push_back(face_centre);
  auto ring_node = [&](int ring, int s) { return 1 + (ring - 1) * sectors + (s % sectors); };
  for (int ring = 1; ring <= rings; ++ring)
    for (int s = 0; s < sectors; ++s) {
      const double a = 2 * M_PI * s / sectors, r = radius * ring / rings;
      d.nodes.push_back(face_centre + r * (std::cos(a) * e1 + std::sin(a) * e2));
    }
  const int rim_first = static_cast<int>(d.nodes.size());
  for (int row = 1; row <= rim_rows; ++row)
    for (int s = 0; s < sectors; ++s) {
      const double a = 2 * M_PI * s / sectors;
      d.nodes.push_back(face_centre + radius * (std::cos(a) * e1 + std::sin(a) * e2) + rim_depth * row / rim_rows * u);
    }
  // Face normals point along -u (towards the body): counter-clockwise seen from the body.
  for (int s = 0; s < sectors; ++s) d.trias.push_back({0, ring_node(1, s + 1), ring_node(1, s)});
  for (int ring = 1; ring < rings; ++ring)
    for (int s = 0; s < sectors; ++s)
      d.quads.push_back({ring_node(ring, s), ring_node(ring, s + 1), ring_node(ring + 1, s + 1), ring_node(ring + 1, s)});
  auto rim_node = [&](int row, int s) { return row == 0 ? ring_node(rings, s) : rim_first + (row - 1) * sectors + (s % sectors); };
  for (int row = 0; row < rim_rows; ++row)
    for (int s = 0; s < sectors; ++s)
      d.quads.push_back({rim_node(row, s), rim_node(row + 1, s), rim_node(row + 1, s + 1), rim_node(row, s + 1)});
  return d;
}

}  // namespace hbm::deckgen::loadcases
