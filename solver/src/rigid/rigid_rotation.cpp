// SPDX-License-Identifier: GPL-3.0-or-later
// Free rigid body rotation by the symplectic splitting of Dullweber, Leimkuhler and
// McLachlan (1997): exact rotations about the principal axes, Strang composition.
#include "rigid/rigid_rotation.hpp"

#include <cmath>

namespace hbm::solver::rigid {

Eigen::Matrix3d axis_rotation(int axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  R(a, a) = c; R(a, b) = -s;
  R(b, a) = s; R(b, b) = c;
  return R;
}

namespace {
// Flow of H_i = Pi_i^2 / (2 I_i) over t: rotate about body axis i by t Pi_i / I_i.
inline void sub_flow(Eigen::Matrix3d& Q, Eigen::Vector3d& Pi, int i, double inv_I, double t) {
  const Eigen::Matrix3d R = axis_rotation(i, t * Pi(i) * inv_I);
  Q = Q * R;
  Pi = R.transpose() * Pi;
}
}  // namespace

Eigen::Matrix3d free_rotation_step(const Eigen::Matrix3d& Q0, const Eigen::Vector3d& L,
                                   const Eigen::Vector3d& inv_inertia, double dt) {
  Eigen::Matrix3d Q = Q0;
  Eigen::Vector3d Pi = Q.transpose() * L;
  const double h = 0.5 * dt;
  sub_flow(Q, Pi, 0, inv_inertia(0), h);
  sub_flow(Q, Pi, 1, inv_inertia(1), h);
  sub_flow(Q, Pi, 2, inv_inertia(2), dt);
  sub_flow(Q, Pi, 1, inv_inertia(1), h);
  sub_flow(Q, Pi, 0, inv_inertia(0), h);
  return Q;
}

Eigen::Matrix3d reorthonormalize(const Eigen::Matrix3d& Q) {
  return 0.5 * (Q + Q.inverse().transpose());
}

}  // namespace hbm::solver::rigid
