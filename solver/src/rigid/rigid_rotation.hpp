// SPDX-License-Identifier: GPL-3.0-or-later
// Rotation of a rigid body over one explicit step, in the principal frame.
//
// State: Q (rotation body principal frame -> global, columns = principal axes in global
// coordinates) and the spatial angular momentum L about the centre of mass. With the
// central-difference cycle the torque M_n at t_n gives the half-step momentum
//   L_{n+1/2} = L_{n-1/2} + dt M_n                      (kick)
// and the rotation is advanced by the exact flow of the free rigid body split into
// three rotations about the principal axes (Dullweber, Leimkuhler & McLachlan, "Symplectic
// splitting methods for rigid body molecular dynamics", J. Chem. Phys. 107 (1997) 5840;
// the free rigid body splitting of McLachlan 1993, also Touma & Wisdom 1994):
//   H = Pi_1^2/(2 I_1) + Pi_2^2/(2 I_2) + Pi_3^2/(2 I_3),  Pi = Q^T L (body momentum);
// the flow of the term i is a rotation about body axis i by the angle phi = t Pi_i / I_i
// (the exponential map of the body angular velocity of that term), applied as
//   Q <- Q R_i(phi),  Pi <- R_i(phi)^T Pi,
// which keeps Q Pi = L exactly. Strang composition 1(h/2) 2(h/2) 3(h) 2(h/2) 1(h/2):
// second order, symplectic, time reversible; |Pi| and L are conserved to round-off and
// the energy error stays bounded (no drift) at O((omega dt)^2).
#pragma once

#include <Eigen/Dense>

namespace hbm::solver::rigid {

// Rotation matrix about coordinate axis `axis` (0, 1, 2) by `angle` (rad).
Eigen::Matrix3d axis_rotation(int axis, double angle);

// Advance Q by the free rotation with spatial angular momentum L over dt.
// `inv_inertia` holds 1/I_i of the principal moments. Returns the new Q.
Eigen::Matrix3d free_rotation_step(const Eigen::Matrix3d& Q, const Eigen::Vector3d& L,
                                   const Eigen::Vector3d& inv_inertia, double dt);

// Body-frame angular momentum -> spatial angular velocity: omega = Q I^{-1} Q^T L.
inline Eigen::Vector3d angular_velocity(const Eigen::Matrix3d& Q, const Eigen::Vector3d& L,
                                        const Eigen::Vector3d& inv_inertia) {
  return Q * inv_inertia.cwiseProduct(Q.transpose() * L);
}

// Rotational kinetic energy 0.5 Pi . I^{-1} Pi.
inline double rotational_energy(const Eigen::Matrix3d& Q, const Eigen::Vector3d& L,
                                const Eigen::Vector3d& inv_inertia) {
  const Eigen::Vector3d Pi = Q.transpose() * L;
  return 0.5 * Pi.dot(inv_inertia.cwiseProduct(Pi));
}

// Nearest rotation to Q (polar decomposition via one Newton step Q <- (Q + Q^-T)/2),
// applied now and then to remove round-off drift from orthogonality.
Eigen::Matrix3d reorthonormalize(const Eigen::Matrix3d& Q);

}  // namespace hbm::solver::rigid
