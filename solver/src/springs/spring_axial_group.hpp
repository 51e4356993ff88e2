// SPDX-License-Identifier: GPL-3.0-or-later
// /PROP/TYPE4 springs: one axial DOF between two nodes. Elongation delta = l - l0, force
// F(delta, delta_dot, history) from the Radioss spring law (spring_dof_law.hpp), acting
// along the current axis e = (x2 - x1) / l: node 1 gets +F e, node 2 gets -F e (tension
// F > 0 pulls the nodes together). The rate is the backward difference
// (delta^n - delta^{n-1}) / dt^{n-1/2}, i.e. e . (v2 - v1) at the half step for a
// straight spring. A spring shortened to zero length keeps its last axis.
#pragma once

#include "springs/spring_group.hpp"

namespace hbm::solver::springs {

class SpringAxialGroup final : public SpringGroup {
 public:
  std::vector<Eigen::Vector3d> axis;  // last non-degenerate axis per element

  std::string_view formulation() const override { return "spring TYPE4 axial"; }
  double relative_element_cost() const override { return 0.7; }  // 100 ns (bench-model)
  void compute_forces(const StepContext& step, const NodalState& nodes,
                      GroupStepResult& result) override;
  void init_axes(const NodalState& nodes);
};

}  // namespace hbm::solver::springs
