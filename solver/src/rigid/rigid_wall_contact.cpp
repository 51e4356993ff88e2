// SPDX-License-Identifier: GPL-3.0-or-later
// Plastic contact of a rigid body with a kinematic wall at several of its secondary
// nodes at once (WallContactBody, wall_contact_body.hpp).
//
// Unknowns: the wall impulse p_k on each contact point k, applied to the body at the
// arm a_k = Q^{n+1} r_k from the centre. Linearised over the step, the position of point
// k at t^{n+1} moves by
//   dx_k = dt (P / M + (J^{-1} H) x a_k),   P = sum p_j,  H = sum a_j x p_j,
// i.e. dx_k = sum_j K_kj p_j with the point compliance K_kk = dt (I / M - [a_k]x J^{-1} [a_k]x)
// (J^{-1} spatial, from the principal moments in use). The conditions are those of the
// nodal wall (rigid_wall_plane.hpp) per point: n . x_k^{n+1} >= floor_k with p_k . n >= 0
// and complementarity (no adhesion), Coulomb |p_t| <= fric p_n on the tangential
// displacement of the step, or x_k^{n+1} = target_k for tied points. The problem is
// solved by projected Gauss-Seidel over the points (the classical scheme for rigid-body
// contact LCPs: Moreau 1988, "Unilateral contact and dry friction in finite freedom
// dynamics"; Jean 1999), the impulses are applied to v_m and L, the rotation over the
// step is recomputed with the exact free flow, and the exact positions are checked again
// (outer loop: points that became active or the linearisation error).
//
// Work of the impulses on the body (into the wall's reaction work, W_ext), the body form
// of the nodal wall's m dv . (v^{n-1/2} + v^{n+1/2}) / 2:
//   W = P . (v^{n-1/2} + v^{n+1/2}) / 2 + H . (omega^{n-1/2} + omega^{n+1/2}) / 2.
// A body resting on the wall (v^{n-1/2} = v^{n+1/2} = 0) takes impulses that do no work;
// a body brought to rest loses exactly its kinetic energy. The impulse acts like a force
// P / dt^n at t^n, so W is split as the engine splits the work of a force over the two
// half steps: the main node's acceleration a^n gets P / (M dt^n) (the engine's E_kin(t^n)
// then holds 0.5 P . v^{n-1/2}), the translational work is P . v^{n-1/2} / 2 at t^n and
// P . v^{n+1/2} / 2 at t^{n+1}; the rotational energy being the mean of the half steps,
// its work is counted half at t^n, half at t^{n+1}. Without the split a whole body
// stopping in one step shows its full kinetic energy as a one-step energy error.
#include "rigid/rigid_body.hpp"
#include "rigid/nodal_vec3.hpp"

#include <algorithm>
#include <cmath>

namespace hbm::solver::rigid {

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d S;
  S << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return S;
}

constexpr int kMaxOuter = 8;     // exact re-evaluations of the positions
constexpr int kMaxSweeps = 500;  // Gauss-Seidel sweeps per linearised problem

}  // namespace

Eigen::Vector3d RigidBody::predicted_position(const NodalState& nodes, std::size_t j, double dt) const {
  return load(nodes.x, main) + dt * load(nodes.v, main) + Q_next_ * r_body[j];
}

WallContactWork RigidBody::resolve_wall_contacts(const StepContext& step, NodalState& nodes,
                                                 std::span<WallContactPoint> pts) {
  const double dt = step.dt_next;
  const std::size_t np = pts.size();
  if (!(dt > 0) || np == 0) return {};
  const double M = nodes.mass[static_cast<std::size_t>(main)];  // incl. added mass
  const Eigen::Vector3d xm = load(nodes.x, main);
  const Eigen::Vector3d v_old = load(nodes.v, main), L_old = L;
  const Eigen::Matrix3d Jinv = Q * inv_inertia_used_.asDiagonal() * Q.transpose();
  contact_active_.assign(np, 0);
  contact_arm_.resize(np);
  contact_x_.resize(np);
  for (WallContactPoint& p : pts) {
    p.impulse.setZero();
    p.touched = false;
  }
  // Length scale of the position tolerance: the largest arm and the step's travel.
  double reach = dt * v_old.norm();
  for (std::size_t k = 0; k < np; ++k) reach = std::max(reach, r_body[pts[k].secondary].norm());
  const double tol_x = 1e-12 * (reach + 1.0);

  for (int outer = 0; outer < kMaxOuter; ++outer) {
    // Exact positions at t^{n+1} with the current motion; activate violated points.
    const Eigen::Vector3d vm = load(nodes.v, main);
    bool violated = false;
    for (std::size_t k = 0; k < np; ++k) {
      const WallContactPoint& p = pts[k];
      contact_arm_[k] = Q_next_ * r_body[p.secondary];
      contact_x_[k] = xm + dt * vm + contact_arm_[k];
      const double gap = p.tied ? -(contact_x_[k] - p.target).norm() : p.normal.dot(contact_x_[k]) - p.floor;
      if (gap < -tol_x) {
        violated = true;
        contact_active_[k] = 1;
      }
    }
    if (!violated) break;
    // Projected Gauss-Seidel on the linearised problem; increments of P and H.
    Eigen::Vector3d dP = Eigen::Vector3d::Zero(), dH = Eigen::Vector3d::Zero();
    double scale = 0;
    for (std::size_t k = 0; k < np; ++k)
      if (contact_active_[k]) scale = std::max(scale, M * (contact_x_[k] - load(nodes.x, secondary[pts[k].secondary])).norm() / dt);
    scale = std::max(scale, 1e-300);
    for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
      double change = 0;
      for (std::size_t k = 0; k < np; ++k) {
        if (!contact_active_[k]) continue;
        WallContactPoint& p = pts[k];
        const Eigen::Vector3d& a = contact_arm_[k];
        const Eigen::Matrix3d S = skew(a);
        const Eigen::Matrix3d K = dt * (Eigen::Matrix3d::Identity() / M - S * Jinv * S);
        const Eigen::Vector3d u = contact_x_[k] + dt * (dP / M + (Jinv * dH).cross(a));
        Eigen::Vector3d delta;
        if (p.tied) {
          delta = K.ldlt().solve(p.target - u);
        } else {
          const Eigen::Vector3d& n = p.normal;
          const double pn = p.impulse.dot(n);
          const double pn_new = std::max(0.0, pn - (n.dot(u) - p.floor) / n.dot(K * n));
          delta = (pn_new - pn) * n;
          if (p.fric > 0) {
            // Tangential displacement of the step after the normal update, removed by a
            // tangential impulse within the Coulomb disc fric * p_n.
            const Eigen::Vector3d x_n = load(nodes.x, secondary[p.secondary]);
            const Eigen::Vector3d s = u + K * delta - x_n;
            const Eigen::Vector3d st = s - n.dot(s) * n;
            const Eigen::Vector3d pt = p.impulse - pn * n;
            Eigen::Vector3d want = K.ldlt().solve(-st);
            want -= n.dot(want) * n;
            Eigen::Vector3d pt_new = pt + want;
            const double cap = std::isinf(p.fric) ? p.fric : p.fric * pn_new, mag = pt_new.norm();  // inf: stick (Slide 1)
            if (mag > cap) pt_new *= cap / mag;
            delta += pt_new - pt;
          }
        }
        p.impulse += delta;
        dP += delta;
        dH += a.cross(delta);
        change = std::max(change, delta.norm());
      }
      if (change <= 1e-13 * scale) break;
    }
    // Apply to the body: translation of the main node, angular momentum, rotation.
    store(nodes.v, main, load(nodes.v, main) + dP / M);
    L += dH;
    predict_rotation(nodes, dt);
  }
  const Eigen::Vector3d v_new = load(nodes.v, main);
  const Eigen::Vector3d P = M * (v_new - v_old), H = L - L_old;
  for (WallContactPoint& p : pts) p.touched = p.impulse.squaredNorm() > 0;
  const double dt_n = 0.5 * (step.dt_prev + step.dt_next);
  if (dt_n > 0) store(nodes.a, main, load(nodes.a, main) + P / (M * dt_n));
  // velocity_ / omega_ still hold the half step n-1/2 (updated in impose_dependent).
  const double rot = 0.25 * H.dot(omega_ + omega_written_);
  return {0.5 * P.dot(velocity_) + rot, 0.5 * P.dot(v_new) + rot};
}

}  // namespace hbm::solver::rigid
