// SPDX-License-Identifier: GPL-3.0-or-later
// /RWALL/PLANE on point masses: a node never crosses a fixed wall and its normal
// velocity is removed; the wall force equals the momentum taken per step; Coulomb
// friction decelerates a sliding node at mu g exactly; a tied node follows the wall; a
// moving wall of mass M hitting resting masses one after the other conserves momentum
// to round-off; each hit is perfectly plastic, so after hitting masses m_1..m_k the wall
// moves at V0 prod M/(M + m_j) and mass k leaves with that velocity.
#include "contact/rigid_wall_plane.hpp"
#include "contact_test_support.hpp"

#include <gtest/gtest.h>

using namespace hbm::solver;
using namespace hbm::solver::contact;
using namespace hbm::solver::contact::testing;

namespace {
// Cycle with a constraint: stage 1, v += dt f/m, stage 2 (impose), x += dt v.
void cycle(NodalState& n, RigidWallPlane& w, double dt, double gz, StepContext& st) {
  w.gather_forces(st, n);
  for (std::size_t i = 0; i < n.n_nodes; ++i) {
    n.v.z[i] += dt * gz;
  }
  st.dt_next = dt;
  w.impose_velocities(st, n);
  for (std::size_t i = 0; i < n.n_nodes; ++i) {
    n.x.x[i] += dt * n.v.x[i];
    n.x.y[i] += dt * n.v.y[i];
    n.x.z[i] += dt * n.v.z[i];
  }
  st.dt_prev = dt;
  st.time += dt;
  ++st.cycle;
}
}  // namespace

TEST(ContactRigidWall, FixedWallStopsNodeWithoutPenetration) {
  NodalState n;
  const Index a = add_node(n, {0, 0, 0.35}, 2.0, {0.3, 0, -1.0});
  RigidWallPlaneParams p;
  p.id = 1;
  p.point = {0, 0, 0};
  p.normal = {0, 0, 1};
  RigidWallPlane w(p, {a});
  StepContext st;
  const double dt = 0.1;
  double fz_total = 0;
  for (int k = 0; k < 10; ++k) {
    cycle(n, w, dt, 0.0, st);
    EXPECT_GE(n.x.z[a], -1e-15);
    fz_total += w.normal_force().z * dt;
  }
  EXPECT_NEAR(n.x.z[a], 0.0, 1e-15);
  EXPECT_NEAR(n.v.z[a], 0.0, 1e-15);
  EXPECT_NEAR(n.v.x[a], 0.3, 1e-15);  // sliding wall: tangential velocity kept
  // Impulse on the wall = momentum removed: m (v0 - 0) downwards... the node had -2 of
  // z-momentum, it all went into the wall (dt_prev = 0 in the first cycle: dt^0 = dt/2).
  EXPECT_LT(fz_total, 0.0);
  EXPECT_NEAR(w.reaction_work(), -0.5 * 2.0 * 1.0, 1e-12);  // normal kinetic energy removed
}

TEST(ContactRigidWall, FrictionDeceleratesAtMuG) {
  NodalState n;
  const double g = 9.81e-3, mu = 0.25, dt = 1e-3, v0 = 0.1;
  const Index a = add_node(n, {0, 0, 0}, 1.5, {v0, 0, 0});
  RigidWallPlaneParams p;
  p.slide = 2;
  p.fric = mu;
  RigidWallPlane w(p, {a});
  StepContext st;
  for (int k = 0; k < 5000; ++k) cycle(n, w, dt, -g, st);
  EXPECT_NEAR((v0 - n.v.x[a]) / st.time, mu * g, 1e-9);
  EXPECT_NEAR(n.x.z[a], 0.0, 1e-15);
  // Steady state: wall normal force = weight, tangential = mu * weight (force ON the wall).
  EXPECT_NEAR(w.normal_force().z, -1.5 * g, 1e-12);
  EXPECT_NEAR(w.tangential_force().x, mu * 1.5 * g, 1e-12);
}

TEST(ContactRigidWall, TiedNodeFollowsTheWall) {
  NodalState n;
  const Index a = add_node(n, {0, 0, 0.05}, 1.0, {0.2, 0.1, -1.0});
  RigidWallPlaneParams p;
  p.slide = 1;
  RigidWallPlane w(p, {a});
  StepContext st;
  for (int k = 0; k < 5; ++k) cycle(n, w, 0.1, 0.0, st);
  EXPECT_EQ(n.v.x[a], 0.0);
  EXPECT_EQ(n.v.y[a], 0.0);
  cycle(n, w, 0.1, +5.0, st);  // pulled away: stays tied
  EXPECT_EQ(n.v.z[a], 0.0);
}

TEST(ContactRigidWall, MovingWallWithMassConservesMomentum) {
  NodalState n;
  const double M = 10.0, V0 = -2.0, dt = 1e-3;
  const Index wall = add_node(n, {0, 0, 1.0}, M, {0, 0.5, V0});
  std::vector<Index> sec;
  double m = 0;
  for (int i = 0; i < 5; ++i) {
    sec.push_back(add_node(n, {double(i), 0, -0.01 * i}, 0.3 + 0.1 * i));
    m += 0.3 + 0.1 * i;
  }
  RigidWallPlaneParams p;
  p.wall_node = wall;
  p.normal = {0, 0, -1};  // the wall pushes towards -z
  p.slide = 2;
  p.fric = 0.2;
  RigidWallPlane w(p, sec);
  const auto p0 = momentum(n);
  StepContext st;
  for (int k = 0; k < 2000; ++k) {
    cycle(n, w, dt, 0.0, st);
    const auto p1 = momentum(n);
    for (int d = 0; d < 3; ++d) ASSERT_NEAR(p1[d], p0[d], 1e-13 * M * std::abs(V0));
  }
  double V = V0;
  for (std::size_t k = 0; k < sec.size(); ++k) {
    V *= M / (M + n.mass[sec[k]]);
    EXPECT_NEAR(n.v.z[sec[k]], V, 1e-12);
    EXPECT_LE(n.x.z[sec[k]], n.x.z[wall] + 1e-12);  // never behind the wall
  }
  EXPECT_NEAR(n.v.z[wall], V, 1e-12);
  EXPECT_GT(m, 0);
}
