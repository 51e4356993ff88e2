// SPDX-License-Identifier: GPL-3.0-or-later
// /PROP/TYPE8 general springs: six uncoupled DOFs between two nodes, measured in a fixed
// frame (the property's skew, or the global axes). With e_i the frame axes:
//   translations  delta_i = ((x2 - x1) - (X2 - X1)) . e_i           (i = X, Y, Z)
//   rotations     theta_i += ((omega2 - omega1) . e_i) dt^{n-1/2}   (i = RX, RY, RZ)
// Each DOF has its own Radioss law (spring_dof_law.hpp). Forces f = sum F_i e_i and
// moments m = sum M_i e_i act +f, +m on node 1 and -f, -m on node 2. As in Radioss the
// force pair is not moment-balanced when the nodes are apart; TYPE8 is meant for
// coincident or close nodes (use TYPE13 otherwise).
#pragma once

#include "springs/spring_group.hpp"

namespace hbm::solver::springs {

class SpringGeneralGroup final : public SpringGroup {
 public:
  bool rotational = true;                    // false when all rotational DOFs are empty
  std::vector<Eigen::Vector3d> rotation;     // accumulated relative rotation, frame axes [rad]

  std::string_view formulation() const override { return "spring TYPE8 general 6-DOF"; }
  double relative_element_cost() const override { return 2.6; }  // 377 ns (bench-model)
  void compute_forces(const StepContext& step, const NodalState& nodes,
                      GroupStepResult& result) override;
};

}  // namespace hbm::solver::springs
