// SPDX-License-Identifier: GPL-3.0-or-later
// Constraint: kinematic conditions applied around the velocity update, in three stages
// called over all constraints in registration order:
//   1. gather_forces      after assembly + interactions, before the nodal time step and
//                         the accelerations. Rigid bodies: add forces, moments and k_n of
//                         the secondary nodes onto the main node (moments of the forces
//                         about the main node included), zero them on the secondaries.
//   2. impose_velocities  after v^{n+1/2} = v^{n-1/2} + dt a^n: conditions on independent
//                         nodes. Rigid bodies integrate the main node rotation (Euler
//                         equations, full inertia tensor) and overwrite its omega; then
//                         /BCS zero components, /IMPVEL sets them, rigid walls remove
//                         penetrating normal velocity.
//   3. impose_dependent   secondary velocities from their main node: v_s = v_m + w x r.
// Nodes with NodalState::is_secondary = 1 are skipped by the nodal time step, mass
// scaling, the velocity update and the total mass M0.
#pragma once

#include "hbm/solver/nodal_state.hpp"
#include "hbm/solver/step_context.hpp"
#include "hbm/solver/th_probe.hpp"

#include <cstdint>
#include <string_view>

namespace hbm::solver {

class Constraint : public ThSource {
 public:
  ~Constraint() override = default;
  virtual std::string_view kind() const = 0;  // deck keyword, e.g. "/RBODY", "/BCS"
  virtual std::int64_t user_id() const = 0;

  virtual void gather_forces(const StepContext& step, NodalState& nodes) {}
  virtual void impose_velocities(const StepContext& step, NodalState& nodes) {}
  virtual void impose_dependent(const StepContext& step, NodalState& nodes) {}

  // Cumulative work of the reaction forces through t^n, added to W_ext [energy]. A
  // velocity change dv imposed on mass m at step dt is a reaction m dv / dt; its work
  // increment is (m dv / dt) . v_mid dt with v_mid the average of the half-step
  // velocities. Zero for fixed /BCS.
  virtual double reaction_work() const { return 0.0; }
};

}  // namespace hbm::solver
