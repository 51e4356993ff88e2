// SPDX-License-Identifier: GPL-3.0-or-later
// /PROP/TYPE13 beam-type spring kernel (corotational, see spring_beam_group.hpp).
#include "springs/spring_beam_group.hpp"

#include "core/parallel_loop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hbm::solver::springs {

Eigen::Quaterniond quat_exp(const Eigen::Vector3d& w) {
  const double a = w.norm();
  if (a < 1e-300) return Eigen::Quaterniond::Identity();
  const double h = 0.5 * a;
  const double s = (a < 1e-8) ? 0.5 : std::sin(h) / a;  // sin(a/2)/a -> 1/2
  return Eigen::Quaterniond(std::cos(h), s * w.x(), s * w.y(), s * w.z());
}

Eigen::Vector3d quat_log(const Eigen::Quaterniond& q0) {
  Eigen::Quaterniond q = q0;
  if (q.w() < 0) q.coeffs() = -q.coeffs();  // shortest rotation
  const Eigen::Vector3d v = q.vec();
  const double s = v.norm();
  if (s < 1e-300) return Eigen::Vector3d::Zero();
  const double angle = 2.0 * std::atan2(s, q.w());
  return (angle / s) * v;
}

void SpringBeamGroup::init_frames(const NodalState& nodes) {
  frame0.assign(n_elements, Eigen::Matrix3d::Identity());
  rot_a.assign(n_elements, Eigen::Quaterniond::Identity());
  rot_b.assign(n_elements, Eigen::Quaterniond::Identity());
  for (std::size_t e = 0; e < n_elements; ++e) {
    const auto a = static_cast<std::size_t>(connectivity[2 * e]);
    const auto b = static_cast<std::size_t>(connectivity[2 * e + 1]);
    const Eigen::Vector3d d(nodes.x0.x[b] - nodes.x0.x[a], nodes.x0.y[b] - nodes.x0.y[a],
                            nodes.x0.z[b] - nodes.x0.z[a]);
    Eigen::Vector3d ex = prop.skew.col(0);
    if (d.norm() > 0) ex = d / d.norm();
    Eigen::Vector3d ey = prop.skew.col(1);
    const Index n3 = e < orientation_node.size() ? orientation_node[e] : kNoIndex;
    if (n3 != kNoIndex) {
      const auto k3 = static_cast<std::size_t>(n3);
      const Eigen::Vector3d d3(nodes.x0.x[k3] - nodes.x0.x[a], nodes.x0.y[k3] - nodes.x0.y[a],
                               nodes.x0.z[k3] - nodes.x0.z[a]);
      ey = d3 - d3.dot(ex) * ex;  // the builder rejects n3 on the spring axis
    } else if (!prop.has_skew || std::abs(ey.dot(ex)) > 0.999) {
      // Global axis least aligned with x.
      int k = 0;
      for (int i = 1; i < 3; ++i)
        if (std::abs(ex(i)) < std::abs(ex(k))) k = i;
      ey = Eigen::Vector3d::Unit(k);
    }
    ey = (ey - ey.dot(ex) * ex).normalized();
    frame0[e].col(0) = ex;
    frame0[e].col(1) = ey;
    frame0[e].col(2) = ex.cross(ey);
  }
}

void SpringBeamGroup::compute_forces(const StepContext& step, const NodalState& nodes,
                                     GroupStepResult& result) {
  const double dt = step.dt_prev;
  const std::size_t nc = n_chunks(n_elements);
  ChunkScratch& scratch = chunk_scratch(nc);
  std::vector<double>& chunk_dt = scratch.dt;
  std::vector<Index>& chunk_el = scratch.el;
  std::vector<std::uint8_t>& chunk_broke = scratch.broke;
  parallel_loop(nc, nc > 1, [&](std::size_t c) {
    const std::size_t end = std::min(n_elements, (c + 1) * kChunk);
    for (std::size_t e = c * kChunk; e < end; ++e) {
      const std::size_t s1 = 2 * e, s2 = 2 * e + 1;
      const auto a = static_cast<std::size_t>(connectivity[s1]);
      const auto b = static_cast<std::size_t>(connectivity[s2]);
      if (dt > 0) {
        const Eigen::Vector3d wa(nodes.omega.x[a], nodes.omega.y[a], nodes.omega.z[a]);
        const Eigen::Vector3d wb(nodes.omega.x[b], nodes.omega.y[b], nodes.omega.z[b]);
        rot_a[e] = (quat_exp(dt * wa) * rot_a[e]).normalized();
        rot_b[e] = (quat_exp(dt * wb) * rot_b[e]).normalized();
      }
      const Eigen::Vector3d psi = quat_log(rot_a[e].conjugate() * rot_b[e]);
      const Eigen::Matrix3d E = (rot_a[e] * quat_exp(0.5 * psi)).toRotationMatrix() * frame0[e];
      const Eigen::Vector3d r(nodes.x.x[b] - nodes.x.x[a], nodes.x.y[b] - nodes.x.y[a],
                              nodes.x.z[b] - nodes.x.z[a]);
      Eigen::Vector3d delta = E.transpose() * r;
      delta(0) -= length0[e];
      const Eigen::Vector3d theta = frame0[e].transpose() * psi;
      Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
      if (alive[e]) {
        const double sc = law_scale[e];
        bool broke = false;
        for (std::size_t i = 0; i < 3; ++i) {
          SpringDofState& st = state[e * 6 + i];
          F(static_cast<int>(i)) = spring_dof_force(prop.dofs[i], st, delta(static_cast<int>(i)) * sc, dt);
          SpringDofState& sr = state[e * 6 + 3 + i];
          M(static_cast<int>(i)) = spring_dof_force(prop.dofs[3 + i], sr, theta(static_cast<int>(i)) * sc, dt);
          broke = broke || st.broken || sr.broken;
        }
        if (broke) { alive[e] = 0; chunk_broke[c] = 1; F.setZero(); M.setZero(); }
      }
      out_force[e] = {F(0), F(1), F(2), M(0), M(1), M(2)};
      out_def[e] = {delta(0), delta(1), delta(2), theta(0), theta(1), theta(2)};
      const Eigen::Vector3d f = E * F;
      const Eigen::Vector3d m = E * M;
      const Eigen::Vector3d couple = 0.5 * r.cross(f);
      slot_force.x[s1] = f.x();  slot_force.y[s1] = f.y();  slot_force.z[s1] = f.z();
      slot_force.x[s2] = -f.x(); slot_force.y[s2] = -f.y(); slot_force.z[s2] = -f.z();
      slot_moment.x[s1] = m.x() + couple.x();
      slot_moment.y[s1] = m.y() + couple.y();
      slot_moment.z[s1] = m.z() + couple.z();
      slot_moment.x[s2] = -m.x() + couple.x();
      slot_moment.y[s2] = -m.y() + couple.y();
      slot_moment.z[s2] = -m.z() + couple.z();
      const double l = r.norm();
      element_stiffness(e, nodes, 0.25 * k_trans * law_scale[e] * l * l, chunk_dt[c], chunk_el[c]);
    }
  }, chunk_thread);
  finish_step(chunk_dt, chunk_el, chunk_broke, result);
}

}  // namespace hbm::solver::springs
