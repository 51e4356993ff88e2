// SPDX-License-Identifier: GPL-3.0-or-later
// FeModel helpers: registration of parts and materials, wave speeds.
#include "hbm/deckgen/fe_model.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hbm::deckgen {

double FeMaterial::solid_wave_speed() const {
  // c = sqrt((K + 4G/3) / rho); LAW34 uses the short-time shear modulus.
  if (law == "LAW34") return std::sqrt((K + 4.0 * G0 / 3.0) / rho);
  double k = E / (3 * (1 - 2 * nu)), g = E / (2 * (1 + nu));
  return std::sqrt((k + 4.0 * g / 3.0) / rho);
}

double FeMaterial::plate_wave_speed() const {
  // c = sqrt(E / (rho (1 - nu^2))) (plane-stress dilatational wave, shells).
  if (law == "LAW34") {
    double e = 9 * K * G0 / (3 * K + G0), n = (3 * K - 2 * G0) / (2 * (3 * K + G0));
    return std::sqrt(e / (rho * (1 - n * n)));
  }
  return std::sqrt(E / (rho * (1 - nu * nu)));
}

double quad_warpage_deg(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, const Eigen::Vector3d& p3) {
  auto angle = [](const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
    return std::acos(std::clamp(u.normalized().dot(v.normalized()), -1.0, 1.0)) * 180 / M_PI;
  };
  return std::max(angle((p1 - p0).cross(p2 - p0), (p2 - p0).cross(p3 - p0)), angle((p2 - p1).cross(p3 - p1), (p3 - p1).cross(p0 - p1)));
}

int FeModel::add_material(FeMaterial m) {
  m.id = static_cast<int>(materials.size()) + 1;
  materials.push_back(std::move(m));
  return static_cast<int>(materials.size()) - 1;
}

int FeModel::add_part(FePart p) {
  p.id = static_cast<int>(parts.size()) + 1;
  parts.push_back(std::move(p));
  return static_cast<int>(parts.size()) - 1;
}

int FeModel::find_part(const std::string& name) const {
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (parts[i].name == name) return static_cast<int>(i);
  return -1;
}

std::vector<char> FeModel::nodes_in_elements() const {
  std::vector<char> in(nodes.size(), 0);
  auto mark = [&](const auto& elements) {
    for (const auto& e : elements)
      for (int n : e) in[static_cast<std::size_t>(n)] = 1;
  };
  mark(bricks);
  mark(tetras);
  mark(shells);
  mark(trias);
  mark(springs);
  return in;
}

std::size_t FeModel::remove_unreferenced_nodes() {
  std::vector<char> used = nodes_in_elements();
  auto mark = [&](int n) { used[static_cast<std::size_t>(n)] = 1; };
  for (const auto& r : rigid_bodies) {
    mark(r.main_node);
    for (int n : r.nodes) mark(n);
  }
  for (const auto& f : interfaces) {
    for (int n : f.secondary) mark(n);
    for (const auto& s : f.main_segments) for (int n : s) mark(n);
  }
  std::vector<int> new_id(nodes.size(), -1);
  std::vector<Eigen::Vector3d> kept;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (used[i]) {
      new_id[i] = static_cast<int>(kept.size());
      kept.push_back(nodes[i]);
    }
  const std::size_t dropped = nodes.size() - kept.size();
  if (dropped == 0) return 0;
  auto re = [&](int& n) { n = new_id[static_cast<std::size_t>(n)]; };
  for (auto& e : bricks) for (int& n : e) re(n);
  for (auto& e : tetras) for (int& n : e) re(n);
  for (auto& e : shells) for (int& n : e) re(n);
  for (auto& e : trias) for (int& n : e) re(n);
  for (auto& e : springs) for (int& n : e) re(n);
  for (auto& r : rigid_bodies) {
    re(r.main_node);
    for (int& n : r.nodes) re(n);
  }
  for (auto& f : interfaces) {
    for (int& n : f.secondary) re(n);
    for (auto& s : f.main_segments) for (int& n : s) re(n);
  }
  nodes = std::move(kept);
  return dropped;
}

int FeModel::find_material(const std::string& name) const {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace hbm::deckgen
