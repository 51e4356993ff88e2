// SPDX-License-Identifier: GPL-3.0-or-later
// Deck cards of the body model and the drop-test decks (see deck_export.hpp).
#include "hbm/deckgen/deck_export.hpp"

#include "hbm/deck/io.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hbm::deckgen {

using hbm::deck::CardBuilder;
using hbm::deck::Deck;

namespace {

constexpr int kSolidProp = 1;          // soft tissue bricks (LAW34), viscous hourglass
constexpr int kBoneSolidProp = 2;      // bone and thoracolumbar disc bricks (LAW1)
constexpr int kSoftPhysicalProp = 3;   // soft tissue bricks (LAW34), physical hourglass

// Hourglass form of a soft tissue (LAW34) brick part (docs/engine-design.md 12.6, 12.10).
// The organ blocks and the flesh of the abdomen and pelvis take the physical
// stabilisation (Isolid 24: elastic assumed-strain hourglass stiffness from G, Belytschko
// & Bindeman 1993): their bending and warping under the impactor, the seat and the floor
// are deformations that the viscous form can only follow through its hourglass modes, so
// it dissipated them as hourglass energy and carried load by that damping (drop deck 36.6 %
// hourglass / internal energy, 7.4 % with this form). With the default tetra flesh
// (`tetra_flesh`: the flesh parts hold tetras, which have no hourglass modes; flesh_pelvis
// keeps 8 bricks under the coccyx) the neck's soft tissue (muscles, visceral column,
// cervical discs) takes it too: the hub cases' hourglass / internal energy 6.0 / 8.0 / 7.5 ->
// 2.5 / 4.1 / 6.2 % (frontal 4.3, 6.7, oblique 9.5), the neck bricks no longer inverting
// once the thorax under them is tetras. With the brick flesh (--flesh-bricks) two groups keep
// the viscous form (Isolid 1): the thoracic flesh (and the presternal fat), a two-brick layer
// that the hub's rim folds until a brick inverts with Isolid 24 (12.9-47.0 ms in the hub
// cases), and the neck's soft tissue, whose bricks inverted in every run that changed it.
bool soft_tissue_physical_hourglass(const FePart& p, bool tetra_flesh) {
  const bool thoracic_flesh = p.segment == "thorax" && p.region == "flesh";  // flesh_thorax, flesh_presternal
  return tetra_flesh || (p.segment != "neck" && !thoracic_flesh);
}

int shell_prop_id(const FePart& p) { return 1000 + p.id; }
int spring_prop_id(const FeSpringProp& s) { return 2000 + s.id; }
int rbody_group_id(const FeRigidBody& r) { return 10000 + r.id; }
int surf_id(const FeInterface& f) { return 20000 + f.id; }
int iface_group_id(const FeInterface& f) { return 30000 + f.id; }

void node_group(Deck& d, int id, const std::string& title, const std::vector<int>& nodes) {
  CardBuilder g(d, "/GRNOD/NODE", id, title);
  static const char* names[10] = {"id1", "id2", "id3", "id4", "id5", "id6", "id7", "id8", "id9", "id10"};
  for (std::size_t i = 0; i < nodes.size(); i += 10) {
    std::size_t r = g.add_row();
    for (std::size_t k = 0; k < 10 && i + k < nodes.size(); ++k) g.row_set_int(r, names[k], nodes[i + k] + 1);
  }
  g.commit();
}

}  // namespace

Deck model_cards(const FeModel& m, const std::string& title) {
  Deck d;
  d.section = hbm::deck::Section::Starter;
  {
    CardBuilder n(d, "/NODE");
    for (std::size_t i = 0; i < m.nodes.size(); ++i) {
      std::size_t r = n.add_row();
      n.row_set_int(r, "id", static_cast<std::int64_t>(i + 1));
      // Coordinates rounded to 1 nm: the text is exact and platform independent.
      auto q = [](double v) { return std::round(v * 1e6) / 1e6; };
      n.row_set(r, "X", q(m.nodes[i].x())).row_set(r, "Y", q(m.nodes[i].y())).row_set(r, "Z", q(m.nodes[i].z()));
    }
    n.commit();
  }
  (void)title;
  // Materials.
  for (const FeMaterial& mat : m.materials) {
    std::string t = mat.name;
    if (mat.law == "LAW1") {
      CardBuilder(d, "/MAT/LAW1", mat.id, t).set(0, "rho", mat.rho).set(1, "E", mat.E).set(1, "nu", mat.nu).commit();
    } else if (mat.law == "LAW2") {
      // Linear hardening (n = 1), no rate term; element deletion at EPS_p_max.
      CardBuilder(d, "/MAT/LAW2", mat.id, t)
          .set(0, "rho", mat.rho)
          .set(1, "E", mat.E)
          .set(1, "nu", mat.nu)
          .set(2, "a", mat.yield)
          .set(2, "b", mat.hardening)
          .set(2, "n", 1.0)
          .set(2, "EPS_p_max", mat.eps_p_max)
          .commit();
    } else {
      CardBuilder(d, "/MAT/LAW34", mat.id, t)
          .set(0, "rho", mat.rho)
          .set(1, "K", mat.K)
          .set(2, "G0", mat.G0)
          .set(2, "Ginf", mat.Ginf)
          .set(2, "beta", mat.beta)
          .commit();
    }
  }
  // Properties: three solid properties; one shell property per shell part; spring properties.
  // Solid properties share the bulk viscosity (qa 1.1, qb 0.05) and hourglass coefficient
  // (h 0.1, the viscous form's, and the physical form's small viscous part).
  // Tetras (the flesh of MesherOptions::flesh_tetra) are average nodal pressure tetras,
  // Itetra4 3 (docs/engine-design.md §12.9): the constant strain tetra locks in nearly
  // incompressible tissue.
  const bool has_tetras = !m.tetras.empty();
  auto solid_property = [&d, has_tetras](int id, const std::string& name, int isolid, double dn = 0.0) {
    CardBuilder c(d, "/PROP/TYPE14", id, name);
    c.set_int(0, "Isolid", isolid);
    if (has_tetras) c.set_int(0, "Itetra4", 3);
    if (dn > 0) c.set(0, "dn", dn);
    c.set(1, "qa", 1.1).set(1, "qb", 0.05).set(1, "h", 0.1).commit();
  };
  // The viscous form's property is written only for the parts that use it.
  bool viscous_used = false;
  for (const FePart& p : m.parts)
    if (p.kind == ElementKind::Brick && m.materials[static_cast<std::size_t>(p.material)].law != "LAW1" &&
        !soft_tissue_physical_hourglass(p, has_tetras))
      viscous_used = true;
  if (viscous_used) solid_property(kSolidProp, "soft tissue solids: 1-point brick, viscous hourglass", 1);
  // Vertebral units and thoracolumbar discs (LAW1) are one or two bricks through their
  // height and bend with the spine: for a one-point brick that bending is its hourglass
  // modes. The physical stabilisation (Isolid 24: assumed-strain hourglass stiffness from
  // G, Belytschko & Bindeman 1993) gives those bricks their elastic bending stiffness; with
  // the viscous form the spine held 8-15 J of hourglass energy against 0.1-0.2 J internal
  // in the hub cases (docs/engine-design.md §12).
  solid_property(kBoneSolidProp, "bone and disc solids: 1-point brick, physical hourglass", 24);
  // The soft tissue's Isolid 24 viscous part, dn / 4 / 150 rho c V^(2/3) (OpenRadioss
  // szhour3.F), takes the dilatational sound speed c: for the nearly incompressible tissue
  // (K / G up to 1.3e5) 360 times the shear wave speed of the hourglass modes. With the
  // default dn 0.1 it dissipated up to 10.0 % of the internal energy (lateral pelvis hub,
  // abdominal_organs_pelvis), with dn 0.05 the six hub cases rate the same within 0.005 and
  // the energy balance holds: dn 0.05 (geometry/calibration-notes-validation.md).
  solid_property(kSoftPhysicalProp, "soft tissue solids: 1-point brick, physical hourglass", 24, 0.05);
  for (const FePart& p : m.parts) {
    if (p.kind != ElementKind::Shell && p.kind != ElementKind::Tria) continue;
    // Ishell 4: Belytschko Q4 with hourglass modes orthogonalised for warped elements
    // (OpenRadioss /PROP/TYPE1); skin, pelvis cortex and scapula quads warp up to 15 deg,
    // and QEPH (24) is not in the project engine (Ishell 0-4). Ish3n 2: C0 triangle with
    // the large-rotation correction (the OpenRadioss default).
    CardBuilder c(d, "/PROP/TYPE1", shell_prop_id(p), "shell " + p.name);
    c.set_int(0, "Ishell", 4)
        .set_int(0, "Ish3n", 2)
        .set_int(2, "N", 3)  // three Gauss points: rib_fracture.hpp's three_point_outer_zeta
        .set(2, "Thick", p.thickness > 0 ? p.thickness : 1.0);
    if (p.fail_fraction > 0) c.set(0, "P_thick_fail", p.fail_fraction);
    c.commit();
  }
  for (const FeSpringProp& s : m.spring_props) {
    if (s.type == 4) {
      CardBuilder(d, "/PROP/TYPE4", spring_prop_id(s), "spring " + s.name).set(1, "K", s.k[0]).set(1, "C", s.c[0]).commit();
    } else {
      CardBuilder c(d, "/PROP/TYPE8", spring_prop_id(s), "joint " + s.name);
      // Spring mass 10 g and inertia 1 kg mm^2 (half to each node): the joint nodes carry no
      // element mass; negligible beside the rigid bodies the joints connect.
      c.set(0, "Mass", 0.01).set(0, "Inertia", 1.0);
      for (int k = 0; k < 6; ++k) {
        std::string n = std::to_string(k + 1);
        c.set(static_cast<std::size_t>(1 + 3 * k), "K" + n, s.k[static_cast<std::size_t>(k)]);
        c.set(static_cast<std::size_t>(1 + 3 * k), "C" + n, s.c[static_cast<std::size_t>(k)]);
      }
      c.commit();
    }
  }
  for (const FePart& p : m.parts) {
    CardBuilder c(d, "/PART", p.id, p.name);
    if (p.kind == ElementKind::Spring) {
      // Spring parts have no material (mat_id 0, as in Radioss: the spring property holds
      // stiffness, damping and mass).
      c.set_int(0, "prop_id", spring_prop_id(m.spring_props[static_cast<std::size_t>(p.spring_prop)]));
      c.set_int(0, "mat_id", 0);
    } else {
      const FeMaterial& mat = m.materials[static_cast<std::size_t>(p.material)];
      const int solid_prop = mat.law == "LAW1"                    ? kBoneSolidProp
                             : soft_tissue_physical_hourglass(p, has_tetras) ? kSoftPhysicalProp
                                                                 : kSolidProp;
      c.set_int(0, "prop_id", p.kind == ElementKind::Brick ? solid_prop : shell_prop_id(p));
      c.set_int(0, "mat_id", mat.id);
    }
    c.commit();
  }
  // Elements, grouped by part in part order (one card per part and kind).
  std::int64_t eid = 0;
  auto by_part = [&](const std::vector<int>& part_of, auto&& emit) {
    for (const FePart& p : m.parts) {
      std::vector<std::size_t> els;
      for (std::size_t e = 0; e < part_of.size(); ++e)
        if (part_of[e] + 1 == p.id) els.push_back(e);
      if (!els.empty()) emit(p, els);
    }
  };
  static const char* bn[8] = {"n1", "n2", "n3", "n4", "n5", "n6", "n7", "n8"};
  // One card per part: element id, its nodes and, for shells given one, the element's own
  // thickness (thick: nullptr for solids).
  auto element_cards = [&](const char* keyword, const auto& elements, const std::vector<int>& part_of,
                           const std::vector<double>* thick) {
    by_part(part_of, [&](const FePart& p, const std::vector<std::size_t>& els) {
      CardBuilder c(d, keyword, p.id);
      for (std::size_t e : els) {
        std::size_t r = c.add_row();
        c.row_set_int(r, "id", ++eid);
        for (std::size_t k = 0; k < elements[e].size(); ++k) c.row_set_int(r, bn[k], elements[e][k] + 1);
        if (thick && (*thick)[e] > 0) c.row_set(r, "thick", std::round((*thick)[e] * 1e6) / 1e6);
      }
      c.commit();
    });
  };
  element_cards("/BRICK", m.bricks, m.brick_part, nullptr);
  element_cards("/TETRA4", m.tetras, m.tetra_part, nullptr);
  element_cards("/SHELL", m.shells, m.shell_part, &m.shell_thick);
  element_cards("/SH3N", m.trias, m.tria_part, &m.tria_thick);
  element_cards("/SPRING", m.springs, m.spring_part, nullptr);
  // Rigid bodies.
  for (const FeRigidBody& rb : m.rigid_bodies) {
    node_group(d, rbody_group_id(rb), "rigid body " + rb.name, rb.nodes);
    CardBuilder c(d, "/RBODY", rb.id, rb.name);
    c.set_int(0, "node_id", rb.main_node + 1).set_int(0, "grnod_id", rbody_group_id(rb)).set_int(0, "ICoG", 1);
    if (rb.added_mass > 0) {
      auto q = [](double v) { return std::round(v * 1e6) / 1e6; };
      c.set(0, "Mass", q(rb.added_mass));
      c.set(1, "Jxx", q(rb.added_inertia(0, 0))).set(1, "Jyy", q(rb.added_inertia(1, 1))).set(1, "Jzz", q(rb.added_inertia(2, 2)));
      c.set(2, "Jxy", q(rb.added_inertia(0, 1))).set(2, "Jyz", q(rb.added_inertia(1, 2))).set(2, "Jxz", q(rb.added_inertia(0, 2)));
    }
    c.commit();
  }
  // Contacts.
  for (const FeInterface& f : m.interfaces) {
    node_group(d, iface_group_id(f), "secondary nodes " + f.name, f.secondary);
    if (!f.main_parts.empty()) {
      // Main surface of whole shell parts: the engine (as Radioss) takes a shell part's
      // elements as two-sided segments even where they lie on solid faces.
      CardBuilder s(d, "/SURF/PART", surf_id(f), "main surface " + f.name);
      std::size_t r = s.add_row();
      for (std::size_t i = 0; i < f.main_parts.size(); ++i) {
        if (i > 0 && i % 10 == 0) r = s.add_row();
        s.row_set_int(r, "id" + std::to_string(i % 10 + 1), m.parts[static_cast<std::size_t>(f.main_parts[i])].id);
      }
      s.commit();
    } else {
      CardBuilder s(d, "/SURF/SEG", surf_id(f), "main surface " + f.name);
      for (const auto& q : f.main_segments) {
        std::size_t r = s.add_row();
        s.row_set_int(r, "n1", q[0] + 1).row_set_int(r, "n2", q[1] + 1).row_set_int(r, "n3", q[2] + 1);
        if (q[3] != q[2]) s.row_set_int(r, "n4", q[3] + 1);
      }
      s.commit();
    }
    if (f.type == 2) {
      CardBuilder(d, "/INTER/TYPE2", f.id, f.name)
          .set_int(0, "grnod_id", iface_group_id(f))
          .set_int(0, "surf_id", surf_id(f))
          .set(0, "dsearch", f.search)
          .commit();
    } else {
      CardBuilder(d, "/INTER/TYPE7", f.id, f.name)
          .set_int(0, "grnod_id", iface_group_id(f))
          .set_int(0, "surf_id", surf_id(f))
          .set(3, "Stfac", f.stiffness_factor)
          .set(3, "Fric", f.friction)
          .set(3, "Gapmin", f.gap)
          .set_int(4, "Inacti", 6)
          .commit();
    }
  }
  return d;
}

void write_file_atomically(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::path tmp = file;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot create " + tmp.string());
    out << text;
    out.flush();
    if (!out) {
      std::filesystem::remove(tmp);
      throw std::runtime_error("cannot write " + tmp.string());
    }
  }
  std::filesystem::rename(tmp, file);
}

void write_model_include(const std::filesystem::path& file, const FeModel& m, const std::string& title) {
  Deck d = model_cards(m, title);
  std::ostringstream os;
  os << "# " << title << "\n";
  for (const std::string& n : m.notes) os << "# " << n << "\n";
  for (const auto& c : d.cards) hbm::deck::write_card(os, c, d);
  write_file_atomically(file, os.str());
}

void write_drop_decks(const std::filesystem::path& dir, const std::string& name, const std::string& include_name,
                      const FeModel& m, const DropTest& t) {
  double zmin = 1e300;
  for (const auto& p : m.nodes) zmin = std::min(zmin, p.z());
  const double zf = std::round((zmin - t.floor_clearance) * 1e3) / 1e3;
  Deck s;
  s.section = hbm::deck::Section::Starter;
  CardBuilder(s, "/BEGIN", 0, name)
      .set_int(0, "Invers", 2024)
      .set_text(1, "mass", "kg").set_text(1, "length", "mm").set_text(1, "time", "ms")
      .set_text(2, "mass", "kg").set_text(2, "length", "mm").set_text(2, "time", "ms")
      .commit();
  Deck rest;
  rest.section = hbm::deck::Section::Starter;
  std::vector<int> all(m.nodes.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  node_group(rest, 90001, "all nodes", all);
  CardBuilder(rest, "/INIVEL/TRA", 90001, "drop velocity").set(0, "Vz", -t.speed).set_int(0, "grnod_id", 90001).commit();
  CardBuilder(rest, "/RWALL/PLANE", 90001, "rigid floor")
      .set_int(0, "grnod_id1", 90001)
      .set(2, "XM", 0).set(2, "YM", 0).set(2, "ZM", zf)
      .set(3, "XM1", 0).set(3, "YM1", 0).set(3, "ZM1", zf + 100.0)
      .commit();
  {
    // Internal and hourglass energy and added mass of every part (as the hub decks have): the
    // hourglass / internal energy ratio of a run of this deck, and where it sits, read from T01.
    CardBuilder th(rest, "/TH/PART", 90001, "parts");
    static const char* vars[3][2] = {{"var1", "IE"}, {"var2", "HE"}, {"var3", "AM"}};
    const std::size_t nr = th.add_name_row();
    for (const auto& v : vars) th.name_row_set_text(nr, v[0], v[1]);
    static const char* ids[10] = {"id1", "id2", "id3", "id4", "id5", "id6", "id7", "id8", "id9", "id10"};
    for (std::size_t i = 0; i < m.parts.size(); i += 10) {
      const std::size_t r = th.add_row();
      for (std::size_t k = 0; k < 10 && i + k < m.parts.size(); ++k) th.row_set_int(r, ids[k], m.parts[i + k].id);
    }
    th.commit();
  }
  CardBuilder(rest, "/END").commit();
  std::ostringstream os;
  os << "#RADIOSS STARTER\n";
  os << "# " << name << ": the 50th percentile male model (" << include_name << ") dropped at " << t.speed
     << " m/s onto a rigid floor " << t.floor_clearance << " mm below its lowest node, " << t.end_time << " ms.\n";
  for (const auto& c : s.cards) hbm::deck::write_card(os, c, s);
  os << "#include " << include_name << "\n";
  for (const auto& c : rest.cards) hbm::deck::write_card(os, c, rest);

  Deck e;
  e.section = hbm::deck::Section::Engine;
  CardBuilder(e, "/RUN", 1, name).set(0, "Tstop", t.end_time).commit();
  CardBuilder(e, "/TFILE", 0).set(0, "dt_his", 0.1).commit();
  CardBuilder(e, "/ANIM/DT").set(0, "Tstart", 0.0).set(0, "Tfreq", 2.0).commit();
  CardBuilder(e, "/DT/NODA/CST").set(0, "Tsca", t.tsca).set(0, "Tmin", t.tmin).commit();
  CardBuilder(e, "/DT/SHELL/CST").set(0, "Tsca", t.tsca).set(0, "Tmin", t.tmin).commit();
  CardBuilder(e, "/DT/BRICK/CST", 1).set(0, "Tsca", t.tsca).set(0, "Tmin", t.brick_tmin).set(1, "VDEF_min", t.brick_vdef_min).commit();
  CardBuilder(e, "/STOP").set(0, "Emax", 0.0).set(0, "DMmax", t.dm_max).commit();
  CardBuilder(e, "/PRINT", -100).commit();
  std::ostringstream oe;
  hbm::deck::write_deck(oe, e);

  std::filesystem::path f0 = dir / (name + "_0000.rad"), f1 = dir / (name + "_0001.rad");
  write_file_atomically(f0, os.str());
  write_file_atomically(f1, oe.str());
}

}  // namespace hbm::deckgen
