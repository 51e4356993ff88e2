// SPDX-License-Identifier: GPL-3.0-or-later
// Nodal state of the explicit engine, struct of arrays, translational and rotational
// degrees of freedom. Central difference: positions at integer steps t^n, velocities at
// half steps t^{n-1/2} / t^{n+1/2}, forces and moments at t^n.
//
// Sign convention: `force` and `moment` hold the total force ON the node (external minus
// internal). Element groups write the force their element exerts on its nodes (i.e.
// -f_int) into their slot buffers; the core sums buffers into these arrays.
//
// Units are the deck's work units (default mm, ms, kg -> kN, GPa, J).
#pragma once

#include "hbm/solver/types.hpp"

#include <cstdint>
#include <vector>

namespace hbm::solver {

struct NodalState {
  std::size_t n_nodes = 0;
  std::vector<std::int64_t> user_id;   // deck id of each node (outputs, messages)

  // --- translational DOFs -------------------------------------------------------------
  Vec3Soa x0;             // initial position [length]
  Vec3Soa x;              // position x^n [length]
  Vec3Soa v;              // velocity: v^{n-1/2} during force computation, v^{n+1/2} after
                          //   the velocity update [length/time]
  Vec3Soa a;              // acceleration a^n = f^n / m [length/time^2]
  Vec3Soa force;          // total force f^n on the node [force]
  Vec3Soa contact_force;  // force of contacts and rigid walls on the node this cycle
                          //   (output only: VTK "contact_force") [force]
  Vec3Soa force_ext;      // external part of f^n (gravity, interactions report theirs
                          //   separately); used for the external work [force]
  std::vector<double> mass0;      // physical lumped mass M0 (build phase) [mass]
  std::vector<double> mass;       // mass used this cycle: mass0 + added_mass [mass]
  std::vector<double> added_mass; // cumulative mass added by /DT/NODA/CST [mass]
  std::vector<double> stiffness;  // assembled nodal stiffness k_n this cycle [force/length]
  // 1 for rigid-body secondary nodes: their velocity is imposed by the rigid body, they
  // are skipped by the nodal time step, mass scaling and the total mass M0 (their mass
  // is carried by the main node's mass0).
  std::vector<std::uint8_t> is_secondary;

  // --- rotational DOFs (only nodes with has_rotation = 1 are integrated) --------------
  std::vector<std::uint8_t> has_rotation;  // set in the build phase by springs / rigid bodies
  Vec3Soa omega;          // angular velocity at half steps (like v) [rad/time]
  Vec3Soa moment;         // total moment at t^n [force*length]
  std::vector<double> inertia0;       // physical scalar (isotropic) nodal inertia [mass*length^2]
  std::vector<double> inertia;        // inertia used this cycle (incl. added) [mass*length^2]
  std::vector<double> rot_stiffness;  // assembled rotational stiffness k_r [force*length/rad]

  void resize(std::size_t n) {
    n_nodes = n;
    user_id.assign(n, 0);
    for (Vec3Soa* f : {&x0, &x, &v, &a, &force, &contact_force, &force_ext, &omega, &moment}) f->resize(n);
    for (auto* f : {&mass0, &mass, &added_mass, &stiffness, &inertia0, &inertia, &rot_stiffness})
      f->assign(n, 0.0);
    has_rotation.assign(n, 0);
    is_secondary.assign(n, 0);
  }
};

}  // namespace hbm::solver
