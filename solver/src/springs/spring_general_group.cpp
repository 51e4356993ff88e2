// SPDX-License-Identifier: GPL-3.0-or-later
// /PROP/TYPE8 general spring kernel (see spring_general_group.hpp).
#include "springs/spring_general_group.hpp"

#include "core/parallel_loop.hpp"

#include <algorithm>
#include <limits>

namespace hbm::solver::springs {

void SpringGeneralGroup::compute_forces(const StepContext& step, const NodalState& nodes,
                                        GroupStepResult& result) {
  const double dt = step.dt_prev;
  const Eigen::Matrix3d& E = prop.skew;  // columns: frame axes
  const std::size_t nc = n_chunks(n_elements);
  ChunkScratch& scratch = chunk_scratch(nc);
  std::vector<double>& chunk_dt = scratch.dt;
  std::vector<Index>& chunk_el = scratch.el;
  std::vector<std::uint8_t>& chunk_broke = scratch.broke;
  if (rotation.size() != n_elements) rotation.assign(n_elements, Eigen::Vector3d::Zero());
  parallel_loop(nc, nc > 1, [&](std::size_t c) {
    const std::size_t end = std::min(n_elements, (c + 1) * kChunk);
    for (std::size_t e = c * kChunk; e < end; ++e) {
      const std::size_t s1 = 2 * e, s2 = 2 * e + 1;
      const auto a = static_cast<std::size_t>(connectivity[s1]);
      const auto b = static_cast<std::size_t>(connectivity[s2]);
      const Eigen::Vector3d u(
          (nodes.x.x[b] - nodes.x.x[a]) - (nodes.x0.x[b] - nodes.x0.x[a]),
          (nodes.x.y[b] - nodes.x.y[a]) - (nodes.x0.y[b] - nodes.x0.y[a]),
          (nodes.x.z[b] - nodes.x.z[a]) - (nodes.x0.z[b] - nodes.x0.z[a]));
      const Eigen::Vector3d delta = E.transpose() * u;
      if (rotational) {
        const Eigen::Vector3d dw(nodes.omega.x[b] - nodes.omega.x[a],
                                 nodes.omega.y[b] - nodes.omega.y[a],
                                 nodes.omega.z[b] - nodes.omega.z[a]);
        rotation[e] += dt * (E.transpose() * dw);
      }
      Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
      if (alive[e]) {
        const double sc = law_scale[e];
        bool broke = false;
        for (int i = 0; i < 3; ++i) {
          SpringDofState& st = state[e * 6 + static_cast<std::size_t>(i)];
          F(i) = spring_dof_force(prop.dofs[static_cast<std::size_t>(i)], st, delta(i) * sc, dt);
          broke = broke || st.broken;
          if (rotational) {
            SpringDofState& sr = state[e * 6 + 3 + static_cast<std::size_t>(i)];
            M(i) = spring_dof_force(prop.dofs[3 + static_cast<std::size_t>(i)], sr, rotation[e](i) * sc, dt);
            broke = broke || sr.broken;
          }
        }
        if (broke) { alive[e] = 0; chunk_broke[c] = 1; F.setZero(); M.setZero(); }
      }
      out_force[e] = {F(0), F(1), F(2), M(0), M(1), M(2)};
      out_def[e] = {delta(0), delta(1), delta(2), rotation[e](0), rotation[e](1), rotation[e](2)};
      const Eigen::Vector3d f = E * F;
      slot_force.x[s1] = f.x();  slot_force.y[s1] = f.y();  slot_force.z[s1] = f.z();
      slot_force.x[s2] = -f.x(); slot_force.y[s2] = -f.y(); slot_force.z[s2] = -f.z();
      if (rotational) {
        const Eigen::Vector3d m = E * M;
        slot_moment.x[s1] = m.x();  slot_moment.y[s1] = m.y();  slot_moment.z[s1] = m.z();
        slot_moment.x[s2] = -m.x(); slot_moment.y[s2] = -m.y(); slot_moment.z[s2] = -m.z();
      }
      element_stiffness(e, nodes, 0.0, chunk_dt[c], chunk_el[c]);
    }
  }, chunk_thread);
  finish_step(chunk_dt, chunk_el, chunk_broke, result);
}

}  // namespace hbm::solver::springs
