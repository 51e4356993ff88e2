// SPDX-License-Identifier: GPL-3.0-or-later
// Builder of shell groups: /SHELL (4-node Belytschko-Tsay) and /SH3N (3-node CST+DKT)
// cards, one group per (keyword, part); material from the part (/MAT/LAW1, LAW2, LAW34,
// LAW36, plane stress), section from /PROP/TYPE1:
//   line 1  Ishell (0-4: Belytschko-Tsay; others are refused), Ish3n (0, 1, 2, 30, 31:
//           CST+DKT), Idrill (0; 1 accepted with a warning: no drilling stiffness),
//           Ipinch (0 only),
//           P_thick_fail (fraction of the N points that must fail to delete the shell;
//           0 = all points),
//   line 2  Hm Hf Hr (hourglass, 0 -> 0.01, Hm Hf 0.1 for Ishell 3, as OpenRadioss),
//           Dm Dn (must be 0),
//   line 3  N (0 -> 5; 1 = membrane), Thick, Ashear (0 -> 5/6), Ithick (1: thickness
//           follows the membrane strain), Iplas (plane-stress return is always iterative),
//           Ipos (0 only: mid-surface).
// Thickness per element: the element row's thick if > 0, else the /PART thick if > 0,
// else the property's. Lumped mass rho t A / npe and rotational inertia
// m (t^2 + A) / 12 per node; shell nodes carry rotational DOFs.
// Registered in solver/src/build/builders.def.
#include "hbm/solver/build_context.hpp"
#include "material/law2_card.hpp"
#include "material/law36_card.hpp"
#include "shells/shell_element_group.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace hbm::solver {

namespace {

using shells::ShellElementGroup;
using shells::ShellLaw;
using shells::ShellMaterial;
using shells::ShellSection;

// Message text by appending (GCC 12 warns falsely, -Wrestrict, on literal + std::string).
template <class... Parts>
std::string cat(const Parts&... parts) {
  std::string s;
  (s.append(std::string_view(parts)), ...);
  return s;
}
std::string num(std::int64_t v) { return std::to_string(v); }

bool read_shell_material(BuildContext& ctx, const hbm::deck::Card& m, ShellMaterial& out) {
  const std::string_view kw = m.keyword();
  out.id = m.id;
  out.rho = m.real(0, "rho");
  if (kw == "/MAT/LAW1") {
    out.law = ShellLaw::Elastic;
    out.E = m.real(1, "E");
    out.nu = m.real(1, "nu");
  } else if (kw == "/MAT/LAW2") {
    out.law = ShellLaw::JohnsonCook;
    out.E = m.real(1, "E");
    out.nu = m.real(1, "nu");
    if (!read_law2_hardening(ctx, m, out.plasticity)) return false;
  } else if (kw == "/MAT/LAW34") {
    out.law = ShellLaw::Viscoelastic;
    out.K = m.real(1, "K");
    out.G0 = m.real(2, "G0");
    out.Ginf = m.real(2, "Ginf");
    out.beta = m.real(2, "beta");
    if (m.real(3, "P0") != 0.0) {
      ctx.error(m, "foam air pressure P0 != 0 is not supported on shells (tissue: 0)");
      return false;
    }
  } else if (kw == "/MAT/LAW42") {
    out.law = ShellLaw::Ogden;
    out.sigma_cut = m.real(1, "sigma_cut");
    for (int p = 0; p < ShellMaterial::kOgdenPairs; ++p) {
      const std::string i = std::to_string(p + 1);
      out.mu[p] = m.real(2, "mu" + i);
      out.alpha[p] = m.real(3, "alpha" + i);
    }
  } else if (kw == "/MAT/LAW36") {
    out.law = ShellLaw::Tabulated;
    out.E = m.real(1, "E");
    out.nu = m.real(1, "nu");
    if (!read_law36_hardening(ctx, m, out.plasticity)) return false;
  } else {
    ctx.error(m, cat("material ", kw, " is not supported on shell elements (LAW1, LAW2, LAW34, LAW36, LAW42)"));
    return false;
  }
  const std::string_view why = out.check();
  if (!why.empty()) {
    ctx.error(m, std::string(why));
    return false;
  }
  return true;
}

bool read_shell_property(BuildContext& ctx, const Part& part, bool tria, ShellSection& s) {
  const hbm::deck::Card* p = part.prop_card;
  if (!p || p->keyword() != "/PROP/TYPE1") {
    ctx.error(*part.part_card,
              cat("part ", num(part.id), " has shell elements: its property must be a /PROP/TYPE1"));
    return false;
  }
  s.prop_id = p->id;
  if (!tria) {
    const auto ishell = p->integer(0, "Ishell");
    if (ishell < 0 || ishell > 4) {
      ctx.error(*p, p->lines.at(0), "Ishell",
                cat("Ishell = ", num(ishell), " not supported (0-4: Belytschko-Tsay with hourglass stiffness)"));
      return false;
    }
  } else {
    const auto ish3n = p->integer(0, "Ish3n");
    if (!(ish3n == 0 || ish3n == 1 || ish3n == 2 || ish3n == 30 || ish3n == 31)) {
      ctx.error(*p, p->lines.at(0), "Ish3n",
                cat("Ish3n = ", num(ish3n), " not supported (0, 1, 2, 30, 31: CST + DKT)"));
      return false;
    }
  }
  if (p->integer(0, "Ipinch") != 0) {
    ctx.error(*p, p->lines.at(0), "Ipinch", "pinching DOF (Ipinch = 1) is not supported");
    return false;
  }
  if (p->integer(2, "Ipos") != 0) {
    ctx.error(*p, p->lines.at(2), "Ipos", "only mid-surface shells (Ipos = 0) are supported");
    return false;
  }
  if (p->integer(0, "Idrill") != 0)
    ctx.warning(*p, "Idrill != 0: shells carry no drilling stiffness (Idrill = 0 behaviour)");
  if (p->integer(0, "Ismstr") != 0)
    ctx.warning(*p, "Ismstr != 0: shells use the large-strain rate formulation");
  auto nonzero_default = [&](std::size_t line, std::string_view f, double def) {
    const double v = p->real(line, f);
    return v > 0 ? v : def;
  };
  // 0 -> OpenRadioss's defaults (hm_read_prop01.F): 0.1, 0.1, 0.01 for Ishell 3, else 0.01.
  const bool ishell3 = p->integer(0, "Ishell") == 3;
  s.hm = nonzero_default(1, "hm", ishell3 ? 0.1 : 0.01);
  s.hf = nonzero_default(1, "hf", ishell3 ? 0.1 : 0.01);
  s.hr = nonzero_default(1, "hr", 0.01);
  if (p->real(1, "dm") != 0.0 || p->real(1, "dn") != 0.0) {
    ctx.error(*p, "membrane / numerical damping Dm, Dn are not supported on shells (give 0)");
    return false;
  }
  auto n = p->integer(2, "N");
  if (n == 0) n = 5;
  if (!s.set_points(static_cast<int>(n))) {
    ctx.error(*p, p->lines.at(2), "N", "N must be 1..10");
    return false;
  }
  s.thickness = p->real(2, "Thick");
  s.shear_factor = nonzero_default(2, "Ashear", 5.0 / 6.0);
  s.thickness_change = p->integer(2, "Ithick") == 1;
  const double pf = p->real(0, "P_thick_fail");
  s.fail_points = pf > 0 ? static_cast<int>(std::ceil(pf * s.n_points - 1e-9)) : 0;
  return true;
}

}  // namespace

// /DT/SHELL/CST (4-node shells, OpenRadioss Eltyp SHELL) or /DT/SH_3N/CST (3-node shells,
// Eltyp SH_3N) of the engine deck, the last one counting as for /DT/NODA/CST: Tsca, Tmin.
// Disabled when absent.
static SmallStrainSwitch read_shell_small_strain_switch(BuildContext& ctx, std::string_view keyword) {
  SmallStrainSwitch sw;
  for (const hbm::deck::Card* c : ctx.engine().cards_of(keyword)) {
    sw.enabled = true;
    sw.tsca = c->real(0, "Tsca");
    sw.tmin = c->real(0, "Tmin");
    // Tmin 0: as /DT/BRICK/CST, OpenRadioss falls back to the /DT Tmin, 0 without one, and
    // its test (cdt3.F, c3dt3.F) never switches a shell.
    if (sw.tmin == 0.0)
      ctx.warning(*c, cat("Tmin = 0: no element switches to small strain under ", keyword,
                          " (as in OpenRadioss without a /DT Tmin)"));
  }
  return sw;
}

void build_shell_groups(BuildContext& ctx) {
  const auto quad_cst = read_shell_small_strain_switch(ctx, "/DT/SHELL/CST");
  const auto tria_cst = read_shell_small_strain_switch(ctx, "/DT/SH_3N/CST");
  for (std::string_view kw : {"/SHELL", "/SH3N"}) {
    ctx.claim(kw);
    const bool tria = kw == "/SH3N";
    const int npe = tria ? 3 : 4;
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
        ctx.error(*cards.front(), cat("no part ", num(part_id)));
        continue;
      }
      const Part& p = ctx.part(part);
      auto g = std::make_unique<ShellElementGroup>();
      g->keyword = std::string(kw);
      g->part = part;
      g->nodes_per_element = static_cast<std::size_t>(npe);
      if (!p.mat_card) {
        ctx.error(*cards.front(), cat("part ", num(part_id), " has no material"));
        continue;
      }
      if (!read_shell_material(ctx, *p.mat_card, g->data.mat)) continue;
      if (!read_shell_property(ctx, p, tria, g->data.sec)) continue;
      const double part_thick = p.part_card ? p.part_card->real(0, "thick") : 0.0;
      bool ok = true;
      for (const hbm::deck::Card* c : cards)
        for (std::size_t r = 0; r < c->n_rows(); ++r) {
          const auto& row = c->row(r);
          g->element_id.push_back(c->integer(row, "id"));
          for (int i = 0; i < npe; ++i) {
            const Index n = ctx.require_node(*c, row, cat("n", num(i + 1)));
            ok = ok && n != kNoIndex;
            g->connectivity.push_back(n);
          }
          const double te = c->real(row, "thick");
          const double t = te > 0 ? te : (part_thick > 0 ? part_thick : g->data.sec.thickness);
          if (!(t > 0)) {
            ctx.error(*c, row, "thick", "shell thickness is 0 (element, part and property)");
            ok = false;
          }
          g->data.thick.push_back(t);
        }
      if (!ok) continue;
      g->n_elements = g->element_id.size();
      g->data.small_strain = tria ? tria_cst : quad_cst;
      const Index bad = g->initialize(ctx.nodes());
      if (bad != kNoIndex) {
        ctx.error(*cards.front(), cat("shell element ", num(g->element_id[static_cast<std::size_t>(bad)]),
                                      " has zero area (coincident nodes?)"));
        continue;
      }
      double part_mass = 0.0;
      for (std::size_t e = 0; e < g->n_elements; ++e) {
        part_mass += g->slot_mass[e] * npe;
        for (int i = 0; i < npe; ++i) {
          const Index n = g->connectivity[e * static_cast<std::size_t>(npe) + static_cast<std::size_t>(i)];
          ctx.add_nodal_mass(n, g->slot_mass[e]);
          ctx.add_nodal_inertia(n, g->slot_inertia[e]);
        }
      }
      ctx.add_part_mass(part, part_mass);
      ctx.add_group(std::move(g));
    }
  }
}

}  // namespace hbm::solver
