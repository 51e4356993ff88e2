// SPDX-License-Identifier: GPL-3.0-or-later
// Builder of spring groups: /SPRING elements, one group per part, property /PROP/TYPE4
// (axial), /PROP/TYPE8 (general 6-DOF) or /PROP/TYPE13 (beam-type). Reads each DOF's law
// (K C A B D / fct_id1 H fct_id2 fct_id3 fct_id4 dmin dmax / F E Ascale Hscale), resolves
// its /FUNCT curves, adds half the spring mass (and inertia) to each node. Registered in
// solver/src/build/builders.def.
//
// Card layouts (Radioss 2024, deck/src/keywords_model.cpp): TYPE4 line 1 `Mass sens_id
// Isflag Ileng`, then one DOF block; TYPE13 line 1 `Mass Inertia skew_id sens_id Isflag
// Ifail Ileng Ifail2` (TYPE8: `... Ifail Ifail2 Iequil`), then six DOF blocks (X, Y, Z,
// RX, RY, RZ), each three lines, fields numbered per DOF (K1, fct_ID11, ...). Not supported
// (deck error naming the field): sensors, skews, H = 3, 5, 6, per-length input on a
// zero-length spring.
#include "hbm/solver/build_context.hpp"
#include "springs/spring_group_factory.hpp"

#include <cmath>
#include <map>
#include <string>

namespace hbm::solver {

namespace {

using springs::CurveView;
using springs::SpringDofLaw;
using springs::SpringProperty;
using springs::SpringType;

const hbm::deck::Row& line_or_last(const hbm::deck::Card& c, std::size_t k) {
  return c.lines.size() > k ? c.lines[k] : c.lines.back();
}

CurveView view_of(const FunctionCurve* f) {
  if (!f) return {};
  return {f->x().data(), f->y().data(), f->n_points()};
}

// Field names of one DOF block: TYPE4 uses K, C, ..., fct_id1 ...; TYPE8/13 number them
// per DOF (K1..K6, fct_ID11..fct_ID16, ...) as in the Radioss reference guide.
struct DofNames {
  std::string K, C, A, B, D, f1, H, f2, f3, f4, dmin, dmax, F, E, Ascale, Hscale;
};
DofNames dof_names(bool axial, std::size_t d) {
  if (axial)
    return {"K", "C", "A", "B", "D", "fct_id1", "H", "fct_id2", "fct_id3", "fct_id4",
            "dmin", "dmax", "F", "E", "Ascale", "Hscale"};
  const std::string i = std::to_string(d + 1);
  return {"K" + i, "C" + i, "A" + i, "B" + i, "D" + i, "fct_ID1" + i, "H" + i, "fct_ID2" + i,
          "fct_ID3" + i, "fct_ID4" + i, "dmin" + i, "dmax" + i, "F" + i, "E" + i,
          "Ascale" + i, "Hscale" + i};
}

// One DOF block starting at fixed line `k` (K line), `k+1` (functions), `k+2` (scales).
bool read_dof(BuildContext& ctx, const hbm::deck::Card& c, std::size_t k, const DofNames& n,
              SpringDofLaw& law) {
  bool ok = true;
  // A, D, F, E, Ascale, Hscale: 0 or blank read as 1 (the deck library's zero_is_default,
  // as OpenRadioss's hm_read_prop04/08/13.F read them).
  law.K = c.real(k, n.K);
  law.C = c.real(k, n.C);
  law.A = c.real(k, n.A);
  law.B = c.real(k, n.B);
  law.D = c.real(k, n.D);
  const int h = static_cast<int>(c.integer(k + 1, n.H));
  law.delta_min = c.real(k + 1, n.dmin);
  law.delta_max = c.real(k + 1, n.dmax);
  law.Fv = c.real(k + 2, n.F);
  law.E = c.real(k + 2, n.E);
  law.Ascale = c.real(k + 2, n.Ascale);
  law.Hscale = c.real(k + 2, n.Hscale);
  const bool has_line = c.lines.size() > k + 1;
  const hbm::deck::Row& fl = line_or_last(c, k + 1);
  auto fn = [&](const std::string& field) -> CurveView {
    if (!has_line || c.integer(fl, field) == 0) return {};
    const FunctionCurve* f = ctx.require_function(c, fl, field, true);
    if (!f) ok = false;
    return view_of(f);
  };
  law.f1 = fn(n.f1);
  law.g2 = fn(n.f2);
  law.f3 = fn(n.f3);
  law.h4 = fn(n.f4);
  if (!springs::is_supported_hardening(h)) {
    ctx.error(c, fl, n.H, "hardening flag H = " + std::to_string(h) +
                              " is not supported (0, 1, 2, 4, 7, 8 are)");
    return false;
  }
  law.H = static_cast<springs::Hardening>(h);
  if (h != 0 && law.f1.empty()) {
    ctx.error(c, fl, n.f1, "H = " + std::to_string(h) + " needs a loading function fct_id1");
    ok = false;
  }
  if ((h == 4 || h == 7) && law.f3.empty()) {
    ctx.error(c, fl, n.f3, "H = " + std::to_string(h) + " needs the " +
                                    (h == 4 ? "lower yield" : "unloading") + " function fct_id3");
    ok = false;
  }
  if ((h == 1 || h == 2 || h == 4 || h == 7) && !(law.K > 0)) {
    ctx.error(c, line_or_last(c, k), n.K, "H = " + std::to_string(h) +
                                              " needs the unloading stiffness K > 0");
    ok = false;
  }
  if (law.B != 0 && !(law.D > 0)) {
    ctx.error(c, line_or_last(c, k), n.D, "the logarithmic rate term needs D > 0");
    ok = false;
  }
  return ok;
}

// Resolve a /PROP/TYPE4, 8 or 13 card.
bool read_property(BuildContext& ctx, const hbm::deck::Card& c, SpringProperty& p) {
  const std::string_view kw = c.keyword();
  p.id = c.id;
  p.title = c.title;
  p.type = kw == "/PROP/TYPE4" ? SpringType::Axial : kw == "/PROP/TYPE8" ? SpringType::General : SpringType::Beam;
  bool ok = true;
  p.mass = c.real(0, "Mass");
  if (c.integer(0, "sens_id") != 0) {
    ctx.error(c, c.lines.at(0), "sens_id", "spring activation by sensor is not supported (use 0)");
    ok = false;
  }
  // TYPE8 has no Ileng field (its line 1 ends with Ifail2, Iequil).
  p.per_length = p.type != SpringType::General && c.integer(0, "Ileng") == 1;
  if (p.type == SpringType::Axial) {
    p.dofs.resize(1);
    ok = read_dof(ctx, c, 1, dof_names(true, 0), p.dofs[0]) && ok;
  } else {
    p.inertia = c.real(0, "Inertia");
    if (c.integer(0, "skew_id") != 0) {
      ctx.error(c, c.lines.at(0), "skew_id", "skew frames are not supported (use 0: global axes)");
      ok = false;
    }
    // Failure variants beyond the uni-directional displacement criterion, and TYPE8's
    // moment-equilibrium option, are not implemented: refuse rather than ignore them.
    std::vector<std::string> unsupported{"Ifail", "Ifail2"};
    if (p.type == SpringType::General) unsupported.push_back("Iequil");
    for (const std::string& f : unsupported)
      if (c.integer(0, f) != 0) {
        ctx.error(c, c.lines.at(0), f, f + " = " + std::to_string(c.integer(0, f)) +
                                           " is not supported (use 0)");
        ok = false;
      }
    p.dofs.resize(6);
    for (std::size_t d = 0; d < 6; ++d) ok = read_dof(ctx, c, 1 + 3 * d, dof_names(false, d), p.dofs[d]) && ok;
    const bool rot = p.type == SpringType::Beam || springs::has_rotational_law(p);
    // OpenRadioss (hm_read_prop08.F, hm_read_prop13.F): an inertia <= 1e-20 becomes 1e-20,
    // with its warning 445 (NULL INERTIA). Half of it goes to each node.
    if (p.inertia <= 1e-20) {
      p.inertia = 1e-20;
      if (rot)
        ctx.warning(c, "Inertia <= 1e-20 is set to 1e-20, as in OpenRadioss (its warning 445, NULL INERTIA): the "
                       "rotations of the spring's nodes then take their inertia from /DT/NODA/CST or need a tiny "
                       "time step");
    }
  }
  return ok;
}

struct PendingGroup {
  const hbm::deck::Card* first_card = nullptr;
  std::vector<Index> connectivity;
  std::vector<std::int64_t> ids;
  std::vector<Index> orientation;  // n3 per element, kNoIndex if blank
};

}  // namespace

void build_spring_groups(BuildContext& ctx) {
  ctx.claim("/SPRING");
  std::map<Index, PendingGroup> by_part;  // ordered by part index: deterministic groups
  for (const hbm::deck::Card* c : ctx.starter().cards_of("/SPRING")) {
    const Index part = ctx.part_index(c->id);
    if (part == kNoIndex) {
      ctx.error(*c, "no part " + std::to_string(c->id));
      continue;
    }
    const Part& p = ctx.part(part);
    const std::string_view pk = p.prop_card ? p.prop_card->keyword() : std::string_view{};
    if (pk != "/PROP/TYPE4" && pk != "/PROP/TYPE8" && pk != "/PROP/TYPE13") {
      ctx.error(*c, "part " + std::to_string(p.id) + " of spring elements needs a /PROP/TYPE4, "
                    "/PROP/TYPE8 or /PROP/TYPE13 property (has " +
                    (pk.empty() ? std::string("none") : std::string(pk)) + ")");
      continue;
    }
    PendingGroup& g = by_part[part];
    if (!g.first_card) g.first_card = c;
    for (std::size_t r = 0; r < c->n_rows(); ++r) {
      const hbm::deck::Row& row = c->row(r);
      const Index n1 = ctx.require_node(*c, row, "n1");
      const Index n2 = ctx.require_node(*c, row, "n2");
      if (c->integer(row, "skew_id") != 0)
        ctx.error(*c, row, "skew_id", "skew frames are not supported (use 0)");
      if (n1 == kNoIndex || n2 == kNoIndex) continue;
      if (n1 == n2) {
        ctx.error(*c, row, "n2", "spring " + std::to_string(c->integer(row, "id")) + " joins node " +
                                     std::to_string(c->integer(row, "n1")) + " to itself");
        continue;
      }
      Index n3 = kNoIndex;
      if (c->integer(row, "n3") != 0) {
        if (pk != "/PROP/TYPE13") {
          ctx.warning(*c, "spring " + std::to_string(c->integer(row, "id")) +
                              ": orientation node n3 is used by /PROP/TYPE13 only; ignored for " + std::string(pk));
        } else {
          n3 = ctx.require_node(*c, row, "n3");
          if (n3 == kNoIndex) continue;
          const NodalState& xs = ctx.nodes();
          const auto a = static_cast<std::size_t>(n1), b = static_cast<std::size_t>(n2),
                     k3 = static_cast<std::size_t>(n3);
          const double ux = xs.x0.x[b] - xs.x0.x[a], uy = xs.x0.y[b] - xs.x0.y[a], uz = xs.x0.z[b] - xs.x0.z[a];
          const double wx = xs.x0.x[k3] - xs.x0.x[a], wy = xs.x0.y[k3] - xs.x0.y[a], wz = xs.x0.z[k3] - xs.x0.z[a];
          const double cx = uy * wz - uz * wy, cy = uz * wx - ux * wz, cz = ux * wy - uy * wx;
          const double lu = std::sqrt(ux * ux + uy * uy + uz * uz), lw = std::sqrt(wx * wx + wy * wy + wz * wz);
          if (!(std::sqrt(cx * cx + cy * cy + cz * cz) > 1e-6 * lu * lw)) {
            ctx.error(*c, row, "n3", "orientation node " + std::to_string(c->integer(row, "n3")) +
                                         " lies on the axis n1-n2 of spring " + std::to_string(c->integer(row, "id")));
            continue;
          }
        }
      }
      g.connectivity.push_back(n1);
      g.connectivity.push_back(n2);
      g.ids.push_back(c->integer(row, "id"));
      g.orientation.push_back(n3);
    }
  }
  std::map<std::int64_t, SpringProperty> props;
  for (auto& [part, pending] : by_part) {
    const Part& p = ctx.part(part);
    auto it = props.find(p.prop_id);
    if (it == props.end()) {
      SpringProperty sp;
      if (!read_property(ctx, *p.prop_card, sp)) continue;
      it = props.emplace(p.prop_id, std::move(sp)).first;
    }
    const SpringProperty& sp = it->second;
    NodalState& nodes = ctx.nodes();
    auto group = springs::make_spring_group(sp, part, pending.connectivity, pending.ids, nodes,
                                            &pending.orientation);
    group->part_title = p.title;
    bool ok = true;
    for (std::size_t e = 0; e < group->n_elements; ++e) {
      const double l0 = group->length0[e];
      const bool zero = !(l0 > 0);
      if (zero && (sp.type == SpringType::Axial || sp.type == SpringType::Beam || sp.per_length)) {
        ctx.error(*pending.first_card,
                  "spring " + std::to_string(group->element_id[e]) + " has zero initial length: " +
                      (sp.type == SpringType::General
                           ? "per-length input (Ileng = 1) needs a length"
                           : "its axis is undefined (use /PROP/TYPE8 for coincident nodes)"));
        ok = false;
        continue;
      }
      const auto share = springs::spring_nodal_share(sp, l0);
      for (int k = 0; k < 2; ++k) {
        const Index n = group->connectivity[2 * e + static_cast<std::size_t>(k)];
        ctx.add_nodal_mass(n, share.mass);
        if (group->has_rotation_slots()) ctx.add_nodal_inertia(n, share.inertia);
      }
      ctx.add_part_mass(part, 2.0 * share.mass);
    }
    if (ok) ctx.add_group(std::move(group));
  }
}

}  // namespace hbm::solver
