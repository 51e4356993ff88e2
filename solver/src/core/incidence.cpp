// SPDX-License-Identifier: GPL-3.0-or-later
// Node -> slot incidence (CSR) for deterministic assembly: node i's slots listed in
// (group, element, local node) order.
#include "hbm/solver/model.hpp"

namespace hbm::solver {

void build_incidence(Model& model) {
  const std::size_t nn = model.nodes.n_nodes;
  model.incidence_start.assign(nn + 1, 0);
  for (const auto& g : model.groups)
    for (Index node : g->connectivity) ++model.incidence_start[static_cast<std::size_t>(node) + 1];
  for (std::size_t i = 0; i < nn; ++i) model.incidence_start[i + 1] += model.incidence_start[i];
  const auto total = static_cast<std::size_t>(model.incidence_start[nn]);
  model.incidence_group.assign(total, 0);
  model.incidence_slot.assign(total, 0);
  std::vector<std::int64_t> fill(model.incidence_start.begin(), model.incidence_start.end() - 1);
  for (std::size_t g = 0; g < model.groups.size(); ++g) {
    const auto& conn = model.groups[g]->connectivity;
    for (std::size_t s = 0; s < conn.size(); ++s) {
      const auto j = static_cast<std::size_t>(fill[static_cast<std::size_t>(conn[s])]++);
      model.incidence_group[j] = static_cast<std::int32_t>(g);
      model.incidence_slot[j] = static_cast<std::int64_t>(s);
    }
  }
}

}  // namespace hbm::solver
