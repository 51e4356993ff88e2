// SPDX-License-Identifier: GPL-3.0-or-later
// Spring group construction (see spring_group_factory.hpp).
#include "springs/spring_group_factory.hpp"

#include "springs/spring_axial_group.hpp"
#include "springs/spring_beam_group.hpp"
#include "springs/spring_general_group.hpp"

#include <cmath>

namespace hbm::solver::springs {

SpringNodalShare spring_nodal_share(const SpringProperty& prop, double length0) {
  const double f = prop.per_length ? length0 : 1.0;
  return {0.5 * prop.mass * f, prop.type == SpringType::Axial ? 0.0 : 0.5 * prop.inertia * f};
}

bool has_rotational_law(const SpringProperty& prop) {
  for (std::size_t d = 3; d < prop.dofs.size(); ++d) {
    const SpringDofLaw& l = prop.dofs[d];
    if (l.K != 0 || l.C != 0 || l.nonlinear() || !l.h4.empty()) return true;
  }
  return false;
}

std::unique_ptr<SpringGroup> make_spring_group(const SpringProperty& prop, Index part,
                                               std::vector<Index> connectivity,
                                               std::vector<std::int64_t> element_ids,
                                               const NodalState& nodes,
                                               const std::vector<Index>* orientation) {
  std::unique_ptr<SpringGroup> g;
  bool rotational = false;
  switch (prop.type) {
    case SpringType::Axial: g = std::make_unique<SpringAxialGroup>(); break;
    case SpringType::General: {
      auto s = std::make_unique<SpringGeneralGroup>();
      s->rotational = rotational = has_rotational_law(prop);
      g = std::move(s);
      break;
    }
    case SpringType::Beam: g = std::make_unique<SpringBeamGroup>(); rotational = true; break;
  }
  g->keyword = "/SPRING";
  g->part = part;
  g->prop = prop;
  g->nodes_per_element = 2;
  g->n_elements = element_ids.size();
  g->connectivity = std::move(connectivity);
  g->element_id = std::move(element_ids);
  g->length0.resize(g->n_elements);
  for (std::size_t e = 0; e < g->n_elements; ++e) {
    const auto a = static_cast<std::size_t>(g->connectivity[2 * e]);
    const auto b = static_cast<std::size_t>(g->connectivity[2 * e + 1]);
    g->length0[e] = std::sqrt(std::pow(nodes.x0.x[b] - nodes.x0.x[a], 2) +
                              std::pow(nodes.x0.y[b] - nodes.x0.y[a], 2) +
                              std::pow(nodes.x0.z[b] - nodes.x0.z[a], 2));
  }
  g->init_state();
  g->allocate_slots(rotational);
  if (auto* a = dynamic_cast<SpringAxialGroup*>(g.get())) a->init_axes(nodes);
  if (auto* b = dynamic_cast<SpringBeamGroup*>(g.get())) {
    if (orientation) b->orientation_node = *orientation;
    b->init_frames(nodes);
  }
  if (auto* s = dynamic_cast<SpringGeneralGroup*>(g.get()))
    s->rotation.assign(s->n_elements, Eigen::Vector3d::Zero());
  return g;
}

}  // namespace hbm::solver::springs
