// SPDX-License-Identifier: GPL-3.0-or-later
// Impactor face, fillet and rim mesh (see impactor_disc.hpp).
#include "hbm/deckgen/loadcases/impactor_disc.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace hbm::deckgen::loadcases {

double ImpactorShape::setback(double rho) const {
  const double flat = radius - edge_radius;
  if (rho <= flat) return 0;
  if (rho > radius) return std::numeric_limits<double>::infinity();
  const double d = std::min(rho - flat, edge_radius);  // rho = R may come out a rounding above R - r + r
  return edge_radius - std::sqrt(std::max(0.0, edge_radius * edge_radius - d * d));
}

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

ImpactorDisc make_impactor_disc(const Eigen::Vector3d& face_centre, const Eigen::Vector3d& back, const ImpactorShape& shape) {
  const double R = shape.radius, r = shape.edge_radius;
  if (!(R > 0) || !(r >= 0) || !(r < R) || shape.rings < 1 || shape.sectors < 3 || shape.rim_rows < 0 ||
      (r > 0 && shape.fillet_rows < 1) || shape.rim_depth < 0)
    throw std::invalid_argument("impactor: radius " + std::to_string(R) + " mm, edge radius " + std::to_string(r) +
                                " mm, " + std::to_string(shape.rings) + " rings, " + std::to_string(shape.sectors) +
                                " sectors, " + std::to_string(shape.fillet_rows) + " fillet rows: need 0 <= edge radius < "
                                "radius, at least 1 ring, 3 sectors and 1 fillet row");
  const Eigen::Vector3d u = back.normalized();
  // e1, e2: in-plane axes of the face (any pair orthogonal to u, e1 x e2 = u).
  const Eigen::Vector3d helper = std::abs(u.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d e1 = helper.cross(u).normalized();
  const Eigen::Vector3d e2 = u.cross(e1);

  // Profile of the surface of revolution outward from the face centre: (distance from the
  // axis, set-back along u). Flat face to R - r, quarter circle of radius r centred at
  // (R - r, r), then the cylinder at R.
  std::vector<std::pair<double, double>> profile;
  const double flat = R - r;
  for (int k = 1; k <= shape.rings; ++k) profile.emplace_back(flat * k / shape.rings, 0.0);
  if (r > 0)
    for (int j = 1; j <= shape.fillet_rows; ++j) {
      const double t = 0.5 * M_PI * j / shape.fillet_rows;
      profile.emplace_back(flat + r * std::sin(t), r * (1 - std::cos(t)));
    }
  for (int j = 1; j <= shape.rim_rows; ++j) profile.emplace_back(R, r + shape.rim_depth * j / shape.rim_rows);

  ImpactorDisc d;
  d.nodes.push_back(face_centre);
  for (const auto& [rho, back_off] : profile)
    for (int s = 0; s < shape.sectors; ++s) {
      const double a = 2 * M_PI * s / shape.sectors;
      d.nodes.push_back(face_centre + rho * (std::cos(a) * e1 + std::sin(a) * e2) + back_off * u);
    }
  auto node = [&](int k, int s) { return 1 + k * shape.sectors + (s % shape.sectors); };  // k: profile index
  // Normals point out of the impactor: -u on the face (towards the body), outward on the
  // fillet and rim. Same node order on every row: (k, s), (k, s+1), (k+1, s+1), (k+1, s).
  for (int s = 0; s < shape.sectors; ++s) d.trias.push_back({0, node(0, s + 1), node(0, s)});
  for (int k = 0; k + 1 < static_cast<int>(profile.size()); ++k)
    for (int s = 0; s < shape.sectors; ++s) d.quads.push_back({node(k, s), node(k, s + 1), node(k + 1, s + 1), node(k + 1, s)});
  return d;
}

}  // namespace hbm::deckgen::loadcases
