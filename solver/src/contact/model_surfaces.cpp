// SPDX-License-Identifier: GPL-3.0-or-later
// Contact geometry of the whole model from the element cards, and surfaces cut from it.
#include "model_surfaces.hpp"

#include "deck_fields.hpp"
#include "hbm/deck/ogden_law.hpp"

#include <algorithm>

namespace hbm::solver::contact {

std::array<Index, 4> segment_key(std::array<Index, 4> n) {
  if (n[3] == n[2]) n[3] = kNoIndex;
  std::sort(n.begin(), n.end());
  return n;
}

bool material_moduli(const hbm::deck::Card& mat, double& young, double& bulk) {
  const std::string_view kw = mat.keyword();
  if (kw == "/MAT/LAW1" || kw == "/MAT/LAW2" || kw == "/MAT/LAW36") {
    young = real_of(mat, 1, {"E"});
    const double nu = real_of(mat, 1, {"nu"});
    bulk = young / (3.0 * (1.0 - 2.0 * nu));
    return true;
  }
  if (kw == "/MAT/LAW34") {
    bulk = real_of(mat, 1, {"K"});
    const double g = real_of(mat, 2, {"G0"});
    young = 9.0 * bulk * g / (3.0 * bulk + g);
    return true;
  }
  if (kw == "/MAT/LAW42") {
    // Small-strain moduli as OpenRadioss's hm_read_mat42.F stores them: GS = sum mu_p
    // alpha_p (twice the shear modulus), E = GS (1 + nu), K = GS (1 + nu) / (3 (1 - 2 nu)).
    double mu[hbm::deck::kOgdenPairs], alpha[hbm::deck::kOgdenPairs];
    for (int p = 0; p < hbm::deck::kOgdenPairs; ++p) {
      mu[p] = real_of(mat, 2, {"mu" + std::to_string(p + 1)});
      alpha[p] = real_of(mat, 3, {"alpha" + std::to_string(p + 1)});
    }
    const double gs = 2.0 * hbm::deck::ogden_shear_modulus(mu, alpha);
    const double nu = real_of(mat, 1, {"nu"});
    young = gs * (1.0 + nu);
    bulk = young / (3.0 * (1.0 - 2.0 * nu));
    return true;
  }
  return false;
}

namespace {

double shell_thickness(const hbm::deck::Card& card, const hbm::deck::Row& row, const Part& part) {
  const double t_el = card.real(row, "thick");
  if (t_el > 0) return t_el;
  if (part.part_card) {
    const double t_part = real_of(*part.part_card, 0, {"thick"});
    if (t_part > 0) return t_part;
  }
  if (part.prop_card && part.prop_card->keyword() == "/PROP/TYPE1")
    return real_of(*part.prop_card, 2, {"Thick"});
  return 0.0;
}

}  // namespace

ModelSurfaces::ModelSurfaces(BuildContext& ctx) {
  const hbm::deck::Deck& d = ctx.starter();
  const NodalState& nodes = ctx.nodes();
  n_nodes_ = nodes.n_nodes;
  std::vector<SolidForSurface> solids;
  std::vector<Index> solid_part;
  auto node = [&](const hbm::deck::Card& c, const hbm::deck::Row& r, std::string_view f) {
    return ctx.node_index(c.integer(r, f));
  };
  for (std::string_view kw : {"/BRICK", "/TETRA4"}) {
    for (const hbm::deck::Card* c : d.cards_of(kw)) {
      const Index part = ctx.part_index(c->id);
      if (part == kNoIndex) continue;  // reported by the element builder
      double e = 0, b = 0;
      const Part& p = ctx.part(part);
      if (p.mat_card) material_moduli(*p.mat_card, e, b);
      for (std::size_t r = 0; r < c->n_rows(); ++r) {
        const hbm::deck::Row& row = c->row(r);
        SolidForSurface s;
        if (kw == "/BRICK") {
          static constexpr std::string_view n8[] = {"n1", "n2", "n3", "n4", "n5", "n6", "n7", "n8"};
          for (std::size_t k = 0; k < 8; ++k) s.nodes[k] = node(*c, row, n8[k]);
        } else {
          const Index a = node(*c, row, "n1"), bb = node(*c, row, "n2"), cc = node(*c, row, "n3"),
                      dd = node(*c, row, "n4");
          s.nodes = {a, bb, cc, cc, dd, dd, dd, dd};
        }
        if (std::any_of(s.nodes.begin(), s.nodes.end(), [](Index i) { return i == kNoIndex; })) continue;
        s.bulk_modulus = b;
        solids.push_back(s);
        solid_part.push_back(part);
      }
    }
  }
  // Outer faces, remembering each face's element to know its part.
  {
    const ContactSurface all = solid_outer_faces(solids, nodes.x0.x, nodes.x0.y, nodes.x0.z);
    faces_ = all;
    // Part of each outer face: the solid that has all its nodes (unique for outer faces).
    std::map<std::array<Index, 4>, Index> part_of;
    static constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                         {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    for (std::size_t e = 0; e < solids.size(); ++e)
      for (const auto& f : kFaces) {
        std::array<Index, 4> q{};
        int m = 0;
        for (int k = 0; k < 4; ++k) {
          const Index id = solids[e].nodes[static_cast<std::size_t>(f[k])];
          if (std::find(q.begin(), q.begin() + m, id) == q.begin() + m) q[static_cast<std::size_t>(m++)] = id;
        }
        if (m < 3) continue;
        if (m == 3) q[3] = q[2];
        part_of.emplace(segment_key(q), solid_part[e]);
      }
    face_part_.resize(faces_.size());
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      const auto key = segment_key(faces_.nodes[f]);
      face_part_[f] = part_of.at(key);
      face_key_.emplace(key, f);
    }
  }
  // Shells.
  std::vector<ShellForSurface> shells;
  for (std::string_view kw : {"/SHELL", "/SH3N"}) {
    for (const hbm::deck::Card* c : d.cards_of(kw)) {
      const Index part = ctx.part_index(c->id);
      if (part == kNoIndex) continue;
      const Part& p = ctx.part(part);
      double e = 0, b = 0;
      if (p.mat_card) material_moduli(*p.mat_card, e, b);
      for (std::size_t r = 0; r < c->n_rows(); ++r) {
        const hbm::deck::Row& row = c->row(r);
        ShellForSurface s;
        s.nodes[0] = node(*c, row, "n1");
        s.nodes[1] = node(*c, row, "n2");
        s.nodes[2] = node(*c, row, "n3");
        s.nodes[3] = kw == "/SHELL" ? node(*c, row, "n4") : s.nodes[2];
        if (std::any_of(s.nodes.begin(), s.nodes.end(), [](Index i) { return i == kNoIndex; })) continue;
        s.young = e;
        s.thickness = shell_thickness(*c, row, p);
        shells.push_back(s);
        shell_part_.push_back(part);
      }
    }
  }
  shells_ = shell_segments(shells);
  for (std::size_t s = 0; s < shells_.size(); ++s) shell_key_.emplace(segment_key(shells_.nodes[s]), s);
}

namespace {
void push_segment(ContactSurface& out, const ContactSurface& from, std::size_t s) {
  out.nodes.push_back(from.nodes[s]);
  out.k0.push_back(from.k0[s]);
  out.thickness.push_back(from.thickness[s]);
  out.one_sided.push_back(from.one_sided[s]);
  out.depth.push_back(from.depth[s]);
}
}  // namespace

ContactSurface ModelSurfaces::of_parts(const std::vector<Index>& parts) const {
  ContactSurface out;
  auto listed = [&](Index p) { return std::find(parts.begin(), parts.end(), p) != parts.end(); };
  for (std::size_t f = 0; f < faces_.size(); ++f)
    if (listed(face_part_[f])) push_segment(out, faces_, f);
  for (std::size_t s = 0; s < shells_.size(); ++s)
    if (listed(shell_part_[s])) push_segment(out, shells_, s);
  return out;
}

ContactSurface ModelSurfaces::of_segments(const std::vector<std::array<Index, 4>>& segs,
                                          std::size_t& n_orphans) const {
  ContactSurface out;
  n_orphans = 0;
  for (const auto& q : segs) {
    const auto key = segment_key(q);
    if (auto it = face_key_.find(key); it != face_key_.end()) {
      push_segment(out, faces_, it->second);  // outward orientation of the solid face
    } else if (auto is = shell_key_.find(key); is != shell_key_.end()) {
      push_segment(out, shells_, is->second);
      out.nodes.back() = q;                   // keep the user's ordering
    } else {
      ++n_orphans;
      out.nodes.push_back(q);
      out.k0.push_back(0.0);
      out.thickness.push_back(0.0);
      out.one_sided.push_back(0);
      out.depth.push_back(0.0);
    }
  }
  return out;
}

std::vector<double> ModelSurfaces::node_half_thickness(const std::vector<Index>& nodes) const {
  std::vector<double> per_node(n_nodes_, 0.0);
  for (std::size_t s = 0; s < shells_.size(); ++s)
    for (Index n : shells_.nodes[s])
      per_node[static_cast<std::size_t>(n)] = std::max(per_node[static_cast<std::size_t>(n)], 0.5 * shells_.thickness[s]);
  std::vector<double> out;
  for (Index n : nodes) out.push_back(per_node[static_cast<std::size_t>(n)]);
  return out;
}

std::vector<double> ModelSurfaces::node_stiffness(const std::vector<Index>& nodes) const {
  std::vector<double> per_node(n_nodes_, 0.0);
  for (const ContactSurface* s : {&faces_, &shells_})
    for (std::size_t k = 0; k < s->size(); ++k)
      for (Index n : s->nodes[k])
        per_node[static_cast<std::size_t>(n)] = std::max(per_node[static_cast<std::size_t>(n)], s->k0[k]);
  std::vector<double> out;
  for (Index n : nodes) out.push_back(per_node[static_cast<std::size_t>(n)]);
  return out;
}

}  // namespace hbm::solver::contact
