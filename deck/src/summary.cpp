// SPDX-License-Identifier: GPL-3.0-or-later
// Model summary (see summary.hpp). Element time steps are the usual explicit estimates
// dt = L / c (before any safety factor):
//   solids: L = volume / largest face area (brick), 3 volume / largest face (tetra),
//           dilatational wave speed c = sqrt(E (1-nu) / ((1+nu)(1-2nu) rho)) for LAW1/2/36,
//           c = sqrt((K + 4/3 G0) / rho) for LAW34;
//   shells: L = area / longest diagonal (quad), 2 area / longest edge (triangle),
//           plane-stress speed c = sqrt(E / ((1 - nu^2) rho)); LAW42 (Ogden, incompressible)
//           with nu = 0.5 and E its stiffest uniaxial tangent up to a stretch of 1.6, as the
//           engine's shells take it (hbm/deck/ogden_law.hpp, shared with them);
//   springs: dt = sqrt(2 m / k) with m the property mass and k the largest translational
//           stiffness (Radioss spring time step, reference guide /PROP/TYPE4).
#include "hbm/deck/summary.hpp"

#include "hbm/deck/ogden_law.hpp"

#include "id_index.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace hbm::deck {

namespace {

struct P3 {
  double x, y, z;
};
P3 sub(P3 a, P3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
P3 cross(P3 a, P3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dot(P3 a, P3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double norm(P3 a) { return std::sqrt(dot(a, a)); }

// Hexahedron volume: 2x2x2 Gauss integration of det J (exact for trilinear geometry).
double hex_volume(const P3 (&x)[8]) {
  static constexpr int xi[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const double g = 1.0 / std::sqrt(3.0);
  double v = 0;
  for (int a = 0; a < 8; ++a) {
    const double p[3] = {xi[a][0] * g, xi[a][1] * g, xi[a][2] * g};
    P3 d[3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (int i = 0; i < 8; ++i) {
      const double dn[3] = {xi[i][0] * (1 + xi[i][1] * p[1]) * (1 + xi[i][2] * p[2]) / 8,
                            xi[i][1] * (1 + xi[i][0] * p[0]) * (1 + xi[i][2] * p[2]) / 8,
                            xi[i][2] * (1 + xi[i][0] * p[0]) * (1 + xi[i][1] * p[1]) / 8};
      for (int k = 0; k < 3; ++k) {
        d[k].x += dn[k] * x[i].x;
        d[k].y += dn[k] * x[i].y;
        d[k].z += dn[k] * x[i].z;
      }
    }
    v += dot(cross(d[0], d[1]), d[2]);
  }
  return v;
}

double quad_area(P3 a, P3 b, P3 c, P3 d) { return 0.5 * norm(cross(sub(c, a), sub(d, b))); }

struct Material {
  const Card* card = nullptr;
  double rho = 0;
  double c_solid = 0;  // dilatational wave speed (0 if unknown)
  double c_shell = 0;  // plane-stress wave speed (0 if not for shells)
};

Material material_of(const Card* m) {
  Material out;
  out.card = m;
  if (!m) return out;
  const std::string_view kw = m->keyword();
  out.rho = m->real(0, "rho");
  if (!(out.rho > 0)) return out;
  if (kw == "/MAT/LAW34") {
    const double k = m->real(1, "K"), g0 = m->real(2, "G0");
    out.c_solid = std::sqrt((k + 4.0 / 3.0 * g0) / out.rho);
    return out;
  }
  if (kw == "/MAT/LAW42") {
    double mu[kOgdenPairs], al[kOgdenPairs];
    for (int p = 0; p < kOgdenPairs; ++p) {
      mu[p] = m->real(2, "mu" + std::to_string(p + 1));
      al[p] = m->real(3, "alpha" + std::to_string(p + 1));
    }
    const double e = ogden_step_modulus(mu, al);
    if (e > 0) out.c_shell = std::sqrt(e / (0.75 * out.rho));
    return out;
  }
  const double e = m->real(1, "E"), nu = m->real(1, "nu");
  if (e > 0 && nu > -1 && nu < 0.5) {
    out.c_solid = std::sqrt(e * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * out.rho));
    out.c_shell = std::sqrt(e / ((1 - nu * nu) * out.rho));
  }
  return out;
}

std::string fmt(double v, const char* f = "%.6g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

ModelSummary summarize(const Deck& d) {
  ModelSummary s;
  // Nodes.
  detail::IdIndex nodes;
  std::vector<P3> xyz;
  for (const Card* c : d.cards_of("/NODE")) {
    for (std::size_t i = 0; i < c->n_rows(); ++i) {
      const Row& r = c->row(i);
      const Value* v = &c->values[r.first];
      nodes.add(v[0].integer, static_cast<std::uint32_t>(xyz.size()));
      xyz.push_back({v[1].real, v[2].real, v[3].real});
    }
  }
  s.nodes = xyz.size();
  nodes.build([](std::int64_t, std::uint32_t, std::uint32_t) {});
  auto node = [&](std::int64_t id, P3& out) {
    const std::uint32_t k = nodes.find(id);
    if (k == detail::IdIndex::kNone) return false;
    out = xyz[k];
    return true;
  };
  // Objects by id.
  auto find_card = [&](std::string_view prefix, std::int64_t id) -> const Card* {
    for (const Card& c : d.cards)
      if (c.id == id && c.keyword().substr(0, prefix.size()) == prefix) return &c;
    return nullptr;
  };
  std::vector<const Card*> parts = d.cards_of("/PART");
  for (const Card* p : parts) {
    PartSummary ps;
    ps.part_id = p->id;
    ps.title = p->title;
    const Card* prop = find_card("/PROP/", p->integer(0, "prop_id"));
    const Card* mat = p->integer(0, "mat_id") ? find_card("/MAT/", p->integer(0, "mat_id")) : nullptr;
    if (prop) ps.property = std::string(prop->keyword()) + "/" + std::to_string(prop->id);
    if (mat) ps.material = std::string(mat->keyword()) + "/" + std::to_string(mat->id);
    s.parts.push_back(ps);
  }
  auto part_index = [&](std::int64_t id) -> PartSummary* {
    for (PartSummary& p : s.parts)
      if (p.part_id == id) return &p;
    return nullptr;
  };
  auto note_dt = [](PartSummary& p, double dt, std::int64_t eid) {
    if (!(dt > 0) || !std::isfinite(dt)) return;
    if (p.dt_min == 0 || dt < p.dt_min) {
      p.dt_min = dt;
      p.dt_element = eid;
    }
  };
  for (const Card& c : d.cards) {
    const std::string_view kw = c.keyword();
    const bool solid = kw == "/BRICK" || kw == "/TETRA4";
    const bool shell = kw == "/SHELL" || kw == "/SH3N";
    const bool spring = kw == "/SPRING";
    if (!solid && !shell && !spring) continue;
    const std::size_t n = c.n_rows();
    s.elements[std::string(kw)] += n;
    PartSummary* ps = part_index(c.id);
    if (!ps) continue;
    ps->elements[std::string(kw)] += n;
    const Card* part = find_card("/PART", c.id);
    const Card* prop = find_card("/PROP/", part->integer(0, "prop_id"));
    const std::int64_t mat_id = part->integer(0, "mat_id");
    const Material mat = material_of(mat_id ? find_card("/MAT/", mat_id) : nullptr);
    if (spring) {
      if (!prop) continue;
      const double m = prop->real(0, "Mass");
      double k = 0;
      if (prop->keyword() == "/PROP/TYPE4") {
        k = prop->real(1, "K");
      } else {
        for (const char* name : {"K1", "K2", "K3"})
          for (std::size_t l = 1; l < prop->n_fixed_lines(); ++l)
            if (field_index(*prop->lines[l].layout, name) >= 0) k = std::max(k, prop->real(l, name));
      }
      ps->mass += m * static_cast<double>(n);
      if (m > 0 && k > 0) {
        const double dt = std::sqrt(2 * m / k);
        for (std::size_t i = 0; i < n; ++i) note_dt(*ps, dt, c.integer(c.row(i), "id"));
        ps->dt_note = "springs: sqrt(2 m / k)";
      } else if (ps->dt_note.empty()) {
        ps->dt_note = m > 0 ? "springs without linear stiffness" : "springs without mass: nodal time step";
      }
      continue;
    }
    double thick_part = part->real(0, "thick");
    if (!(thick_part > 0) && prop && prop->keyword() == "/PROP/TYPE1") thick_part = prop->real(2, "Thick");
    for (std::size_t i = 0; i < n; ++i) {
      const Row& r = c.row(i);
      const Value* v = &c.values[r.first];
      const std::int64_t eid = v[0].integer;
      if (kw == "/BRICK") {
        P3 x[8];
        bool ok = true;
        for (int k = 0; k < 8; ++k) ok = ok && node(v[1 + k].integer, x[k]);
        if (!ok) continue;
        const double vol = hex_volume(x);
        static constexpr int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                            {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
        double amax = 0;
        for (const auto& f : faces) amax = std::max(amax, quad_area(x[f[0]], x[f[1]], x[f[2]], x[f[3]]));
        ps->mass += mat.rho * vol;
        if (mat.c_solid > 0 && amax > 0) note_dt(*ps, vol / amax / mat.c_solid, eid);
      } else if (kw == "/TETRA4") {
        P3 x[4];
        bool ok = true;
        for (int k = 0; k < 4; ++k) ok = ok && node(v[1 + k].integer, x[k]);
        if (!ok) continue;
        const double vol = dot(cross(sub(x[1], x[0]), sub(x[2], x[0])), sub(x[3], x[0])) / 6;
        static constexpr int faces[4][3] = {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}};
        double amax = 0;
        for (const auto& f : faces)
          amax = std::max(amax, 0.5 * norm(cross(sub(x[f[1]], x[f[0]]), sub(x[f[2]], x[f[0]]))));
        ps->mass += mat.rho * vol;
        if (mat.c_solid > 0 && amax > 0) note_dt(*ps, 3 * vol / amax / mat.c_solid, eid);
      } else {
        const int nn = kw == "/SHELL" ? 4 : 3;
        P3 x[4];
        bool ok = true;
        for (int k = 0; k < nn; ++k) ok = ok && node(v[1 + k].integer, x[k]);
        if (!ok) continue;
        double area = 0, len = 0;
        if (nn == 4) {
          area = quad_area(x[0], x[1], x[2], x[3]);
          const double dmax = std::max(norm(sub(x[2], x[0])), norm(sub(x[3], x[1])));
          len = dmax > 0 ? area / dmax : 0;
        } else {
          area = 0.5 * norm(cross(sub(x[1], x[0]), sub(x[2], x[0])));
          const double emax = std::max({norm(sub(x[1], x[0])), norm(sub(x[2], x[1])), norm(sub(x[0], x[2]))});
          len = emax > 0 ? 2 * area / emax : 0;
        }
        const double t = c.real(r, "thick") > 0 ? c.real(r, "thick") : thick_part;
        ps->mass += mat.rho * area * t;
        if (mat.c_shell > 0 && len > 0) note_dt(*ps, len / mat.c_shell, eid);
      }
    }
    if (ps->dt_note.empty())
      ps->dt_note = solid ? (mat.card && mat.card->keyword() == "/MAT/LAW34" ? "solids: L / sqrt((K + 4/3 G0) / rho)"
                                                                              : "solids: L / dilatational wave speed")
                          : "shells: L / plane-stress wave speed";
  }
  for (const PartSummary& p : s.parts) {
    s.element_mass += p.mass;
    if (p.dt_min > 0 && (s.dt_min == 0 || p.dt_min < s.dt_min)) {
      s.dt_min = p.dt_min;
      s.dt_part = p.part_id;
    }
  }
  for (const Card* rb : d.cards_of("/RBODY")) s.rbody_mass += rb->real(0, "Mass");
  return s;
}

void print_model_summary(std::ostream& os, const Deck& d) {
  const ModelSummary s = summarize(d);
  const Units& u = d.work_units;
  os << "Model summary: " << (d.run_name.empty() ? std::string("(no run name)") : d.run_name) << "  (units: mass "
     << u.mass << ", length " << u.length << ", time " << u.time << ")\n";
  os << "  nodes: " << s.nodes << "\n  elements:";
  if (s.elements.empty()) os << " none";
  for (const auto& [kw, n] : s.elements) os << "  " << kw << " " << n;
  os << "\n  materials:\n";
  for (const Card& c : d.cards) {
    if (c.keyword().substr(0, 5) != "/MAT/") continue;
    const Material m = material_of(&c);
    os << "    " << c.keyword() << "/" << c.id << "  " << c.title << "  rho " << fmt(m.rho);
    if (c.keyword() == "/MAT/LAW34") {
      os << "  K " << fmt(c.real(1, "K")) << "  G0 " << fmt(c.real(2, "G0")) << "  Ginf " << fmt(c.real(2, "Ginf"));
    } else if (c.keyword() == "/MAT/LAW42") {
      for (int p = 1; p <= kOgdenPairs; ++p) {
        const double mu = c.real(2, "mu" + std::to_string(p));
        if (mu != 0.0) os << "  mu" << p << " " << fmt(mu) << " alpha" << p << " " << fmt(c.real(3, "alpha" + std::to_string(p)));
      }
    } else {
      os << "  E " << fmt(c.real(1, "E")) << "  nu " << fmt(c.real(1, "nu"));
    }
    os << "  c " << fmt(m.c_solid) << " " << u.length << "/" << u.time << "\n";
  }
  os << "  parts:\n";
  for (const PartSummary& p : s.parts) {
    os << "    /PART/" << p.part_id << "  " << p.title << "  " << p.property << "  "
       << (p.material.empty() ? std::string("(no material)") : p.material) << "\n      elements:";
    if (p.elements.empty()) os << " none";
    for (const auto& [kw, n] : p.elements) os << "  " << kw << " " << n;
    os << "\n      mass " << fmt(p.mass) << " " << u.mass;
    if (p.dt_min > 0) {
      os << "  smallest time step " << fmt(p.dt_min) << " " << u.time << " (element " << p.dt_element << "; "
         << p.dt_note << ")";
    } else {
      os << "  time step: " << (p.dt_note.empty() ? std::string("no elements") : p.dt_note);
    }
    os << "\n";
  }
  os << "  total mass " << fmt(s.total_mass()) << " " << u.mass << " (elements " << fmt(s.element_mass)
     << ", rigid body added masses " << fmt(s.rbody_mass) << ")\n";
  if (s.dt_min > 0)
    os << "  smallest element time step " << fmt(s.dt_min) << " " << u.time << " in part " << s.dt_part << "\n";
}

}  // namespace hbm::deck
