// SPDX-License-Identifier: GPL-3.0-or-later
// Test harness for the spring and rigid-body kernels: the central-difference cycle of
// docs/cycle.md in a few lines (element forces -> slot assembly -> constraints gather ->
// velocity update -> constraints impose -> energies -> positions), with a fixed step and
// no mass scaling, on the engine's own NodalState / ElementGroup / Constraint types.
// Used by springs_*_verification.cpp and rigid_*_verification.cpp to check the kernels
// before (and independently of) the full engine.
#pragma once

#include "hbm/solver/constraint.hpp"
#include "hbm/solver/element_group.hpp"
#include "hbm/solver/nodal_state.hpp"

#include <memory>
#include <vector>

namespace hbm::solver::testing {

struct MiniCycle {
  NodalState nodes;
  std::vector<ElementGroup*> groups;
  std::vector<Constraint*> constraints;
  double dt = 1.5e-3;
  double time = 0;
  std::int64_t cycle = 0;
  double dt_prev = 0;
  double kinetic = 0;      // at t^n (mean of half-step velocities), translation + rotation
  double momentum[3] = {0, 0, 0};  // sum m v^{n+1/2} over non-secondary nodes
  double half_prev = -1;           // half-step kinetic energy of the previous cycle

  void init_nodes(std::size_t n) {
    nodes.resize(n);
  }
  void finish_build() {
    nodes.mass = nodes.mass0;
    nodes.inertia = nodes.inertia0;
  }

  // One cycle n -> n+1.
  void step() {
    const std::size_t n = nodes.n_nodes;
    StepContext sc{cycle, time, dt_prev, dt};
    for (std::size_t i = 0; i < n; ++i) {
      nodes.force.x[i] = nodes.force.y[i] = nodes.force.z[i] = 0;
      nodes.moment.x[i] = nodes.moment.y[i] = nodes.moment.z[i] = 0;
      nodes.stiffness[i] = nodes.rot_stiffness[i] = 0;
    }
    for (ElementGroup* g : groups) {
      GroupStepResult r;
      g->compute_forces(sc, nodes, r);
      for (std::size_t s = 0; s < g->connectivity.size(); ++s) {
        const auto i = static_cast<std::size_t>(g->connectivity[s]);
        nodes.force.x[i] += g->slot_force.x[s];
        nodes.force.y[i] += g->slot_force.y[s];
        nodes.force.z[i] += g->slot_force.z[s];
        nodes.stiffness[i] += g->slot_stiffness[s];
        if (g->has_rotation_slots()) {
          nodes.moment.x[i] += g->slot_moment.x[s];
          nodes.moment.y[i] += g->slot_moment.y[s];
          nodes.moment.z[i] += g->slot_moment.z[s];
          nodes.rot_stiffness[i] += g->slot_rot_stiffness[s];
        }
      }
    }
    for (Constraint* c : constraints) c->gather_forces(sc, nodes);
    const double dt_n = 0.5 * (dt_prev + dt);
    for (std::size_t i = 0; i < n; ++i) {
      if (nodes.is_secondary[i] || nodes.mass[i] <= 0) continue;
      nodes.v.x[i] += dt_n * nodes.force.x[i] / nodes.mass[i];
      nodes.v.y[i] += dt_n * nodes.force.y[i] / nodes.mass[i];
      nodes.v.z[i] += dt_n * nodes.force.z[i] / nodes.mass[i];
      if (nodes.has_rotation[i] && nodes.inertia[i] > 0) {
        nodes.omega.x[i] += dt_n * nodes.moment.x[i] / nodes.inertia[i];
        nodes.omega.y[i] += dt_n * nodes.moment.y[i] / nodes.inertia[i];
        nodes.omega.z[i] += dt_n * nodes.moment.z[i] / nodes.inertia[i];
      }
    }
    for (Constraint* c : constraints) c->impose_velocities(sc, nodes);
    for (Constraint* c : constraints) c->impose_dependent(sc, nodes);
    // Kinetic energy at t^n as the core accounts it (docs/cycle.md step 8): the mean of
    // the half-step energies 0.5 m |v^{n-1/2}|^2 and 0.5 m |v^{n+1/2}|^2 (+ rotation).
    double half = 0;
    momentum[0] = momentum[1] = momentum[2] = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (nodes.is_secondary[i]) continue;
      const double vx = nodes.v.x[i], vy = nodes.v.y[i], vz = nodes.v.z[i];
      half += 0.5 * nodes.mass[i] * (vx * vx + vy * vy + vz * vz);
      if (nodes.has_rotation[i]) {
        const double wx = nodes.omega.x[i], wy = nodes.omega.y[i], wz = nodes.omega.z[i];
        half += 0.5 * nodes.inertia[i] * (wx * wx + wy * wy + wz * wz);
      }
      momentum[0] += nodes.mass[i] * vx;
      momentum[1] += nodes.mass[i] * vy;
      momentum[2] += nodes.mass[i] * vz;
    }
    kinetic = 0.5 * ((half_prev < 0 ? half : half_prev) + half);
    half_prev = half;
    for (std::size_t i = 0; i < n; ++i) {
      nodes.x.x[i] += dt * nodes.v.x[i];
      nodes.x.y[i] += dt * nodes.v.y[i];
      nodes.x.z[i] += dt * nodes.v.z[i];
    }
    time += dt;
    dt_prev = dt;
    ++cycle;
  }
};

}  // namespace hbm::solver::testing
