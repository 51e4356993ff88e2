// SPDX-License-Identifier: GPL-3.0-or-later
// Rigid body mass properties from secondary nodes against closed forms: a lattice of
// N^3 equal point masses with spacings (hx, hy, hz) has, about its centre,
//   J_xx = M (hy^2 + hz^2) (N^2 - 1) / 12 (and cyclic), no products of inertia
// (variance of N equally spaced points: h^2 (N^2 - 1) / 12). Rotated and translated, the
// principal moments are the same and the principal axes are the rotated lattice axes.
#include "rigid/rigid_mass_properties.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

using hbm::solver::rigid::PointMass;
using hbm::solver::rigid::compute_mass_properties;

namespace {

std::vector<PointMass> lattice(int n, double m, Eigen::Vector3d h, const Eigen::Matrix3d& R,
                               const Eigen::Vector3d& shift) {
  std::vector<PointMass> p;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        p.push_back({m, R * Eigen::Vector3d(i * h.x(), j * h.y(), k * h.z()) + shift, 0.0});
  return p;
}

}  // namespace

TEST(RigidMassProperties, CubicLatticeClosedForm) {
  const int n = 4;
  const double m = 0.01, h = 10.0;  // kg, mm
  const auto pts = lattice(n, m, {h, h, h}, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
  const auto mp = compute_mass_properties(pts);
  const double M = n * n * n * m;
  const double J = 2.0 * M * h * h * (n * n - 1) / 12.0;  // closed form, kg*mm^2
  EXPECT_NEAR(mp.mass, M, 1e-15 * M);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(mp.centre(a), 1.5 * h, 1e-12 * h);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(mp.inertia(a, b), a == b ? J : 0.0, 1e-12 * J) << a << b;
}

TEST(RigidMassProperties, RotatedBoxPrincipalAxes) {
  const int n = 3;
  const double m = 0.02;
  const Eigen::Vector3d h(10, 20, 30);
  const Eigen::Matrix3d R =
      (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())).toRotationMatrix();
  const Eigen::Vector3d shift(100, -50, 7);
  const auto mp = compute_mass_properties(lattice(n, m, h, R, shift));
  const double M = n * n * n * m, f = (n * n - 1) / 12.0;
  // Lattice-frame moments: x: hy^2 + hz^2, y: hx^2 + hz^2, z: hx^2 + hy^2.
  const Eigen::Vector3d lattice_J(M * f * (h.y() * h.y() + h.z() * h.z()),
                                  M * f * (h.x() * h.x() + h.z() * h.z()),
                                  M * f * (h.x() * h.x() + h.y() * h.y()));
  // Ascending order: z (500), y (1000), x (1300) in units of M f.
  const int order[3] = {2, 1, 0};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(mp.principal(k), lattice_J(order[k]), 1e-11 * lattice_J.maxCoeff());
    EXPECT_NEAR(std::abs(mp.axes.col(k).dot(R.col(order[k]))), 1.0, 1e-12) << "axis " << k;
  }
  EXPECT_NEAR(mp.axes.determinant(), 1.0, 1e-12);
  const Eigen::Vector3d centre = R * Eigen::Vector3d(h.x(), h.y(), h.z()) + shift;  // (n-1)/2 = 1
  EXPECT_NEAR((mp.centre - centre).norm(), 0.0, 1e-12 * centre.norm());
}

TEST(RigidMassProperties, AddedMassAndInertia) {
  // Two masses 1 kg at x = +-10 mm: J = diag(0, 200, 200); added 3 kg at the centre and
  // an added isotropic 5 kg*mm^2 give mass 5 kg and J = diag(5, 205, 205).
  std::vector<PointMass> p{{1.0, {10, 0, 0}, 0.0}, {1.0, {-10, 0, 0}, 0.0}};
  const auto mp = compute_mass_properties(p, 3.0, 5.0 * Eigen::Matrix3d::Identity());
  EXPECT_DOUBLE_EQ(mp.mass, 5.0);
  EXPECT_NEAR(mp.principal(0), 5.0, 1e-12);
  EXPECT_NEAR(mp.principal(1), 205.0, 1e-12);
  EXPECT_NEAR(mp.principal(2), 205.0, 1e-12);
}

TEST(RigidMassProperties, CollinearNodesWithoutInertiaAreRejected) {
  std::vector<PointMass> p{{1.0, {10, 0, 0}, 0.0}, {1.0, {-10, 0, 0}, 0.0}};
  EXPECT_THROW(compute_mass_properties(p), std::invalid_argument);
  std::vector<PointMass> none{{0.0, {0, 0, 0}, 0.0}};
  EXPECT_THROW(compute_mass_properties(none), std::invalid_argument);
}
