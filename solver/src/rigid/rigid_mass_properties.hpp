// SPDX-License-Identifier: GPL-3.0-or-later
// Mass properties of a rigid body from its nodes: total mass, centre of mass, inertia
// tensor about the centre of mass and its principal moments and axes. Each node is a
// point mass with an optional isotropic nodal rotational inertia (springs, given node
// inertia). Added mass (/RBODY Mass, at the centre) and an added inertia tensor (/RBODY
// Jxx..Jxz, about the centre, global axes) are included when given.
// Units: mass kg, length mm, inertia kg*mm^2.
#pragma once

#include <Eigen/Dense>

#include <span>

namespace hbm::solver::rigid {

struct PointMass {
  double m = 0;                          // kg
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  // mm
  double j = 0;                          // isotropic nodal inertia, kg*mm^2
};

struct MassProperties {
  double mass = 0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();   // about the centre, global axes
  Eigen::Vector3d principal = Eigen::Vector3d::Zero(); // ascending principal moments
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // columns: principal axes, det = +1
};

// Inertia tensor of point masses about `about`: J = sum m (|r|^2 I - r r^T), r = x - about.
Eigen::Matrix3d point_inertia(std::span<const PointMass> points, const Eigen::Vector3d& about);

// Mass properties of the points plus an added mass at the centre and an added inertia
// tensor (global axes, about the centre). Throws std::invalid_argument when the total
// mass is not positive or the inertia tensor is not positive definite (a body whose nodes
// are all on one line, without nodal inertia, has a zero moment about that line).
MassProperties compute_mass_properties(std::span<const PointMass> points,
                                       double added_mass = 0,
                                       const Eigen::Matrix3d& added_inertia = Eigen::Matrix3d::Zero());

// Principal moments (ascending) and axes (columns, right-handed) of a symmetric tensor.
void principal_axes(const Eigen::Matrix3d& inertia, Eigen::Vector3d& moments, Eigen::Matrix3d& axes);

}  // namespace hbm::solver::rigid
