// SPDX-License-Identifier: GPL-3.0-or-later
// /PROP/TYPE4 axial spring kernel (see spring_axial_group.hpp).
#include "springs/spring_axial_group.hpp"

#include "core/parallel_loop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hbm::solver::springs {

void SpringAxialGroup::init_axes(const NodalState& nodes) {
  axis.assign(n_elements, Eigen::Vector3d::UnitX());
  for (std::size_t e = 0; e < n_elements; ++e) {
    const auto a = static_cast<std::size_t>(connectivity[2 * e]);
    const auto b = static_cast<std::size_t>(connectivity[2 * e + 1]);
    const Eigen::Vector3d d(nodes.x0.x[b] - nodes.x0.x[a], nodes.x0.y[b] - nodes.x0.y[a],
                            nodes.x0.z[b] - nodes.x0.z[a]);
    if (d.norm() > 0) axis[e] = d / d.norm();
  }
}

void SpringAxialGroup::compute_forces(const StepContext& step, const NodalState& nodes,
                                      GroupStepResult& result) {
  const SpringDofLaw& law = prop.dofs[0];
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
      Eigen::Vector3d d(nodes.x.x[b] - nodes.x.x[a], nodes.x.y[b] - nodes.x.y[a],
                        nodes.x.z[b] - nodes.x.z[a]);
      const double l = d.norm();
      if (l > 1e-12 * length0[e]) axis[e] = d / l;
      double f = 0;
      if (alive[e]) {
        SpringDofState& st = state[e];
        const double sc = law_scale[e];
        f = spring_dof_force(law, st, (l - length0[e]) * sc, dt, l * sc);
        if (st.broken) { alive[e] = 0; chunk_broke[c] = 1; f = 0; }
      }
      out_force[e] = {f, 0, 0, 0, 0, 0};
      out_def[e] = {l - length0[e], 0, 0, 0, 0, 0};
      const Eigen::Vector3d fe = f * axis[e];
      slot_force.x[s1] = fe.x();  slot_force.y[s1] = fe.y();  slot_force.z[s1] = fe.z();
      slot_force.x[s2] = -fe.x(); slot_force.y[s2] = -fe.y(); slot_force.z[s2] = -fe.z();
      element_stiffness(e, nodes, 0.0, chunk_dt[c], chunk_el[c]);
    }
  }, chunk_thread);
  finish_step(chunk_dt, chunk_el, chunk_broke, result);
}

}  // namespace hbm::solver::springs
