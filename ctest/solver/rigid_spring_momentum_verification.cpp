// SPDX-License-Identifier: GPL-3.0-or-later
// A rigid body hit by a free mass through a linear spring (central force between the
// mass and one corner node of the body, off the centre so the body starts to spin), in
// the central-difference cycle (springs_mini_cycle.hpp), dt = 1.5e-3 ms:
//  - linear momentum m v + M v_c is conserved to round-off (1e-12 relative);
//  - angular momentum about the origin, m x^n x v^{n+1/2} + M x_c^n x v_c^{n+1/2} +
//    L^{n+1/2}, is an exact invariant of the kick-drift scheme for a central force and
//    is conserved to round-off (1e-12);
//  - energy (kinetic of the mass and of the body + spring energy) stays within 1e-4.
// The spring here is a minimal linear element group (the TYPE4 kernel is tested in
// springs_*; the deck-level test couples the real one).
#include "springs_mini_cycle.hpp"

#include "rigid/rigid_body.hpp"
#include "rigid/rigid_rotation.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace hbm::solver;
using hbm::solver::rigid::RigidBody;
using hbm::solver::testing::MiniCycle;

namespace {

class LinearSpring final : public ElementGroup {
 public:
  double k = 0, l0 = 0, energy_now = 0;
  std::string_view formulation() const override { return "test linear spring"; }
  void compute_forces(const StepContext&, const NodalState& n, GroupStepResult&) override {
    const auto a = static_cast<std::size_t>(connectivity[0]), b = static_cast<std::size_t>(connectivity[1]);
    const Eigen::Vector3d d(n.x.x[b] - n.x.x[a], n.x.y[b] - n.x.y[a], n.x.z[b] - n.x.z[a]);
    const double l = d.norm(), f = k * (l - l0);
    energy_now = 0.5 * k * (l - l0) * (l - l0);
    const Eigen::Vector3d fa = f * d / l;
    slot_force.x[0] = fa.x(); slot_force.y[0] = fa.y(); slot_force.z[0] = fa.z();
    slot_force.x[1] = -fa.x(); slot_force.y[1] = -fa.y(); slot_force.z[1] = -fa.z();
    slot_stiffness[0] = slot_stiffness[1] = k;
  }
};

Eigen::Vector3d at(const Vec3Soa& a, std::size_t i) { return {a.x[i], a.y[i], a.z[i]}; }

}  // namespace

TEST(RigidSpring, ImpactConservesMomentumAndAngularMomentum) {
  MiniCycle c;
  // Body: 2x2x2 nodes of 50 g, cube of 40 mm; node 8 = main; node 9 = free mass 0.2 kg.
  c.init_nodes(10);
  RigidBody body;
  for (int i = 0; i < 8; ++i) {
    c.nodes.x0.x[i] = c.nodes.x.x[i] = 40.0 * (i & 1);
    c.nodes.x0.y[i] = c.nodes.x.y[i] = 40.0 * ((i >> 1) & 1);
    c.nodes.x0.z[i] = c.nodes.x.z[i] = 40.0 * ((i >> 2) & 1);
    c.nodes.mass0[i] = 0.05;
    body.secondary.push_back(i);
  }
  body.main = 8;
  body.id = 3;
  c.nodes.x0.x[9] = c.nodes.x.x[9] = 100.0;  // free mass at (100, 40, 0), spring to node 3 (40, 40, 0)
  c.nodes.x0.y[9] = c.nodes.x.y[9] = 40.0;
  c.nodes.mass0[9] = 0.2;
  c.nodes.v.x[9] = -5.0;  // 5 m/s towards the body
  c.nodes.v.y[9] = 1.0;
  body.assemble(c.nodes, 0.0, Eigen::Matrix3d::Zero(), true, false);
  c.finish_build();
  LinearSpring spring;
  spring.nodes_per_element = 2;
  spring.n_elements = 1;
  spring.connectivity = {3, 9};
  spring.element_id = {1};
  spring.k = 2.0;  // kN/mm
  spring.l0 = 60.0;
  spring.allocate_slots();
  c.groups.push_back(&spring);
  c.constraints.push_back(&body);

  auto momentum = [&] {
    return Eigen::Vector3d(c.nodes.mass[9] * at(c.nodes.v, 9) + c.nodes.mass[8] * at(c.nodes.v, 8));
  };
  // Angular momentum about the origin with positions at t^n (before the position update).
  auto angular = [&] {
    const double dt = c.dt;
    const Eigen::Vector3d x9 = at(c.nodes.x, 9) - dt * at(c.nodes.v, 9);
    const Eigen::Vector3d x8 = at(c.nodes.x, 8) - dt * at(c.nodes.v, 8);
    return Eigen::Vector3d(c.nodes.mass[9] * x9.cross(at(c.nodes.v, 9)) +
                           c.nodes.mass[8] * x8.cross(at(c.nodes.v, 8)) + body.L);
  };
  // Energy at t^n: velocities and momentum averaged over the two half steps, the body
  // orientation at t^n, the spring energy at x^n.
  Eigen::Vector3d v9_prev, v8_prev, L_prev;
  Eigen::Matrix3d Q_prev;
  auto step_and_energy = [&] {
    v9_prev = at(c.nodes.v, 9); v8_prev = at(c.nodes.v, 8); L_prev = body.L; Q_prev = body.Q;
    c.step();
    const Eigen::Vector3d v9 = 0.5 * (v9_prev + at(c.nodes.v, 9));
    const Eigen::Vector3d v8 = 0.5 * (v8_prev + at(c.nodes.v, 8));
    const Eigen::Vector3d Lm = 0.5 * (L_prev + body.L);
    return 0.5 * c.nodes.mass[9] * v9.squaredNorm() + 0.5 * c.nodes.mass[8] * v8.squaredNorm() +
           rigid::rotational_energy(Q_prev, Lm, body.principal.cwiseInverse()) + spring.energy_now;
  };
  step_and_energy();
  const Eigen::Vector3d P0 = momentum(), J0 = angular();
  const double E0 = step_and_energy();
  double max_p = 0, max_j = 0, max_e = 0;
  for (int i = 0; i < 40000; ++i) {  // 60 ms: several spring oscillations, body spins
    const double e = step_and_energy();
    max_p = std::max(max_p, (momentum() - P0).norm() / P0.norm());
    max_j = std::max(max_j, (angular() - J0).norm() / J0.norm());
    max_e = std::max(max_e, std::abs(e - E0) / E0);
  }
  std::printf("rigid body + spring: max |dP|/|P| %.2e, max |dJ|/|J| %.2e, max |dE|/E %.2e, "
              "body spin %.4f rad/ms\n", max_p, max_j, max_e, body.omega().norm());
  EXPECT_GT(body.omega().norm(), 1e-3);  // the impact did make the body spin
  EXPECT_LT(max_p, 1e-12);
  EXPECT_LT(max_j, 1e-12);
  EXPECT_LT(max_e, 1e-4);
}
