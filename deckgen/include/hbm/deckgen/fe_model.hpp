// SPDX-License-Identifier: GPL-3.0-or-later
// The finite-element body model as deckgen builds it, before it becomes a deck: nodes,
// parts (element kind, material, property, segment, region), elements in struct-of-arrays
// groups, rigid bodies, spring joints and contact interfaces. Units: kg, mm, ms (force kN,
// stress GPa, stiffness kN/mm, rotational stiffness kN*mm/rad = N*m/rad).
#pragma once

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace hbm::deckgen {

// Brick: a solid part (its elements are in `bricks` and `tetras`); Tetra names a tetra's
// element list in element_mass().
enum class ElementKind { Brick, Tetra, Shell, Tria, Spring };

// Material in model units (density kg/mm^3, moduli GPa, beta 1/ms).
struct FeMaterial {
  int id = 0;
  std::string name, law;  // LAW1 / LAW2 / LAW34
  double rho = 0, E = 0, nu = 0;      // LAW1, LAW2
  double yield = 0, hardening = 0, eps_p_max = 0;  // LAW2: sigma_y = yield + hardening eps_p, deletion at eps_p_max
  double K = 0, G0 = 0, Ginf = 0, beta = 0;  // LAW34
  std::string source;
  // Dilatational wave speed (mm/ms) for solids, plate wave speed for shells.
  double solid_wave_speed() const;
  double plate_wave_speed() const;
};

// Spring property: TYPE4 (k[0], c[0]) or TYPE8 (k[0..2] translational kN/mm, k[3..5]
// rotational kN*mm/rad; c likewise).
struct FeSpringProp {
  int id = 0;
  std::string name;
  int type = 4;
  std::array<double, 6> k{}, c{};
  double mass = 0, inertia = 0;
};

struct FePart {
  int id = 0;
  std::string name;
  ElementKind kind = ElementKind::Brick;
  int material = 0;        // index into FeModel::materials (-1 for springs)
  int spring_prop = -1;    // index into FeModel::spring_props for springs
  double thickness = 0;    // shells: property thickness (element thickness may override)
  std::string segment;     // head, neck, thorax, abdomen, pelvis, humerus_r, ...
  std::string region;      // budget region (ribs, organs, spine, ...)
  bool rigid = false;      // all its nodes are in rigid bodies
  double fail_fraction = 0;  // shells: P_thick_fail (0: all through-thickness points fail)
};

struct FeRigidBody {
  int id = 0;
  std::string name, segment;
  int main_node = 0;               // node index
  std::vector<int> nodes;          // secondary node indices (sorted, unique)
  double added_mass = 0;           // kg, at the main node
  Eigen::Matrix3d added_inertia = Eigen::Matrix3d::Zero();  // kg*mm^2 about the main node
};

struct FeInterface {
  int id = 0;
  int type = 7;                    // 7 penalty, 2 tied
  std::string name;
  std::vector<int> secondary;      // node indices
  std::vector<std::array<int, 4>> main_segments;  // node indices (n4 == n3 for triangles)
  std::vector<int> main_parts;     // part indices: main surface /SURF/PART instead of segments
  double gap = 0, stiffness_factor = 0, friction = 0, search = 0;
};

struct FeModel {
  std::vector<Eigen::Vector3d> nodes;  // node id = index + 1
  std::vector<FePart> parts;
  std::vector<FeMaterial> materials;
  std::vector<FeSpringProp> spring_props;
  // Element groups: part index per element; node indices.
  std::vector<std::array<int, 8>> bricks;
  std::vector<int> brick_part;
  // 4-node tetras of solid parts (ElementKind::Brick parts: a solid part may hold both).
  std::vector<std::array<int, 4>> tetras;
  std::vector<int> tetra_part;
  std::vector<std::array<int, 4>> shells;
  std::vector<int> shell_part;
  std::vector<double> shell_thick;
  std::vector<std::array<int, 3>> trias;
  std::vector<int> tria_part;
  std::vector<double> tria_thick;
  std::vector<std::array<int, 2>> springs;
  std::vector<int> spring_part;
  std::vector<FeRigidBody> rigid_bodies;
  std::vector<FeInterface> interfaces;
  std::vector<std::string> notes;  // printed in the deck header

  int add_node(const Eigen::Vector3d& p) {
    nodes.push_back(p);
    return static_cast<int>(nodes.size()) - 1;
  }
  int add_material(FeMaterial m);
  int add_part(FePart p);
  int find_part(const std::string& name) const;
  int find_material(const std::string& name) const;
  std::size_t element_count() const { return bricks.size() + tetras.size() + shells.size() + trias.size() + springs.size(); }
  // Flags (1) of the nodes some element uses.
  std::vector<char> nodes_in_elements() const;
  // Drops the nodes no element, rigid body or interface refers to and renumbers the rest
  // in their order; returns how many were dropped.
  std::size_t remove_unreferenced_nodes();
};

// Warpage of a quad (degrees): the larger angle between the normals of the two triangles
// of either diagonal (0 for a flat quad). The quality check limits it, and the skin and
// wall layers split a quad above 15 degrees into two triangles.
double quad_warpage_deg(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, const Eigen::Vector3d& p3);

}  // namespace hbm::deckgen
