// SPDX-License-Identifier: GPL-3.0-or-later
// Interaction: anything that adds forces to nodes each cycle and is not an element group
// (contact interfaces, rigid walls as penalty, gravity, concentrated loads). Called on
// one thread, in registration order, after element assembly and before constraints;
// an interaction may parallelise inside only if its result is independent of the thread
// count. It writes nodes.force (and moment), and adds its stiffness to nodes.stiffness
// (contact penalty k must enter the nodal time step).
#pragma once

#include "hbm/solver/nodal_state.hpp"
#include "hbm/solver/step_context.hpp"
#include "hbm/solver/th_probe.hpp"

#include <cstdint>
#include <limits>
#include <string_view>

namespace hbm::solver {

// Where an interaction's work goes in the energy balance
//   E_kin + E_int + E_hg + E_contact = E_0 + W_ext.
enum class WorkKind : std::uint8_t {
  Contact,   // E_contact += -(work of its forces on the nodes): stored + friction
  External,  // W_ext += work of its forces on the nodes (gravity, loads, walls)
};

class Interaction : public ThSource {
 public:
  ~Interaction() override = default;
  virtual std::string_view kind() const = 0;  // deck keyword, e.g. "/INTER/TYPE7"
  virtual std::int64_t user_id() const = 0;
  virtual WorkKind work_kind() const = 0;

  // Add forces at t^n (x^n, v^{n-1/2}) into nodes.force / nodes.moment, and the penalty
  // stiffness into nodes.stiffness. External loads also add into nodes.force_ext.
  virtual void add_forces(const StepContext& step, NodalState& nodes) = 0;

  // Cumulative work of its forces on the nodes through t^n [energy]. Recommended
  // update, trapezoidal: W += 0.5 (f^{n-1} + f^n) . v^{n-1/2} dt_prev.
  virtual double work() const = 0;

  // Smallest stable step it imposes without /DT/NODA/CST (infinity if none) [time].
  virtual double critical_step() const { return std::numeric_limits<double>::infinity(); }
};

}  // namespace hbm::solver
