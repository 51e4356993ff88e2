// SPDX-License-Identifier: GPL-3.0-or-later
// Builder of solid groups: /BRICK and /TETRA4 cards, one group per (keyword, part),
// material LAW1/2/34/36 from the part, hourglass and bulk viscosity from /PROP/TYPE14.
// Lumped mass rho V0 / n per element node. Registered in solver/src/build/builders.def.
#include "hbm/solver/build_context.hpp"
#include "material/law2_card.hpp"
#include "material/law36_card.hpp"
#include "solid/brick_ha8_group.hpp"
#include "solid/solid_group.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <string>

namespace hbm::solver {

namespace {

// Solid material from the part's /MAT card; false (error recorded) if unusable.
bool read_solid_material(BuildContext& ctx, const hbm::deck::Card& m, SolidMaterial& out) {
  const std::string_view kw = m.keyword();
  out.id = m.id;
  out.rho = m.real(0, "rho");
  if (kw == "/MAT/LAW1") {
    out.law = SolidLaw::Elastic;
    out.set_elastic(m.real(1, "E"), m.real(1, "nu"));
  } else if (kw == "/MAT/LAW2") {
    out.law = SolidLaw::JohnsonCook;
    out.set_elastic(m.real(1, "E"), m.real(1, "nu"));
    if (!read_law2_hardening(ctx, m, out.plasticity)) return false;
  } else if (kw == "/MAT/LAW34") {
    out.law = SolidLaw::Viscoelastic;
    const double G0 = m.real(2, "G0"), Ginf = m.real(2, "Ginf");
    if (Ginf > G0) {
      ctx.error(m, "Ginf must not exceed G0");
      return false;
    }
    if (m.real(3, "P0") != 0.0) {
      ctx.error(m, "foam air pressure P0 != 0 is not supported (tissue: 0)");
      return false;
    }
    out.set_viscoelastic(m.real(1, "K"), G0, Ginf, m.real(2, "beta"));
  } else if (kw == "/MAT/LAW36") {
    out.law = SolidLaw::Tabulated;
    out.set_elastic(m.real(1, "E"), m.real(1, "nu"));
    if (!read_law36_hardening(ctx, m, out.plasticity)) return false;
  } else {
    ctx.error(m, std::string("material ") + std::string(kw) + " is not supported on solid elements (LAW1, LAW2, LAW34, LAW36)");
    return false;
  }
  return true;
}

bool read_solid_property(BuildContext& ctx, const Part& part, int nodes_per_element, SolidGroup& g) {
  // Isolid 0 (and no property) is Isolid 1 for every material, as OpenRadioss reads it
  // (hm_read_prop14.F: IHBE 0 -> the /DEF_SOLID value, 1 by default); the physical form is
  // Isolid 24, written out (until 2026-11-24 LAW34 took it by default here).
  g.hourglass = HourglassForm::Viscous;
  const hbm::deck::Card* p = part.prop_card;
  if (!p) return true;
  if (p->keyword() != "/PROP/TYPE14") {
    ctx.error(*part.part_card, std::string("property ") + std::string(p->keyword()) + " of part " +
                                   std::to_string(part.id) + " is not a solid property (/PROP/TYPE14)");
    return false;
  }
  const auto isolid = p->integer(0, "Isolid");
  switch (isolid) {
    case 0: break;
    case 1: g.hourglass = HourglassForm::Viscous; break;
    case 2: g.hourglass = HourglassForm::Stiffness; break;
    case 14: break;  // bricks: BrickHa8Group (is_ha8); tetras: no hourglass (Itetra4 below)
    case 24: g.hourglass = HourglassForm::Physical; break;
    default:
      ctx.error(*p, p->lines.at(0), "Isolid",
                "Isolid = " + std::to_string(isolid) +
                    " not supported (0, 1 viscous, 2 stiffness, 14 HA8 full integration, 24 physical)");
      return false;
  }
  // Itetra4 (4-node tetras; OpenRadioss: 0 = 1000 standard one-point tetra, 3 the smoothed
  // tetra of solide4_sfem): 3 = average nodal pressure here (nodal_pressure_average.hpp).
  const auto itetra4 = nodes_per_element == 4 ? p->integer(0, "Itetra4") : 0;  // bricks: ignored
  if (itetra4 != 0 && itetra4 != 3) {
    ctx.error(*p, p->lines.at(0), "Itetra4",
              "Itetra4 = " + std::to_string(itetra4) + " not supported (0 constant strain, 3 average nodal pressure)");
    return false;
  }
  g.nodal_pressure.enabled = itetra4 == 3;
  g.icpre = static_cast<int>(p->integer(0, "Icpre"));
  g.qa = p->real(1, "qa");
  g.qb = p->real(1, "qb");
  // OpenRadioss hm_read_prop14.F: Isolid 24 takes the coefficient of its viscous part from
  // dn (0 -> 0.1) and ignores h; Isolid 1 and 2 take h (0 -> 0.1, the field's default).
  if (isolid == 24) {
    const double dn = p->real(0, "dn");
    g.hourglass_coef = dn > 0 ? dn : 0.1;
    if (p->real(1, "h") != 0.1)
      ctx.warning(*p, "h is not used by Isolid 24: its viscous hourglass coefficient is dn (" +
                          std::to_string(g.hourglass_coef) + "), as in OpenRadioss");
  } else {
    g.hourglass_coef = p->real(1, "h");
  }
  return true;
}

// Elements of one part into group g (SolidGroup or BrickHa8Group): connectivity, V0 and
// mass, lumped nodal masses rho V0 / n; the group is added to the model.
template <class Group>
void fill_group(BuildContext& ctx, std::string_view kw, Index part,
                const std::vector<const hbm::deck::Card*>& cards, std::unique_ptr<Group> g) {
  const int npe = kw == "/BRICK" ? 8 : 4;
  g->keyword = std::string(kw);
  g->part = part;
  g->nodes_per_element = static_cast<std::size_t>(npe);
  bool ok = true;
  for (const hbm::deck::Card* c : cards)
    for (std::size_t r = 0; r < c->n_rows(); ++r) {
      const auto& row = c->row(r);
      g->element_id.push_back(c->integer(row, "id"));
      for (int i = 0; i < npe; ++i) {
        std::string field = "n";  // appended in steps: GCC 12 -Wrestrict false positive on "n" + to_string
        field += std::to_string(i + 1);
        const Index n = ctx.require_node(*c, row, field);
        ok = ok && n != kNoIndex;
        g->connectivity.push_back(n);
      }
    }
  if (!ok) return;
  g->n_elements = g->element_id.size();
  const Index bad = g->initialize(ctx.nodes());
  if (bad != kNoIndex) {
    ctx.error(*cards.front(), "element " + std::to_string(g->element_id[static_cast<std::size_t>(bad)]) +
                                  " has a non-positive volume (node order?)");
    return;
  }
  double part_mass = 0.0;
  for (std::size_t e = 0; e < g->n_elements; ++e) {
    part_mass += g->mass[e];
    for (int i = 0; i < npe; ++i) ctx.add_nodal_mass(g->connectivity[e * npe + i], g->mass[e] / npe);
  }
  ctx.add_part_mass(part, part_mass);
  ctx.add_group(std::move(g));
}

// Isolid 14 (HA8) on a /PROP/TYPE14 part: 2x2x2 Gauss bricks. Icpre 1 constant pressure
// (mean dilatation), 0 pressure at the Gauss points too (locks as nu -> 1/2, as in
// OpenRadioss); Inpts 222 only. False (error recorded) on unsupported fields.
bool is_ha8(const Part& part) {
  const hbm::deck::Card* p = part.prop_card;
  return p && p->keyword() == "/PROP/TYPE14" && p->integer(0, "Isolid") == 14;
}

bool read_ha8_property(BuildContext& ctx, const Part& part, BrickHa8Group& g) {
  const hbm::deck::Card& p = *part.prop_card;
  const auto icpre = p.integer(0, "Icpre");
  if (icpre != 0 && icpre != 1) {
    ctx.error(p, p.lines.at(0), "Icpre",
              "Icpre = " + std::to_string(icpre) + " not supported with Isolid 14 (0 or 1)");
    return false;
  }
  g.constant_pressure = icpre == 1;
  const auto inpts = p.integer(0, "Inpts");
  if (inpts != 0 && inpts != 222) {
    ctx.error(p, p.lines.at(0), "Inpts",
              "Inpts = " + std::to_string(inpts) + " not supported with Isolid 14 (222: 2x2x2 Gauss)");
    return false;
  }
  g.qa = p.real(1, "qa");
  g.qb = p.real(1, "qb");
  return true;
}

// /DT/BRICK/CST/Iflag of the engine deck (the last one counts, as for /DT/NODA/CST).
// ASP_min (tetra collapse) is not supported: an error, not a silent ignore.
SmallStrainSwitch read_small_strain_switch(BuildContext& ctx) {
  SmallStrainSwitch sw;
  const auto cards = ctx.engine().cards_of("/DT/BRICK/CST");
  for (const hbm::deck::Card* c : cards) {
    sw.enabled = true;
    sw.tsca = c->real(0, "Tsca");
    sw.tmin = c->real(0, "Tmin");
    // Tmin 0: OpenRadioss takes the /DT Tmin then (lectur.F), 0 when none is given (this
    // deck subset has no /DT card), and its time step test (mqviscb.F) never switches a
    // brick; VDEF_min still acts.
    if (sw.tmin == 0.0)
      ctx.warning(*c, "Tmin = 0: the time step never switches a brick to small strain (as in OpenRadioss "
                      "without a /DT Tmin); only VDEF_min can");
    if (c->lines.size() > 1) {
      if (c->real(1, "ASP_min") > 0)
        ctx.error(*c, c->lines.at(1), "ASP_min", "not supported (tetra collapse switch); use 0");
      sw.vdef_min = c->real(1, "VDEF_min");
    }
  }
  return sw;
}

}  // namespace

void build_solid_groups(BuildContext& ctx) {
  const SmallStrainSwitch small_strain = read_small_strain_switch(ctx);
  for (std::string_view kw : {"/BRICK", "/TETRA4"}) {
    ctx.claim(kw);
    const int npe = kw == "/BRICK" ? 8 : 4;
    // Cards of one part are merged into one group, parts in order of first appearance.
    std::map<std::int64_t, std::vector<const hbm::deck::Card*>> by_part;
    std::vector<std::int64_t> order;
    for (const hbm::deck::Card* c : ctx.starter().cards_of(kw)) {
      if (!by_part.count(c->id)) order.push_back(c->id);
      by_part[c->id].push_back(c);
    }
    for (std::int64_t part_id : order) {
      const auto& cards = by_part[part_id];
      const Index part = ctx.part_index(part_id);
      if (part == kNoIndex) {
        ctx.error(*cards.front(), "no part " + std::to_string(part_id));
        continue;
      }
      const Part& p = ctx.part(part);
      if (npe == 8 && is_ha8(p)) {
        auto h = std::make_unique<BrickHa8Group>();
        if (!p.mat_card || !read_solid_material(ctx, *p.mat_card, h->material)) continue;
        if (!read_ha8_property(ctx, p, *h)) continue;
        h->small_strain = small_strain;
        fill_group(ctx, kw, part, cards, std::move(h));
        continue;
      }
      auto g = std::make_unique<SolidGroup>();
      if (!p.mat_card || !read_solid_material(ctx, *p.mat_card, g->material)) continue;
      if (!read_solid_property(ctx, p, npe, *g)) continue;
      g->small_strain = small_strain;
      fill_group(ctx, kw, part, cards, std::move(g));
    }
  }
}

}  // namespace hbm::solver
