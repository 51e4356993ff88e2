// SPDX-License-Identifier: GPL-3.0-or-later
// Builder of rigid bodies (/RBODY). Runs after the element builders (it needs their
// nodal masses). Layout (Radioss 2024): line 1 `node_id sens_id skew_id Ispher Mass
// grnod_id Ikrem ICoG surf_id`, line 2 `Jxx Jyy Jzz`, line 3 `Jxy Jyz Jxz`.
// Mass and J are added to the body (at the centre, global axes). ICoG 0/1: centre from
// the secondaries and the main node; 2: from the secondaries only, main node mass added
// at the centre; the main node is moved to the centre. Ispher = 1: spherical inertia
// (mean of the principal moments). Elements whose nodes all belong to one body are
// deactivated, as in OpenRadioss (/RBODY: "all the elements belonging to the rigid body
// are deactivated"): ElementGroup::deactivate, no force, energy or time step from them,
// their mass stays in the body. Not supported (deck
// error naming the field): sensors, skews, ICoG 3 and 4, nested bodies.
// Registered in solver/src/build/builders.def.
#include "hbm/solver/build_context.hpp"
#include "rigid/rigid_body.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hbm::solver {

void build_rigid_bodies(BuildContext& ctx) {
  ctx.claim("/RBODY");
  NodalState& nodes = ctx.nodes();
  // Body index per node (-1: none), for overlap checks and element deactivation.
  std::vector<std::int32_t> body_of(nodes.n_nodes, -1);
  std::vector<rigid::RigidBody*> bodies;
  for (const hbm::deck::Card* c : ctx.starter().cards_of("/RBODY")) {
    const hbm::deck::Row& l1 = c->lines.at(0);
    auto body = std::make_unique<rigid::RigidBody>();
    body->id = c->id;
    body->title = c->title;
    bool ok = true;
    body->main = ctx.require_node(*c, l1, "node_id");
    if (c->integer(l1, "sens_id") != 0) {
      ctx.error(*c, l1, "sens_id", "rigid body activation by sensor is not supported (use 0)");
      ok = false;
    }
    if (c->integer(l1, "skew_id") != 0) {
      ctx.error(*c, l1, "skew_id", "skew frames are not supported (use 0: global axes)");
      ok = false;
    }
    const std::int64_t icog = c->integer(l1, "ICoG");
    if (icog > 2) {
      ctx.error(*c, l1, "ICoG", "ICoG = " + std::to_string(icog) +
                                    " is not supported (0/1: centre of all masses, 2: of the secondaries)");
      ok = false;
    }
    if (c->integer(l1, "Ikrem") != 0 || c->integer(l1, "surf_id") != 0)
      ctx.warning(*c, "Ikrem and surf_id are not used by this engine (rigid walls and contact see the "
                      "secondary nodes as ordinary nodes)");
    const std::vector<Index>* group = ctx.require_node_group(*c, l1, "grnod_id");
    if (!group || body->main == kNoIndex || !ok) continue;
    const auto main = static_cast<std::size_t>(body->main);
    if (body_of[main] >= 0) {
      ctx.error(*c, l1, "node_id", "main node " + std::to_string(nodes.user_id[main]) +
                                       " already belongs to another rigid body (nested bodies are not supported)");
      continue;
    }
    const auto self = static_cast<std::int32_t>(bodies.size());
    for (Index n : *group) {
      if (n == body->main) continue;  // the main node is never its own secondary
      const auto k = static_cast<std::size_t>(n);
      if (body_of[k] >= 0) {
        ctx.error(*c, l1, "grnod_id", "node " + std::to_string(nodes.user_id[k]) +
                                          " is already a node of another rigid body");
        ok = false;
        break;
      }
      body->secondary.push_back(n);
    }
    if (!ok) continue;
    if (body->secondary.empty()) {
      ctx.error(*c, l1, "grnod_id", "the secondary node group is empty");
      continue;
    }
    Eigen::Matrix3d J;
    J << c->real(1, "Jxx"), c->real(2, "Jxy"), c->real(2, "Jxz"),
         c->real(2, "Jxy"), c->real(1, "Jyy"), c->real(2, "Jyz"),
         c->real(2, "Jxz"), c->real(2, "Jyz"), c->real(1, "Jzz");
    const Eigen::Vector3d x_before(nodes.x.x[main], nodes.x.y[main], nodes.x.z[main]);
    try {
      body->assemble(nodes, c->real(l1, "Mass"), J, icog != 2, c->integer(l1, "Ispher") == 1);
    } catch (const std::invalid_argument& e) {
      ctx.error(*c, e.what());
      continue;
    }
    const RunControl& rc = ctx.model().control;
    if (rc.nodal_cst && rc.dt_scale > 0)
      body->rot_scaling_coef = 0.5 * (rc.dt_min / rc.dt_scale) * (rc.dt_min / rc.dt_scale);
    const Eigen::Vector3d x_after(nodes.x.x[main], nodes.x.y[main], nodes.x.z[main]);
    if ((x_after - x_before).norm() > 1e-9 * (1.0 + x_before.norm()))
      for (const auto& g : ctx.model().groups)
        if (std::find(g->connectivity.begin(), g->connectivity.end(), body->main) != g->connectivity.end()) {
          ctx.warning(*c, "main node " + std::to_string(nodes.user_id[main]) +
                              " is moved to the centre of mass but carries elements (" + g->keyword +
                              "): attach elements to secondary nodes");
          break;
        }
    body_of[main] = self;
    for (Index n : body->secondary) body_of[static_cast<std::size_t>(n)] = self;
    bodies.push_back(body.get());
    ctx.add_constraint(std::move(body));
  }
  // Deactivate elements lying entirely inside one body (ElementGroup::deactivate).
  if (bodies.empty()) return;
  std::vector<std::size_t> deactivated(bodies.size(), 0);
  std::vector<std::uint8_t> inside;
  for (const auto& g : ctx.model().groups) {
    const std::size_t npe = g->nodes_per_element;
    inside.assign(g->n_elements, 0);
    bool any = false;
    for (std::size_t e = 0; e < g->n_elements; ++e) {
      const std::int32_t b = body_of[static_cast<std::size_t>(g->connectivity[e * npe])];
      if (b < 0 || !g->alive[e]) continue;
      bool in = true;
      for (std::size_t k = 1; k < npe && in; ++k)
        in = body_of[static_cast<std::size_t>(g->connectivity[e * npe + k])] == b;
      if (!in) continue;
      inside[e] = 1;
      any = true;
      ++deactivated[static_cast<std::size_t>(b)];
    }
    if (any) g->deactivate(inside);
  }
  const auto cards = ctx.starter().cards_of("/RBODY");
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (deactivated[b] > 0)
      for (const hbm::deck::Card* c : cards)
        if (c->id == bodies[b]->id)
          ctx.warning(*c, std::to_string(deactivated[b]) +
                              " elements lie inside the rigid body and are deactivated");
}

}  // namespace hbm::solver
