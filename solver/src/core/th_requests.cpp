// SPDX-License-Identifier: GPL-3.0-or-later
// /TH/... cards -> ThGroups (see th_requests.hpp for the variables).
#include "core/th_requests.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace hbm::solver {

namespace {

using hbm::deck::Dimension;

std::string upper_trim(std::string s) {
  const auto b = s.find_first_not_of(' ');
  if (b == std::string::npos) return {};
  s = s.substr(b, s.find_last_not_of(' ') - b + 1);
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::optional<ThProbe> node_probe(const Model& m, Index node, const std::string& title, const std::string& var) {
  const NodalState* n = &m.nodes;
  const Model* mp = &m;
  const auto i = static_cast<std::size_t>(node);
  ThProbe p{"node", n->user_id[i], title, var, Dimension::Length, {}};
  static const std::string axes = "XYZ";
  if (var.size() == 2 && axes.find(var[1]) != std::string::npos) {
    const int d = static_cast<int>(axes.find(var[1]));
    auto pick = [d](const Vec3Soa& v, std::size_t k) { return d == 0 ? v.x[k] : d == 1 ? v.y[k] : v.z[k]; };
    if (var[0] == 'D') {
      p.read = [n, i, pick] { return pick(n->x, i) - pick(n->x0, i); };
      return p;
    }
    if (var[0] == 'V') {
      p.unit = Dimension::Velocity;
      p.read = [n, i, pick, mp] { return pick(n->v, i) - 0.5 * mp->dt_output * pick(n->a, i); };
      return p;
    }
    if (var[0] == 'A') {
      p.unit = Dimension::Acceleration;
      p.read = [n, i, pick] { return pick(n->a, i); };
      return p;
    }
  }
  if (var.size() == 1 && axes.find(var[0]) != std::string::npos) {
    const int d = static_cast<int>(axes.find(var[0]));
    p.read = [n, i, d] { return d == 0 ? n->x.x[i] : d == 1 ? n->x.y[i] : n->x.z[i]; };
    return p;
  }
  return std::nullopt;
}

// Element-lumped part quantities (KE, momentum, centre of gravity): each node of an element
// of the part carries its mass shared among the element slots at it (its element count over
// all parts), so that the parts' sums add up to the nodes' total. Calls f(node, 1 / slots).
template <class F>
void for_each_slot(const std::vector<const ElementGroup*>& groups, const Model& m, F&& f) {
  for (auto* g : groups)
    for (std::size_t k = 0; k < g->connectivity.size(); ++k) {
      const auto i = static_cast<std::size_t>(g->connectivity[k]);
      f(i, 1.0 / static_cast<double>(m.incidence_start[i + 1] - m.incidence_start[i]));
    }
}

// Velocity at the output time from the half-step velocity and the acceleration.
std::array<double, 3> output_velocity(const Model& m, std::size_t i) {
  const NodalState& n = m.nodes;
  const double h = 0.5 * m.dt_output;
  return {n.v.x[i] - h * n.a.x[i], n.v.y[i] - h * n.a.y[i], n.v.z[i] - h * n.a.z[i]};
}

std::optional<ThProbe> part_probe(const Model& m, Index part, const std::string& var) {
  const Part& pt = m.parts[static_cast<std::size_t>(part)];
  ThProbe p{"part", pt.id, pt.title, var, Dimension::Energy, {}};
  std::vector<const ElementGroup*> groups;
  for (const auto& g : m.groups)
    if (g->part == part) groups.push_back(g.get());
  const Model* mp = &m;
  const Part* pp = &pt;
  if (var == "IE") {
    p.read = [groups] { double s = 0; for (auto* g : groups) s += g->energy.internal; return s; };
  } else if (var == "HE") {
    p.read = [groups] { double s = 0; for (auto* g : groups) s += g->energy.hourglass; return s; };
  } else if (var == "KE") {
    p.read = [groups, mp] {
      double s = 0;
      for_each_slot(groups, *mp, [&](std::size_t i, double share) {
        const auto v = output_velocity(*mp, i);
        s += 0.5 * mp->nodes.mass[i] * share * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      });
      return s;
    };
  } else if (var == "XMOM" || var == "YMOM" || var == "ZMOM") {
    // With the mass the run integrates (added mass included), lumped as KE, so the parts'
    // momenta add up to the nodes' total. A rigid body's main node is in no part.
    p.unit = Dimension::Momentum;
    const int d = var[0] - 'X';
    p.read = [groups, mp, d] {
      double s = 0;
      for_each_slot(groups, *mp, [&](std::size_t i, double share) {
        s += mp->nodes.mass[i] * share * output_velocity(*mp, i)[d];
      });
      return s;
    };
  } else if (var == "XCG" || var == "YCG" || var == "ZCG") {
    // Weighted by the physical lumped mass, with the lumping of KE and momentum.
    p.unit = Dimension::Length;
    const int d = var[0] - 'X';
    p.read = [groups, mp, d] {
      const NodalState& n = mp->nodes;
      double s = 0, w = 0;
      for_each_slot(groups, *mp, [&](std::size_t i, double share) {
        const double mi = n.mass0[i] * share;
        s += mi * (d == 0 ? n.x.x[i] : d == 1 ? n.x.y[i] : n.x.z[i]);
        w += mi;
      });
      return w > 0 ? s / w : 0.0;
    };
  } else if (var == "MASS") {
    // Radioss: the part's mass without the mass added by mass scaling.
    p.unit = Dimension::Mass;
    p.read = [pp] { return pp->mass0; };
  } else if (var == "AM") {
    p.unit = Dimension::Mass;
    p.read = [pp] { return pp->added_mass; };
  } else if (var == "M") {
    p.unit = Dimension::Mass;
    p.read = [pp] { return pp->mass0 + pp->added_mass; };
  } else if (var == "ER") {
    p.unit = Dimension::Count;
    p.read = [groups] { double s = 0; for (auto* g : groups) s += static_cast<double>(g->n_eroded); return s; };
  } else {
    return std::nullopt;
  }
  return p;
}

ThKind kind_of(std::string_view kw) {
  if (kw == "/TH/NODE") return ThKind::Node;
  if (kw == "/TH/PART") return ThKind::Part;
  if (kw == "/TH/SPRING") return ThKind::Spring;
  if (kw == "/TH/INTER") return ThKind::Inter;
  if (kw == "/TH/RBODY") return ThKind::Rbody;
  return ThKind::Rwall;
}

}  // namespace

void build_th_groups(BuildContext& ctx) {
  Model& m = ctx.model();
  const hbm::deck::Deck& d = ctx.starter();
  for (std::string_view kw : {"/TH/NODE", "/TH/PART", "/TH/SPRING", "/TH/INTER", "/TH/RBODY", "/TH/RWALL"}) {
    ctx.claim(kw);
    const ThKind kind = kind_of(kw);
    for (const hbm::deck::Card* c : d.cards_of(kw)) {
      ThGroup g;
      g.keyword = std::string(kw);
      g.id = c->id;
      g.title = c->title;
      std::vector<std::string> vars;
      for (std::size_t r = 0; r < c->n_name_rows(); ++r)
        for (int k = 1; k <= 10; ++k) {
          const std::string v = upper_trim(d.text(*c, c->name_row(r), "var" + std::to_string(k)));
          if (!v.empty()) vars.push_back(v);
        }
      auto expand = [&](const std::vector<std::string>& defaults) {
        std::vector<std::string> out;
        for (const auto& v : vars) {
          if (v == "DEF")
            out.insert(out.end(), defaults.begin(), defaults.end());
          else
            out.push_back(v);
        }
        return out;
      };
      if (kind == ThKind::Node) {
        const auto list = expand({"DX", "DY", "DZ", "VX", "VY", "VZ", "AX", "AY", "AZ"});
        for (std::size_t r = 0; r < c->n_rows(); ++r) {
          const auto& row = c->row(r);
          const Index node = ctx.require_node(*c, row, "node_id");
          if (node == kNoIndex) continue;
          std::string name = d.text(*c, row, "name");
          name = name.substr(0, name.find_last_not_of(' ') + 1);
          name = name.substr(std::min(name.size(), name.find_first_not_of(' ')));
          for (const auto& v : list) {
            auto p = node_probe(m, node, name, v);
            if (p) g.columns.push_back(std::move(*p));
            else ctx.error(*c, "unknown /TH/NODE variable '" + v + "'");
          }
        }
      } else {
        for (std::size_t r = 0; r < c->n_rows(); ++r)
          for (int k = 1; k <= 10; ++k) {
            const std::string f = "id" + std::to_string(k);
            const std::int64_t id = c->integer(c->row(r), f);
            if (id == 0) continue;
            if (kind == ThKind::Part) {
              const Index part = ctx.part_index(id);
              if (part == kNoIndex) {
                ctx.error(*c, c->row(r), f, "no part " + std::to_string(id));
                continue;
              }
              for (const auto& v : expand({"IE", "KE", "XMOM", "YMOM", "ZMOM", "MASS", "HE", "AM"})) {
                auto p = part_probe(m, part, v);
                if (p) g.columns.push_back(std::move(*p));
                else ctx.error(*c, "unknown /TH/PART variable '" + v + "'");
              }
              continue;
            }
            // Other kinds: the first owner of the object answers.
            std::vector<const ThSource*> owners;
            for (const auto& x : m.groups) owners.push_back(x.get());
            for (const auto& x : m.interactions) owners.push_back(x.get());
            for (const auto& x : m.constraints) owners.push_back(x.get());
            const ThSource* owner = nullptr;
            for (const ThSource* o : owners)
              if (o->owns_th_object(kind, id)) {
                owner = o;
                break;
              }
            if (!owner) {
              ctx.error(*c, c->row(r), f, "no object " + std::to_string(id) + " for " + std::string(kw));
              continue;
            }
            std::vector<std::string> list;
            for (const auto& v : vars) {
              if (v == "DEF") {
                const auto defs = owner->th_default_variables(kind);
                list.insert(list.end(), defs.begin(), defs.end());
              } else {
                list.push_back(v);
              }
            }
            for (const auto& v : list) {
              auto p = owner->th_probe(kind, id, v);
              if (p) g.columns.push_back(std::move(*p));
              else ctx.error(*c, "unknown " + std::string(kw) + " variable '" + v + "' for object " + std::to_string(id));
            }
          }
      }
      m.th_groups.push_back(std::move(g));
    }
  }
}

}  // namespace hbm::solver
