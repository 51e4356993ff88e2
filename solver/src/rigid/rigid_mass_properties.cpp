// SPDX-License-Identifier: GPL-3.0-or-later
// Rigid body mass, centre and inertia from point masses (parallel-axis sums) and the
// principal decomposition by a symmetric eigen-solver.
#include "rigid/rigid_mass_properties.hpp"

#include <stdexcept>
#include <string>

namespace hbm::solver::rigid {

Eigen::Matrix3d point_inertia(std::span<const PointMass> points, const Eigen::Vector3d& about) {
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  for (const PointMass& p : points) {
    const Eigen::Vector3d r = p.x - about;
    J += p.m * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
    J.diagonal().array() += p.j;
  }
  return J;
}

void principal_axes(const Eigen::Matrix3d& inertia, Eigen::Vector3d& moments, Eigen::Matrix3d& axes) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (inertia + inertia.transpose()));
  moments = eig.eigenvalues();  // ascending
  axes = eig.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
}

MassProperties compute_mass_properties(std::span<const PointMass> points, double added_mass,
                                       const Eigen::Matrix3d& added_inertia) {
  MassProperties mp;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  for (const PointMass& p : points) {
    mp.mass += p.m;
    first += p.m * p.x;
  }
  if (!(mp.mass > 0)) throw std::invalid_argument("rigid body mass is not positive (its nodes carry no mass)");
  mp.centre = first / mp.mass;
  mp.mass += added_mass;  // added mass sits at the centre: no shift, no inertia
  mp.inertia = point_inertia(points, mp.centre) + added_inertia;
  principal_axes(mp.inertia, mp.principal, mp.axes);
  if (!(mp.principal(0) > 1e-12 * mp.principal(2)) || !(mp.principal(2) > 0))
    throw std::invalid_argument("rigid body inertia is singular (principal moments " +
                                std::to_string(mp.principal(0)) + ", " + std::to_string(mp.principal(1)) +
                                ", " + std::to_string(mp.principal(2)) +
                                " kg*mm^2): nodes on one line and no nodal or given inertia");
  return mp;
}

}  // namespace hbm::solver::rigid
