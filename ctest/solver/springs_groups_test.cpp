// SPDX-License-Identifier: GPL-3.0-or-later
// Spring element groups (TYPE4, TYPE8, TYPE13) on single elements: forces in the right
// frame with the stiffness of the right DOF, objectivity (rigid motions give no force),
// balance of forces and moments (sum f = 0, sum x x f + m = 0), nodal stiffness for the
// time step (k_slot = K, sqrt(2 m / K)).
#include "springs/spring_axial_group.hpp"
#include "springs/spring_beam_group.hpp"
#include "springs/spring_general_group.hpp"
#include "springs/spring_group_factory.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

using namespace hbm::solver;
using namespace hbm::solver::springs;

namespace {

NodalState two_nodes(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  NodalState n;
  n.resize(2);
  for (int i = 0; i < 2; ++i) {
    const Eigen::Vector3d& p = i == 0 ? a : b;
    n.x0.x[i] = n.x.x[i] = p.x();
    n.x0.y[i] = n.x.y[i] = p.y();
    n.x0.z[i] = n.x.z[i] = p.z();
    n.mass0[i] = n.mass[i] = 1.0;
    n.inertia0[i] = n.inertia[i] = 1.0;
    n.has_rotation[i] = 1;
  }
  return n;
}

SpringProperty linear_property(SpringType type, const std::array<double, 6>& k) {
  SpringProperty p;
  p.type = type;
  p.dofs.resize(type == SpringType::Axial ? 1 : 6);
  for (std::size_t d = 0; d < p.dofs.size(); ++d) p.dofs[d].K = k[d];
  return p;
}

Eigen::Vector3d slot_f(const ElementGroup& g, std::size_t s) {
  return {g.slot_force.x[s], g.slot_force.y[s], g.slot_force.z[s]};
}
Eigen::Vector3d slot_m(const ElementGroup& g, std::size_t s) {
  return {g.slot_moment.x[s], g.slot_moment.y[s], g.slot_moment.z[s]};
}
void set_x(NodalState& n, int i, const Eigen::Vector3d& p) {
  n.x.x[i] = p.x(); n.x.y[i] = p.y(); n.x.z[i] = p.z();
}
Eigen::Vector3d get_x(const NodalState& n, int i) { return {n.x.x[i], n.x.y[i], n.x.z[i]}; }

}  // namespace

TEST(SpringAxial, ForceAlongTheAxisAndObjective) {
  NodalState n = two_nodes({0, 0, 0}, {3, 4, 0});  // l0 = 5 mm
  auto g = make_spring_group(linear_property(SpringType::Axial, {2.0}), 0, {0, 1}, {7}, n);
  GroupStepResult r;
  set_x(n, 1, {3.6, 4.8, 0});  // l = 6: tension 2 kN
  g->compute_forces(StepContext{1, 0, 1e-3, 1e-3}, n, r);
  EXPECT_NEAR((slot_f(*g, 0) - Eigen::Vector3d(1.2, 1.6, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((slot_f(*g, 0) + slot_f(*g, 1)).norm(), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(g->slot_stiffness[0], 2.0);
  EXPECT_NEAR(r.dt_min, std::sqrt(2.0 * 1.0 / 2.0), 1e-14);
  // Rigid rotation of the unstretched spring: no force.
  auto g2 = make_spring_group(linear_property(SpringType::Axial, {2.0}), 0, {0, 1}, {7}, n);
  set_x(n, 1, {-4, 3, 0});
  g2->compute_forces(StepContext{1, 0, 1e-3, 1e-3}, n, r);
  EXPECT_NEAR(slot_f(*g2, 1).norm(), 0.0, 1e-12);
}

TEST(SpringGeneral, SixDofsInASkewFrame) {
  NodalState n = two_nodes({0, 0, 0}, {0, 0, 0});  // coincident nodes
  SpringProperty p = linear_property(SpringType::General, {1, 2, 3, 4, 5, 6});
  p.skew = Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  p.has_skew = true;
  auto g = make_spring_group(p, 0, {0, 1}, {1}, n);
  // Node 2 moves 0.1 mm along the skew y axis and turns 0.01 rad about the skew z axis.
  set_x(n, 1, 0.1 * p.skew.col(1));
  const Eigen::Vector3d w = (0.01 / 1e-3) * p.skew.col(2);
  n.omega.x[1] = w.x(); n.omega.y[1] = w.y(); n.omega.z[1] = w.z();
  GroupStepResult r;
  g->compute_forces(StepContext{1, 0, 1e-3, 1e-3}, n, r);
  const auto& out = static_cast<const SpringGroup&>(*g).out_force[0];
  EXPECT_NEAR(out[0], 0.0, 1e-14);
  EXPECT_NEAR(out[1], 2.0 * 0.1, 1e-14);
  EXPECT_NEAR(out[5], 6.0 * 0.01, 1e-14);
  EXPECT_NEAR((slot_f(*g, 1) + 0.2 * p.skew.col(1)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((slot_m(*g, 1) + 0.06 * p.skew.col(2)).norm(), 0.0, 1e-14);
}

TEST(SpringBeam, RigidMotionGivesNoForceAndShearIsBalanced) {
  const double l0 = 10.0;
  NodalState n = two_nodes({0, 0, 0}, {l0, 0, 0});
  auto g = make_spring_group(linear_property(SpringType::Beam, {10, 20, 30, 40, 50, 60}), 0,
                             {0, 1}, {1}, n);
  auto& beam = dynamic_cast<SpringBeamGroup&>(*g);
  // Rigid rotation about a skew axis through node 0, 200 steps of 1e-3 ms at 2 rad/ms.
  const Eigen::Vector3d w = 2.0 * Eigen::Vector3d(1, 2, -1).normalized();
  const double dt = 1e-3;
  GroupStepResult r;
  for (int i = 0; i < 2; ++i) { n.omega.x[i] = w.x(); n.omega.y[i] = w.y(); n.omega.z[i] = w.z(); }
  for (int step = 1; step <= 200; ++step) {
    const Eigen::Matrix3d R = Eigen::AngleAxisd(w.norm() * dt * step, w.normalized()).toRotationMatrix();
    set_x(n, 1, R * Eigen::Vector3d(l0, 0, 0));
    g->compute_forces(StepContext{step, step * dt, dt, dt}, n, r);
  }
  EXPECT_NEAR(slot_f(*g, 1).norm(), 0.0, 1e-9);
  EXPECT_NEAR(slot_m(*g, 1).norm(), 0.0, 1e-8);
  // Now a shear displacement u of node 1 along the element's current y axis.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(w.norm() * dt * 200, w.normalized()).toRotationMatrix();
  const Eigen::Vector3d ey = R * beam.frame0[0].col(1);
  set_x(n, 1, R * Eigen::Vector3d(l0, 0, 0) + 0.05 * ey);
  for (int i = 0; i < 2; ++i) n.omega.x[i] = n.omega.y[i] = n.omega.z[i] = 0;
  g->compute_forces(StepContext{201, 0.201, dt, dt}, n, r);
  EXPECT_NEAR(beam.out_force[0][1], 20.0 * 0.05, 1e-9);
  // Balance: sum of forces and sum of moments about the origin vanish.
  const Eigen::Vector3d fsum = slot_f(*g, 0) + slot_f(*g, 1);
  const Eigen::Vector3d msum = get_x(n, 0).cross(slot_f(*g, 0)) + get_x(n, 1).cross(slot_f(*g, 1)) +
                               slot_m(*g, 0) + slot_m(*g, 1);
  EXPECT_NEAR(fsum.norm(), 0.0, 1e-12);
  EXPECT_NEAR(msum.norm(), 0.0, 1e-12);
}

TEST(SpringBeam, TorsionAndBendingFromNodalRotations) {
  NodalState n = two_nodes({0, 0, 0}, {10, 0, 0});
  auto g = make_spring_group(linear_property(SpringType::Beam, {10, 20, 30, 40, 50, 60}), 0,
                             {0, 1}, {1}, n);
  // Node 1 turns 0.02 rad about x (torsion) in one step.
  n.omega.x[1] = 0.02 / 1e-3;
  GroupStepResult r;
  g->compute_forces(StepContext{1, 1e-3, 1e-3, 1e-3}, n, r);
  const auto& out = dynamic_cast<SpringBeamGroup&>(*g).out_force[0];
  EXPECT_NEAR(out[3], 40.0 * 0.02, 1e-12);
  EXPECT_NEAR(slot_m(*g, 1).x(), -40.0 * 0.02, 1e-12);
}

TEST(SpringBeam, OrientationNodeSetsTheLocalYAxis) {
  NodalState n;
  n.resize(3);
  n.x0.x[1] = n.x.x[1] = 10.0;  // axis along X
  n.x0.z[2] = n.x.z[2] = 5.0;   // n3 above node 1: local y = global Z
  for (int i = 0; i < 3; ++i) { n.mass0[i] = n.mass[i] = 1; n.inertia0[i] = n.inertia[i] = 1; n.has_rotation[i] = 1; }
  const std::vector<Index> n3{2};
  auto g = make_spring_group(linear_property(SpringType::Beam, {10, 20, 30, 40, 50, 60}), 0, {0, 1}, {1}, n, &n3);
  auto& beam = dynamic_cast<SpringBeamGroup&>(*g);
  EXPECT_NEAR((beam.frame0[0].col(1) - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-15);
  n.x.z[1] = 0.1;  // shear along global Z = local y: K2 = 20
  GroupStepResult r;
  g->compute_forces(StepContext{1, 0, 1e-3, 1e-3}, n, r);
  EXPECT_NEAR(beam.out_force[0][1], 20.0 * 0.1, 1e-9);
  EXPECT_NEAR(beam.out_force[0][2], 0.0, 1e-9);
}
