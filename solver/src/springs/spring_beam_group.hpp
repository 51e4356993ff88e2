// SPDX-License-Identifier: GPL-3.0-or-later
// /PROP/TYPE13 beam-type springs: six DOFs in a corotational frame that follows the two
// nodes. Each element tracks the rotation R_a, R_b of its nodes (R <- exp(omega dt) R,
// exponential map of the nodal angular velocity) and builds its frame from the mean
// rotation and the initial frame E0 (x along the initial chord, y towards the orientation
// node n3 when given, else the global axis least aligned with x, made normal to x):
//   psi   = log(R_a^T R_b)                     relative rotation (body of node a)
//   E     = R_a exp(psi / 2) E0                frame of the mean rotation
//   delta = E^T (x_b - x_a) - (l0, 0, 0)       axial and two shear displacements
//   theta = E0^T psi                           torsion and two bending rotations
// F_i = law_i(delta_i), M_i = law_{3+i}(theta_i); f = E F acts +f on a and -f on b;
// m = E M acts +m on a and -m on b; the shear couple is balanced by adding
// (1/2) (x_b - x_a) x f to both nodal moments, which is the work-conjugate moment of
// delta with respect to the rotation of E (half from each node). The element is
// objective (rigid motions give no force) and conserves momentum and angular momentum.
#pragma once

#include "springs/spring_group.hpp"

#include <Eigen/Geometry>

namespace hbm::solver::springs {

class SpringBeamGroup final : public SpringGroup {
 public:
  std::vector<Eigen::Matrix3d> frame0;     // E0 per element (columns x, y, z)
  std::vector<Eigen::Quaterniond> rot_a;   // rotation of node a since t = 0
  std::vector<Eigen::Quaterniond> rot_b;   // rotation of node b since t = 0
  std::vector<Index> orientation_node;     // optional n3 per element (y axis towards it)

  std::string_view formulation() const override { return "spring TYPE13 beam-type"; }
  double relative_element_cost() const override { return 2.6; }  // as TYPE8 (estimate)
  void compute_forces(const StepContext& step, const NodalState& nodes,
                      GroupStepResult& result) override;
  // Initial frames from x0 and the property skew (call after length0 is set).
  void init_frames(const NodalState& nodes);
};

// Quaternion of the rotation vector w (exponential map).
Eigen::Quaterniond quat_exp(const Eigen::Vector3d& w);
// Rotation vector of a unit quaternion (logarithm), angle in [0, pi].
Eigen::Vector3d quat_log(const Eigen::Quaterniond& q);

}  // namespace hbm::solver::springs
