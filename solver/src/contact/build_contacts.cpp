// SPDX-License-Identifier: GPL-3.0-or-later
// Builder of the contact area (registered in solver/src/build/builders.def): reads
// /SURF/PART, /SURF/SEG, /INTER/TYPE7, /INTER/TYPE2 and /RWALL/PLANE and adds the
// interfaces (Interaction) and walls and ties (Constraint) to the model.
//
// Defaults (Radioss TYPE7 conventions; Stfac and VIS_S also when given as 0, as OpenRadioss
// reads them): Stfac 1, VIS_S 0.05, Tstop infinite; Gapmin
// blank or 0 with Igap 0: the smallest of half the main shells' thickness and a tenth
// of the main solid faces' size. With /DT/NODA/CST the penalty is capped so that the
// contact alone keeps the fixed step (PenaltyContactParams::fixed_dt).
#include "deck_fields.hpp"
#include "model_surfaces.hpp"
#include "penalty_contact.hpp"
#include "rigid_wall_plane.hpp"
#include "segment_projection.hpp"
#include "tied_contact.hpp"
#include "type7_interface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace hbm::solver {

namespace {

using contact::ContactSurface;
using hbm::deck::Card;

// Names as in the Radioss 2024 reference guide; alternatives cover other spellings.
#define F_SEC {"grnd_IDs", "grnod_id", "grnd_ids", "grnod_ids", "grnd_id"}
#define F_SURF {"surf_IDm", "surf_id", "surf_idm", "surf_ID"}

// Resolve a node group field; error recorded if missing or unknown.
const std::vector<Index>* node_group_of(BuildContext& ctx, const Card& c,
                                        std::initializer_list<std::string_view> names,
                                        bool optional) {
  const contact::FieldRef r = contact::find_any(c, names);
  if (!r.row) {
    if (!optional) ctx.error(c, std::string("field ") + std::string(r.spec->name) + " missing: a node group is required");
    return nullptr;
  }
  return ctx.require_node_group(c, *r.row, r.spec->name, optional);
}

struct SurfaceTable {
  std::map<std::int64_t, ContactSurface> by_id;
  std::map<std::int64_t, const Card*> card;
};

SurfaceTable read_surfaces(BuildContext& ctx, const contact::ModelSurfaces& geo) {
  SurfaceTable t;
  static constexpr std::string_view ids[] = {"id1", "id2", "id3", "id4", "id5",
                                             "id6", "id7", "id8", "id9", "id10"};
  for (const Card* c : ctx.starter().cards_of("/SURF/PART")) {
    std::vector<Index> parts;
    for (std::size_t r = 0; r < c->n_rows(); ++r) {
      const hbm::deck::Row& row = c->row(r);
      for (std::string_view f : ids) {
        bool known = false;
        for (const auto& fs : row.layout->fields) known = known || fs.name == f;
        if (!known || c->blank(row, f)) continue;
        const std::int64_t pid = c->integer(row, f);
        const Index p = ctx.part_index(pid);
        if (p == kNoIndex) ctx.error(*c, row, f, "part " + std::to_string(pid) + " does not exist");
        else parts.push_back(p);
      }
    }
    ContactSurface s = geo.of_parts(parts);
    if (s.size() == 0) ctx.error(*c, "surface has no segment (parts without solids or shells)");
    t.by_id[c->id] = std::move(s);
    t.card[c->id] = c;
  }
  for (const Card* c : ctx.starter().cards_of("/SURF/SEG")) {
    std::vector<std::array<Index, 4>> segs;
    for (std::size_t r = 0; r < c->n_rows(); ++r) {
      const hbm::deck::Row& row = c->row(r);
      std::array<Index, 4> q{};
      bool ok = true;
      static constexpr std::string_view nn[] = {"n1", "n2", "n3", "n4"};
      for (std::size_t k = 0; k < 4; ++k) {
        if (k == 3 && c->blank(row, nn[k])) {
          q[3] = q[2];
          continue;
        }
        q[k] = ctx.require_node(*c, row, nn[k]);
        ok = ok && q[k] != kNoIndex;
      }
      if (ok) segs.push_back(q);
    }
    std::size_t orphans = 0;
    t.by_id[c->id] = geo.of_segments(segs, orphans);
    t.card[c->id] = c;
    if (orphans > 0)
      ctx.warning(*c, std::to_string(orphans) +
                          " segment(s) lie on no solid face or shell: two-sided, stiffness 0 "
                          "(usable as TYPE2 main surface or with Istf = 1)");
  }
  return t;
}

const ContactSurface* surface_of(BuildContext& ctx, const SurfaceTable& t, const Card& c) {
  const contact::FieldRef r = contact::find_any(c, F_SURF);
  const std::int64_t id = r.row ? c.integer(*r.row, r.spec->name) : 0;
  auto it = t.by_id.find(id);
  if (it == t.by_id.end()) {
    if (r.row) ctx.error(c, *r.row, r.spec->name, "surface " + std::to_string(id) + " is not defined (/SURF/PART or /SURF/SEG)");
    else ctx.error(c, "main surface missing");
    return nullptr;
  }
  return &it->second;
}

// Options this implementation does not have: a non-default value is reported (never
// silently ignored); the run goes on with the documented behaviour.
void warn_unsupported(BuildContext& ctx, const Card& c, std::initializer_list<std::string_view> fields) {
  for (std::string_view f : fields) {
    if (!contact::has_any(c, {f}) || contact::blank_any(c, {f})) continue;
    const contact::FieldRef r = contact::find_any(c, {f});
    const hbm::deck::Value& v = c.value(*r.row, r.spec->name);
    const bool is_default = r.spec->type == hbm::deck::FieldType::Real ? v.real == r.spec->default_value
                                                                       : static_cast<double>(v.integer) == r.spec->default_value;
    if (!is_default)
      ctx.warning(c, std::string("field ").append(f).append(" is not supported by the engine: ignored"));
  }
}

double default_gap(const ContactSurface& s, const NodalState& n) {
  double g = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (!s.one_sided[k]) {
      if (s.thickness[k] > 0) g = std::min(g, 0.5 * s.thickness[k]);
      continue;
    }
    std::array<contact::V3, 4> c{};
    for (std::size_t j = 0; j < 4; ++j) {
      const auto i = static_cast<std::size_t>(s.nodes[k][j]);
      c[j] = {n.x0.x[i], n.x0.y[i], n.x0.z[i]};
    }
    g = std::min(g, 0.1 * std::sqrt(norm(contact::segment_area_vector(c, s.is_triangle(k)))));
  }
  return std::isfinite(g) ? g : 0.0;
}

void build_type7(BuildContext& ctx, const Card& c, const SurfaceTable& surfs,
                 const contact::ModelSurfaces& geo) {
  const std::vector<Index>* sec = node_group_of(ctx, c, F_SEC, false);
  const ContactSurface* main = surface_of(ctx, surfs, c);
  if (!sec || !main) return;
  contact::PenaltyContactParams p;
  p.istf = static_cast<int>(contact::int_any(c, {"Istf"}));
  p.igap = static_cast<int>(contact::int_any(c, {"Igap"}));
  if (p.istf < 0 || p.istf > 5) {
    ctx.error(c, "Istf = " + std::to_string(p.istf) + ": supported values are 0 to 5");
    return;
  }
  const int igap_typed = p.igap;
  if (p.igap >= 2) {
    ctx.warning(c, "Igap = " + std::to_string(p.igap) + " treated as Igap = 1 (gap from thicknesses)");
    p.igap = 1;
  }
  // Stfac and VIS_S: blank or 0 read as the default 1, 0.05 (the deck library's
  // zero_is_default, as OpenRadioss's starter hm_read_inter_type07.F reads them).
  p.stfac = contact::real_any(c, {"Stfac"});
  p.fric = contact::real_any(c, {"Fric"});
  p.gapmin = contact::real_any(c, {"Gapmin"});
  p.tstart = contact::real_any(c, {"Tstart"});
  const double tstop = contact::real_any(c, {"Tstop"});
  p.tstop = tstop > 0 ? tstop : std::numeric_limits<double>::infinity();
  // As OpenRadioss reads them (hm_read_inter_type07.F): Fscalegap and Gapmax act with
  // Igap >= 2 only (here read as Igap 1, gap from thicknesses: they scale and cap it), Stmin
  // and Stmax with Istf >= 2 only; elsewhere they are dropped, with a warning here.
  auto dropped = [&](std::initializer_list<std::string_view> names, const std::string& why) {
    for (std::string_view f : names)
      if (contact::has_any(c, {f}) && contact::real_any(c, {f}) != 0.0)
        ctx.warning(c, std::string(f) + " is not used " + why + " (as in OpenRadioss)");
  };
  if (igap_typed >= 2) {
    if (contact::has_any(c, {"Fscalegap", "Fscale_gap"})) {
      const double fs = contact::real_any(c, {"Fscalegap", "Fscale_gap"});
      p.gap_scale = fs > 0 ? fs : 1.0;
    }
    if (contact::has_any(c, {"Gapmax", "Gap_max"})) p.gapmax = contact::real_any(c, {"Gapmax", "Gap_max"});
  } else {
    dropped({"Fscalegap", "Gapmax"}, "with Igap " + std::to_string(igap_typed));
  }
  if (p.istf >= 2) {
    if (contact::has_any(c, {"Stmin"})) p.stmin = contact::real_any(c, {"Stmin"});
    if (contact::has_any(c, {"Stmax"})) p.stmax = contact::real_any(c, {"Stmax"});
  } else {
    dropped({"Stmin", "Stmax"}, "with Istf " + std::to_string(p.istf));
  }
  if (contact::has_any(c, {"VISs", "VIS_S", "VISS"})) p.vis_s = contact::real_any(c, {"VISs", "VIS_S", "VISS"});
  // Friction as OpenRadioss reads it (hm_read_inter_type07.F): Iform 0 is 1, the viscous
  // form; VISF 0 (or blank) with Fric > 0 is 1; Iform 2, the incremental spring, has no VISF.
  const auto iform = contact::has_any(c, {"Iform"}) ? contact::int_any(c, {"Iform"}) : 0;
  p.friction_form = iform == 2 ? 2 : 1;
  if (contact::has_any(c, {"VISF"})) p.visf = contact::real_any(c, {"VISF"});
  if (p.visf == 0.0) p.visf = 1.0;
  if (p.fric < 0 || p.vis_s < 0 || p.stfac <= 0 || p.visf < 0) {
    ctx.error(c, "Stfac must be > 0, Fric, VIS_S and VISF >= 0");
    return;
  }
  warn_unsupported(ctx, c, {"Ibag", "Idel", "Iadm", "Fpenmax", "ITIED", "mesh_size", "dtmin", "Irem_gap",
                            "Irem_i2", "Ifiltr", "Xfreq", "sens_id", "fct_IDF"});
  // Inacti 5 and 6 (variable gap for initially penetrated nodes) are carried; 1-4 are not.
  if (contact::has_any(c, {"Inacti"})) {
    const auto inacti = contact::int_any(c, {"Inacti"});
    if (inacti == 5 || inacti == 6) p.inacti = static_cast<int>(inacti);
    else if (inacti != 0) warn_unsupported(ctx, c, {"Inacti"});
  }
  const RunControl& rc = ctx.model().control;
  if (rc.nodal_cst) {
    p.fixed_dt = rc.dt_min;
    p.tsca = rc.dt_scale;
  }
  if (p.igap == 0 && p.gapmin <= 0) p.gapmin = default_gap(*main, ctx.nodes());
  if (p.istf != 1) {
    std::size_t zero = 0;
    for (double k : main->k0) zero += k <= 0;
    if (zero > 0 && p.stmin <= 0)
      ctx.error(c, std::to_string(zero) + " main segment(s) have no stiffness (no element or material "
                   "with E/K): use Istf = 1 with Stfac = stiffness, or Istf 2-5 with Stmin > 0");
  }
  std::vector<double> node_gap, node_k0;
  if (p.igap == 1) node_gap = geo.node_half_thickness(*sec);
  if (p.istf >= 2) node_k0 = geo.node_stiffness(*sec);
  contact::PenaltyContact kernel(*main, *sec, p, ctx.nodes(), std::move(node_gap), std::move(node_k0));
  ctx.add_interaction(std::make_unique<contact::Type7Interface>(c.id, c.title, std::move(kernel)));
}

void build_type2(BuildContext& ctx, const Card& c, const SurfaceTable& surfs) {
  const std::vector<Index>* sec = node_group_of(ctx, c, F_SEC, false);
  const ContactSurface* main = surface_of(ctx, surfs, c);
  if (!sec || !main) return;
  warn_unsupported(ctx, c, {"Ignore", "Spotflag", "Level", "Isearch", "Idel2"});
  double dsearch = 0;
  if (contact::has_any(c, {"dsearch", "Dsearch", "dSearch"})) dsearch = contact::real_any(c, {"dsearch", "Dsearch", "dSearch"});
  std::vector<Index> untied;
  auto tie = std::make_unique<contact::TiedContact>(c.id, c.title, *main, *sec, dsearch, ctx.nodes(), untied);
  if (!untied.empty()) {
    std::string list;
    for (std::size_t k = 0; k < std::min<std::size_t>(untied.size(), 10); ++k)
      list.append(" ").append(std::to_string(ctx.nodes().user_id[static_cast<std::size_t>(untied[k])]));
    ctx.warning(c, std::to_string(untied.size()) + " secondary node(s) farther than dsearch from the main "
                   "surface are not tied:" + list + (untied.size() > 10 ? " ..." : ""));
  }
  for (const contact::TiedLink& l : tie->links())
    if (ctx.nodes().is_secondary[static_cast<std::size_t>(l.secondary)]) {
      ctx.error(c, "node " + std::to_string(ctx.nodes().user_id[static_cast<std::size_t>(l.secondary)]) +
                   " is already a secondary node (rigid body or another TYPE2)");
      return;
    }
  tie->transfer_mass(ctx.nodes());
  ctx.add_constraint(std::move(tie));
}

void build_rwall(BuildContext& ctx, const Card& c) {
  contact::RigidWallPlaneParams p;
  p.id = c.id;
  p.title = c.title;
  const NodalState& n = ctx.nodes();
  const contact::FieldRef node_ref = contact::find_any(c, {"node_id", "node_ID"});
  const std::int64_t node_id = node_ref.row ? c.integer(*node_ref.row, node_ref.spec->name) : 0;
  p.slide = static_cast<int>(contact::int_any(c, {"Slide"}));
  if (p.slide < 0 || p.slide > 2) {
    ctx.error(c, "Slide = " + std::to_string(p.slide) + ": 0 sliding, 1 tied, 2 friction");
    return;
  }
  p.fric = contact::real_any(c, {"fric", "Fric"});
  warn_unsupported(ctx, c, {"ffac", "ifq"});
  const double dsearch = contact::real_any(c, {"Dsearch", "dsearch", "d"});
  contact::V3 m1{contact::real_any(c, {"XM1"}), contact::real_any(c, {"YM1"}), contact::real_any(c, {"ZM1"})};
  if (node_id != 0) {
    p.wall_node = ctx.require_node(c, *node_ref.row, node_ref.spec->name);
    if (p.wall_node == kNoIndex) return;
    const auto w = static_cast<std::size_t>(p.wall_node);
    p.point = {n.x0.x[w], n.x0.y[w], n.x0.z[w]};
    // With a node, the M line holds Mass VX0 VY0 VZ0.
    const double mass = contact::real_any(c, {"Mass", "XM"});
    const contact::V3 v0{contact::real_any(c, {"VX0", "YM"}), contact::real_any(c, {"VY0", "ZM"}),
                         contact::has_any(c, {"VZ0"}) ? contact::real_any(c, {"VZ0"}) : 0.0};
    if (mass <= 0 && ctx.nodes().mass0[w] <= 0) {
      ctx.error(c, "moving wall node " + std::to_string(node_id) + " needs Mass > 0");
      return;
    }
    if (mass > 0) ctx.add_nodal_mass(p.wall_node, mass);
    ctx.nodes().v.x[w] = v0.x;
    ctx.nodes().v.y[w] = v0.y;
    ctx.nodes().v.z[w] = v0.z;
  } else {
    p.point = {contact::real_any(c, {"XM"}), contact::real_any(c, {"YM"}), contact::real_any(c, {"ZM"})};
  }
  p.normal = m1 - p.point;
  if (norm(p.normal) <= 0) {
    ctx.error(c, "M1 equals M: the wall normal M->M1 is undefined");
    return;
  }
  p.normal = contact::normalized(p.normal);
  // Secondary nodes: grnd_ID1, plus the nodes with mass on the free side within Dsearch
  // of the wall at t = 0 (none by distance when Dsearch = 0), minus grnd_ID2: OpenRadioss
  // hm_read_rwall_plane.F (a wall with Dsearch 0 and no grnd_ID1 holds no node there).
  std::vector<std::uint8_t> mark(n.n_nodes, 0);
  const auto* g1 = node_group_of(ctx, c, {"grnd_ID1", "grnod_id1", "grnd1", "grnd_id1"}, true);
  if (g1)
    for (Index i : *g1) mark[static_cast<std::size_t>(i)] = 1;
  const double reach = dsearch > 0 ? dsearch : -1.0;
  if (reach >= 0)
    for (std::size_t i = 0; i < n.n_nodes; ++i) {
      const double d = dot(contact::V3{n.x0.x[i], n.x0.y[i], n.x0.z[i]} - p.point, p.normal);
      if (d >= 0 && d <= reach && n.mass0[i] > 0) mark[i] = 1;
    }
  if (const auto* g2 = node_group_of(ctx, c, {"grnd_ID2", "grnod_id2", "grnd2", "grnd_id2"}, true))
    for (Index i : *g2) mark[static_cast<std::size_t>(i)] = 0;
  if (p.wall_node != kNoIndex) mark[static_cast<std::size_t>(p.wall_node)] = 0;
  // Secondaries of rigid bodies go to their body (RigidWallPlane header); other
  // dependent nodes (TYPE2 secondaries) cannot take a wall condition and are left out.
  std::vector<Index> sec;
  std::size_t n_dependent = 0, n_body = 0;
  for (std::size_t i = 0; i < n.n_nodes; ++i) {
    if (!mark[i]) continue;
    if (!n.is_secondary[i]) sec.push_back(static_cast<Index>(i));
    else mark[i] = 2;
  }
  std::vector<std::pair<rigid::WallContactBody*, std::vector<std::size_t>>> on_bodies;
  for (const auto& k : ctx.model().constraints) {
    auto* body = dynamic_cast<rigid::WallContactBody*>(k.get());
    if (!body) continue;
    std::vector<std::size_t> js;
    const std::vector<Index>& bs = body->secondary_nodes();
    for (std::size_t j = 0; j < bs.size(); ++j)
      if (mark[static_cast<std::size_t>(bs[j])] == 2) {
        js.push_back(j);
        mark[static_cast<std::size_t>(bs[j])] = 3;
      }
    n_body += js.size();
    if (!js.empty()) on_bodies.emplace_back(body, std::move(js));
  }
  for (std::size_t i = 0; i < n.n_nodes; ++i) n_dependent += mark[i] == 2;
  if (n_body > 0 && p.wall_node != kNoIndex) {
    ctx.error(c, *node_ref.row, node_ref.spec->name,
              "moving rigid wall with " + std::to_string(n_body) +
                  " rigid-body (/RBODY) secondary nodes is not supported (use a fixed wall, or remove them "
                  "with grnd_ID2)");
    return;
  }
  if (n_dependent > 0)
    ctx.warning(c, std::to_string(n_dependent) +
                       " secondary nodes are dependent nodes of a /INTER/TYPE2 tie and are left out of the wall");
  if (sec.empty() && n_body == 0)
    ctx.warning(c, dsearch > 0 || g1 ? "rigid wall has no secondary node (grnd_ID1 empty and none within Dsearch)"
                                     : "rigid wall has no secondary node: Dsearch = 0 and no grnd_ID1 (as in "
                                       "OpenRadioss; give a node group or a search distance)");
  auto wall = std::make_unique<contact::RigidWallPlane>(p, std::move(sec));
  for (auto& [body, js] : on_bodies) wall->add_body(*body, js);
  ctx.add_constraint(std::move(wall));
}

}  // namespace

void build_contacts(BuildContext& ctx) {
  const hbm::deck::Deck& d = ctx.starter();
  for (std::string_view kw : {"/SURF/PART", "/SURF/SEG", "/INTER/TYPE7", "/INTER/TYPE2", "/RWALL/PLANE"})
    ctx.claim(kw);
  const bool any = !d.cards_of("/INTER/TYPE7").empty() || !d.cards_of("/INTER/TYPE2").empty() ||
                   !d.cards_of("/SURF/PART").empty() || !d.cards_of("/SURF/SEG").empty();
  if (any) {
    const contact::ModelSurfaces geo(ctx);
    const SurfaceTable surfs = read_surfaces(ctx, geo);
    for (const Card* c : d.cards_of("/INTER/TYPE7")) build_type7(ctx, *c, surfs, geo);
    for (const Card* c : d.cards_of("/INTER/TYPE2")) build_type2(ctx, *c, surfs);
  }
  for (const Card* c : d.cards_of("/RWALL/PLANE")) build_rwall(ctx, *c);
}

}  // namespace hbm::solver
