// SPDX-License-Identifier: GPL-3.0-or-later
// Second rigid-body builder, registered after the loads (solver/src/build/builders.def):
//  - /BCS and /IMPVEL on a node that is a secondary of an /RBODY are deck errors (file,
//    line, keyword, field grnod_id). The body imposes the velocity of its secondaries
//    after those constraints, so the condition would be silently lost; Radioss reports
//    two kinematic conditions on one node as incompatible (warning 147, "Incompatible
//    Kinematic Conditions" in the Radioss theory manual). Constrain the main node.
//  - The initial motion of each body is taken from the nodal velocities now that
//    /INIVEL has been applied (RigidBody::start_motion), so that the engine's kinetic
//    energy at t = 0 holds the body's translation and spin.
#include "hbm/solver/build_context.hpp"
#include "rigid/rigid_body.hpp"

#include <string>
#include <vector>

namespace hbm::solver {

void finish_rigid_bodies(BuildContext& ctx) {
  NodalState& nodes = ctx.nodes();
  std::vector<rigid::RigidBody*> bodies;
  for (const auto& k : ctx.model().constraints)
    if (auto* b = dynamic_cast<rigid::RigidBody*>(k.get())) bodies.push_back(b);
  if (bodies.empty()) return;
  std::vector<const rigid::RigidBody*> body_of(nodes.n_nodes, nullptr);
  for (const rigid::RigidBody* b : bodies)
    for (Index s : b->secondary) body_of[static_cast<std::size_t>(s)] = b;
  for (const char* kw : {"/BCS", "/IMPVEL"})
    for (const hbm::deck::Card* c : ctx.starter().cards_of(kw)) {
      const hbm::deck::Row& row = c->lines.at(0);
      const std::vector<Index>* group = ctx.node_group(c->integer(row, "grnod_id"));
      if (!group) continue;  // unknown group: already reported by the loads builder
      for (Index n : *group) {
        const rigid::RigidBody* b = body_of[static_cast<std::size_t>(n)];
        if (!b) continue;
        const auto i = static_cast<std::size_t>(n);
        ctx.error(*c, row, "grnod_id",
                  "node " + std::to_string(nodes.user_id[i]) + " is a secondary node of /RBODY/" +
                      std::to_string(b->id) + ": the rigid body imposes its velocity, so " + kw +
                      " would be ignored; apply it to the main node " +
                      std::to_string(nodes.user_id[static_cast<std::size_t>(b->main)]) + " instead");
        break;
      }
    }
  for (rigid::RigidBody* b : bodies) b->start_motion(nodes);
}

}  // namespace hbm::solver
