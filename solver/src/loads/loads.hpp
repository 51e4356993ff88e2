// SPDX-License-Identifier: GPL-3.0-or-later
// Boundary conditions and loads of the starter deck:
//  - /BCS        FixedDofs constraint: listed components of v (and omega) set to 0.
//  - /IMPVEL     ImposedVelocity constraint: v_dir(t) = Fscale_y f(t / Ascale_x) for
//                Tstart <= t <= Tstop (Tstop 0 = never stops); v^{n+1/2} is the mean of
//                v_dir over [t^n, t^{n+1}] (exact integral), so the imposed displacement
//                is exact at every step; outside the window the DOF is free. Reaction work m dv (v^{n-1/2} + v^{n+1/2}) / 2.
//  - /GRAV       Gravity interaction: f = m g(t), g(t) = Fscale_y f(t / Ascale_x) along
//                Dir, on a node group; work trapezoidal 0.5 (f^{n-1} + f^n) v^{n-1/2} dt.
//  - /INIVEL/TRA initial velocity (applied once in the build phase).
// /FUNCT outside its abscissa range: end segments extended linearly (function_curve.hpp).
#pragma once

#include "hbm/solver/constraint.hpp"
#include "hbm/solver/function_curve.hpp"
#include "hbm/solver/interaction.hpp"
#include "hbm/solver/types.hpp"

#include <array>
#include <string>
#include <vector>

namespace hbm::solver {

class FixedDofs final : public Constraint {
 public:
  std::int64_t id = 0;
  std::array<bool, 6> fixed{};  // TX TY TZ RX RY RZ
  std::vector<Index> nodes;
  std::string_view kind() const override { return "/BCS"; }
  std::int64_t user_id() const override { return id; }
  void impose_velocities(const StepContext& step, NodalState& n) override;
};

class ImposedVelocity final : public Constraint {
 public:
  std::int64_t id = 0;
  const FunctionCurve* function = nullptr;
  int dof = 0;  // 0..2 translation X Y Z, 3..5 rotation
  double ascale = 1, fscale = 1, t_start = 0, t_stop = 0;
  std::vector<Index> nodes;
  std::string_view kind() const override { return "/IMPVEL"; }
  std::int64_t user_id() const override { return id; }
  void impose_velocities(const StepContext& step, NodalState& n) override;
  double reaction_work() const override { return work_; }

 private:
  double work_done_ = 0.0;  // through t^{n-1/2} ... completed steps
  double work_ = 0.0;       // reported through t^n
};

class Gravity final : public Interaction {
 public:
  std::int64_t id = 0;
  const FunctionCurve* function = nullptr;
  int dir = 2;
  double ascale = 1, fscale = 1;
  std::vector<Index> nodes;
  std::string_view kind() const override { return "/GRAV"; }
  std::int64_t user_id() const override { return id; }
  WorkKind work_kind() const override { return WorkKind::External; }
  void add_forces(const StepContext& step, NodalState& n) override;
  double work() const override { return work_; }

 private:
  std::vector<double> f_prev_;  // force of the previous cycle per listed node
  double work_ = 0.0;
};

}  // namespace hbm::solver
