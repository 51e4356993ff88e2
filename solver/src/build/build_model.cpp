// SPDX-License-Identifier: GPL-3.0-or-later
// Build phase entry: run control from the engine deck, core tables, every registered
// builder, time-history requests, unsupported-keyword check, assembly incidence.
#include "core/th_requests.hpp"
#include "hbm/solver/build_context.hpp"

#include <algorithm>

namespace hbm::solver {

namespace {

void read_run_control(BuildContext& ctx, RunControl& rc) {
  const hbm::deck::Deck& e = ctx.engine();
  const auto run = e.cards_of("/RUN");
  if (run.empty()) {
    ctx.model().run_name = e.run_name;
  } else {
    rc.t_stop = run.back()->real(0, "Tstop");
  }
  for (const auto* c : e.cards_of("/TFILE")) rc.th_interval = c->real(0, "dt_his");
  // Animation frames always hold displacement, velocity, contact force and added mass per
  // node, and von Mises stress, plastic strain, erosion, specific energy and hourglass energy
  // per element (output/vtk_writer.cpp); other requested results are not written: say so.
  for (const char* kw : {"/ANIM/VECT/ACC", "/ANIM/VECT/FINT", "/ANIM/VECT/FEXT"})
    for (const auto* c : e.cards_of(kw))
      ctx.warning(*c, "not written to the animation (this engine writes displacement, velocity, contact force and "
                      "added mass per node; von Mises stress, plastic strain, erosion, specific and hourglass energy per element)");
  for (const auto* c : e.cards_of("/ANIM/DT")) {
    rc.anim_start = c->real(0, "Tstart");
    rc.anim_interval = c->real(0, "Tfreq");
  }
  for (const auto* c : e.cards_of("/DT/NODA/CST")) {
    rc.nodal_cst = true;
    rc.dt_scale = c->real(0, "Tsca");
    rc.dt_min = c->real(0, "Tmin");
    if (!(rc.dt_min > 0)) ctx.error(*c, c->lines.at(0), "Tmin", "must be > 0 for a fixed nodal time step");
  }
  for (const auto* c : e.cards_of("/STOP")) {
    const double em = c->real(0, "Emax"), dm = c->real(0, "DMmax");
    if (em > 0) rc.stop_energy_error = em;
    if (dm > 0) rc.stop_mass_ratio = dm;
  }
  for (const auto* c : e.cards_of("/PRINT")) {
    rc.print_every = std::max<std::int64_t>(1, c->id < 0 ? -c->id : c->id);
    rc.print_stdout = c->id < 0;
  }
  if (!(rc.t_stop > 0)) ctx.messages_add_error_once("engine deck: /RUN with Tstop > 0 is required");
}

}  // namespace

bool build_model(const hbm::deck::Deck& starter, const hbm::deck::Deck& engine, Model& model,
                 std::vector<std::string>& messages) {
  model.units = starter.work_units;
  model.run_name = starter.run_name;
  BuildContext ctx(starter, engine, model);
  read_run_control(ctx, model.control);
  for (const BuilderEntry& b : registered_builders()) b.build(ctx);
  build_th_groups(ctx);
  // Every starter keyword must be claimed by the core or a builder.
  std::vector<std::string> reported;
  for (const auto& c : starter.cards) {
    const std::string kw(c.keyword());
    const auto& cl = ctx.claimed();
    if (std::find(cl.begin(), cl.end(), kw) != cl.end()) continue;
    if (std::find(reported.begin(), reported.end(), kw) != reported.end()) continue;
    reported.push_back(kw);
    ctx.error(c, "keyword " + kw + " is not supported by the engine (no builder handles it)");
  }
  build_incidence(model);
  NodalState& n = model.nodes;
  n.mass = n.mass0;
  n.inertia = n.inertia0;
  messages = ctx.messages();
  return ctx.ok();
}

}  // namespace hbm::solver
