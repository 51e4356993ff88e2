// SPDX-License-Identifier: GPL-3.0-or-later
// Writes a pendulum impact deck pair on the body model (see load_case.hpp).
//
// Impactor: shell face, rounded edge and rim (impactor_disc.hpp; steel, 1 mm; all its nodes
// secondaries of one /RBODY, so its elements are inactive) plus the rest of the mass as
// added mass, so that shells +
// added mass = spec.mass_kg exactly; added inertia of a solid steel cylinder of that mass
// and face (J_axis = m R^2/2, J_transverse = m (3 R^2 + L^2)/12). Rotations of the main
// node are fixed (/BCS): a guided impactor that translates only.
#include "hbm/deckgen/loadcases/geometry_landmarks.hpp"
#include "hbm/deckgen/loadcases/impactor_disc.hpp"
#include "hbm/deckgen/loadcases/load_case.hpp"

#include "hbm/deck/io.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace hbm::deckgen::loadcases {

namespace {

namespace fs = std::filesystem;
using hbm::deck::CardBuilder;
using hbm::deck::Deck;

constexpr double kSteelDensity = 7.85e-6;  // kg/mm^3
constexpr double kSteelModulus = 210.0;    // GPa
constexpr double kShellThickness = 1.0;    // mm

// Field names n1..n4, id1..id10, var1..var10 (no string building in loops).
constexpr const char* kN[] = {"n1", "n2", "n3", "n4"};
constexpr const char* kId[] = {"id1", "id2", "id3", "id4", "id5", "id6", "id7", "id8", "id9", "id10"};
constexpr const char* kVar[] = {"var1", "var2", "var3", "var4", "var5", "var6", "var7", "var8", "var9", "var10"};

// Coordinates and velocities rounded to 1e-6 (mm, mm/ms) and without negative zeros, so
// the deck reads cleanly by eye; 1e-6 mm is far below any length in the model.
double tidy(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0 ? 0.0 : r;
}

std::int64_t next_base(std::int64_t max_id, std::int64_t step) { return (max_id / step + 1) * step; }

// Distance of p from the line through a along unit u.
double axis_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& u) {
  const Eigen::Vector3d d = p - a;
  return (d - d.dot(u) * u).norm();
}

std::int64_t nearest_node(const ModelView& m, const std::vector<std::int64_t>& candidates, const Eigen::Vector3d& p,
                          double* distance) {
  std::int64_t best = 0;
  double bd = std::numeric_limits<double>::infinity();
  for (std::int64_t n : candidates) {
    const double d = (m.nodes.at(n) - p).norm();
    if (d < bd) bd = d, best = n;
  }
  if (distance) *distance = bd;
  return best;
}

std::vector<std::int64_t> require_parts(const ModelView& m, const std::vector<std::string>& prefixes,
                                        const std::string& what) {
  auto parts = m.parts_with_prefix(prefixes);
  if (parts.empty()) {
    std::string p;
    for (const auto& s : prefixes) p += (p.empty() ? "" : ", ") + s;
    throw std::runtime_error(m.path.string() + ": no part whose title starts with " + p + " (" + what +
                             "); parts of the model:\n" + m.part_list());
  }
  return parts;
}

void add_node_group(Deck& d, std::int64_t id, const std::string& title, const std::vector<std::int64_t>& nodes) {
  CardBuilder g(d, "/GRNOD/NODE", id, title);
  for (std::size_t i = 0; i < nodes.size(); i += 10) {
    const std::size_t r = g.add_row();
    for (std::size_t k = 0; k < 10 && i + k < nodes.size(); ++k) g.row_set_int(r, kId[k], nodes[i + k]);
  }
  g.commit();
}

void add_part_group(Deck& d, std::string_view kw, std::int64_t id, const std::string& title,
                    const std::vector<std::int64_t>& parts) {
  CardBuilder g(d, kw, id, title);
  for (std::size_t i = 0; i < parts.size(); i += 10) {
    const std::size_t r = g.add_row();
    for (std::size_t k = 0; k < 10 && i + k < parts.size(); ++k) g.row_set_int(r, kId[k], parts[i + k]);
  }
  g.commit();
}

void add_th(Deck& d, std::string_view kw, std::int64_t id, const std::string& title,
            const std::vector<std::string>& vars, const std::vector<std::int64_t>& objects) {
  CardBuilder t(d, kw, id, title);
  for (std::size_t i = 0; i < vars.size(); i += 10) {
    const std::size_t r = t.add_name_row();
    for (std::size_t k = 0; k < 10 && i + k < vars.size(); ++k)
      t.name_row_set_text(r, kVar[k], vars[i + k]);
  }
  for (std::size_t i = 0; i < objects.size(); i += 10) {
    const std::size_t r = t.add_row();
    for (std::size_t k = 0; k < 10 && i + k < objects.size(); ++k) t.row_set_int(r, kId[k], objects[i + k]);
  }
  t.commit();
}

std::string fmt(double v, int prec = 1) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(prec) << v;
  return os.str();
}

void check_written(const fs::path& path, hbm::deck::Section section) {
  hbm::deck::ReadResult r = hbm::deck::read_deck(path, section);
  if (!r.ok()) {
    std::ostringstream os;
    hbm::deck::print_diagnostics(os, r);
    throw std::runtime_error("the generated deck " + path.filename().string() + " does not read back:\n" + os.str());
  }
}

}  // namespace

GeneratedCase generate_load_case(const LoadCaseSpec& spec, const ModelView& model, const fs::path& model_path,
                                 const fs::path& geometry_dir, const fs::path& out_dir) {
  if (spec.speed_m_s <= 0 || spec.mass_kg <= 0 || spec.face_diameter_mm <= 0 || spec.tstop_ms <= 0)
    throw std::runtime_error(spec.name + ": speed, mass, face diameter and end time must be > 0");
  if (model.length_unit != "mm" || model.mass_unit != "kg" || model.time_unit != "ms")
    throw std::runtime_error(model.path.string() + ": work units " + model.mass_unit + " " + model.length_unit + " " +
                             model.time_unit + "; the load cases are written in kg mm ms");
  GeneratedCase g;
  const double a = spec.approach_deg * M_PI / 180;
  const Eigen::Vector3d u(std::cos(a), std::sin(a), 0.0);  // from the body towards the impactor
  g.travel = -u;
  const double R = 0.5 * spec.face_diameter_mm;

  ImpactorShape shape;
  shape.radius = R;
  shape.edge_radius = spec.edge_radius_mm;
  if (!(shape.edge_radius >= 0) || shape.edge_radius >= R)
    throw std::runtime_error(spec.name + ": edge radius " + fmt(spec.edge_radius_mm, 2) + " mm must lie in [0, " + fmt(R, 2) +
                             ") mm (half the face diameter)");

  // Landmarks and reference nodes. contact_nodes: the struck skin (aim); all_contact_*: skin
  // and the limbs in the path, the impactor contact's secondaries.
  const auto contact_parts = require_parts(model, spec.contact_part_prefixes, "contact with the impactor face");
  const auto contact_nodes = model.nodes_of(contact_parts);
  std::vector<std::int64_t> all_contact_parts = contact_parts;
  if (!spec.limb_part_prefixes.empty()) {
    const auto limbs = require_parts(model, spec.limb_part_prefixes, "limbs in the impactor's path");
    all_contact_parts.insert(all_contact_parts.end(), limbs.begin(), limbs.end());
    std::sort(all_contact_parts.begin(), all_contact_parts.end());
    all_contact_parts.erase(std::unique(all_contact_parts.begin(), all_contact_parts.end()), all_contact_parts.end());
  }
  const auto all_contact_nodes = model.nodes_of(all_contact_parts);
  g.contact_nodes = all_contact_nodes.size();
  g.limb_contact_nodes = all_contact_nodes.size() - contact_nodes.size();
  const auto sternum_nodes = model.nodes_of(require_parts(model, {"sternum"}, "sternum reference"));
  double zs_min = std::numeric_limits<double>::infinity(), zs_max = -zs_min;
  for (auto n : sternum_nodes) zs_min = std::min(zs_min, model.nodes.at(n).z()), zs_max = std::max(zs_max, model.nodes.at(n).z());
  Eigen::Vector3d P = Eigen::Vector3d::Zero();  // a point on the impactor axis
  switch (spec.target) {
    case Target::MidSternum:
      P = Eigen::Vector3d(0, 0, 0.5 * (zs_min + zs_max));
      break;
    case Target::XiphoidCentre: {
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      int k = 0;
      for (auto n : contact_nodes)
        if (std::abs(model.nodes.at(n).z() - zs_min) < 20) c += model.nodes.at(n), ++k;
      if (k == 0) throw std::runtime_error(spec.name + ": no contact node within 20 mm of the xiphoid level z = " + fmt(zs_min));
      c /= k;
      P = Eigen::Vector3d(c.x(), c.y(), zs_min);
      break;
    }
    case Target::GreaterTrochanter:
      P = pelvis_landmark(geometry_dir, spec.trochanter_landmark);
      break;
  }
  const Eigen::Vector3d spine_centre = vertebra_centre(geometry_dir, spec.spine_level);
  const auto spine_parts = require_parts(model, {"thoracic_vertebrae", "vertebra_" + spec.spine_level}, "spine reference");
  g.spine_node = nearest_node(model, model.nodes_of(spine_parts), spine_centre, &g.spine_node_distance_mm);
  if (g.spine_node_distance_mm > 30)
    throw std::runtime_error(spec.name + ": the nearest spine node is " + fmt(g.spine_node_distance_mm) + " mm from the " +
                             spec.spine_level + " body centre (limit 30 mm)");
  {
    // The sternum node: frontmost sternum node nearest the mid-height on the mid-plane.
    double best = std::numeric_limits<double>::infinity();
    for (auto n : sternum_nodes) {
      const Eigen::Vector3d& p = model.nodes.at(n);
      const double score = std::abs(p.z() - 0.5 * (zs_min + zs_max)) + std::abs(p.y()) - 0.1 * p.x();
      if (score < best) best = score, g.sternum_node = n;
    }
  }

  // Face position: the impactor surface (flat face, then the edge fillet set back by
  // ImpactorShape::setback) clear of every contact node in the footprint by the initial
  // clearance, measured along the axis. s_max: face-plane position that touches the
  // foremost node (struck skin or limb); s_skin: the same for the struck skin alone.
  const std::int64_t no_part = std::numeric_limits<std::int64_t>::min();
  std::map<std::int64_t, std::int64_t> part_of;  // contact node -> part
  for (auto pid : all_contact_parts)
    for (auto n : model.nodes_of({pid})) part_of.emplace(n, pid);
  double s_max = -std::numeric_limits<double>::infinity(), s_skin = s_max;
  std::int64_t nearest = no_part;
  for (auto n : all_contact_nodes) {
    const Eigen::Vector3d& p = model.nodes.at(n);
    const double rho = axis_distance(p, P, u);
    if (rho < R) {
      ++g.footprint_contact_nodes;
      const double s = (p - P).dot(u) - shape.setback(rho);
      if (s > s_max) s_max = s, nearest = part_of.at(n);
      if (std::binary_search(contact_nodes.begin(), contact_nodes.end(), n)) s_skin = std::max(s_skin, s);
    }
  }
  if (g.footprint_contact_nodes == 0 || !std::isfinite(s_skin))
    throw std::runtime_error(spec.name + ": no node of the contact parts lies in the impactor's footprint (axis through " +
                             fmt(P.x()) + " " + fmt(P.y()) + " " + fmt(P.z()) + ")");
  g.nearest_part = model.part_titles.count(nearest) ? model.part_titles.at(nearest) : std::to_string(nearest);
  const double s_face = s_max + spec.initial_clearance_mm;
  g.face_centre = P + s_face * u;
  g.first_contact_ms = (spec.initial_clearance_mm - spec.contact_gap_mm) / spec.speed_m_s;
  // Other model nodes ahead of the struck skin in the path: the impactor does not touch them.
  std::map<std::string, int> in_path;
  for (const auto& [pid, list] : model.part_nodes) {
    int k = 0;
    for (auto n : list) {
      const Eigen::Vector3d& p = model.nodes.at(n);
      const double rho = axis_distance(p, P, u);
      if (rho < R && (p - P).dot(u) - shape.setback(rho) > s_skin &&
          !std::binary_search(all_contact_nodes.begin(), all_contact_nodes.end(), n))
        ++k;
    }
    if (k) in_path[model.part_titles.count(pid) ? model.part_titles.at(pid) : std::to_string(pid)] += k;
  }
  for (const auto& [part, k] : in_path)
    g.warnings.push_back(std::to_string(k) + " node(s) of part " + part +
                         " lie in the impactor's path ahead of the struck skin; the impactor does not contact them");

  // Impactor mesh and ids.
  const ImpactorDisc disc = make_impactor_disc(g.face_centre, u, shape);
  const std::int64_t node0 = next_base(model.max_node_id, 100000);
  const std::int64_t elem0 = next_base(model.max_element_id, 100000);
  const std::int64_t obj = next_base(model.max_object_id, 1000);
  const double shell_mass = kSteelDensity * kShellThickness * disc.area();
  const double added_mass = spec.mass_kg - shell_mass;
  g.impactor_mass_kg = shell_mass + added_mass;
  const double length = spec.mass_kg / (kSteelDensity * M_PI * R * R);  // solid steel cylinder
  const double Ja = 0.5 * spec.mass_kg * R * R, Jt = spec.mass_kg * (3 * R * R + length * length) / 12;
  const Eigen::Matrix3d J = Jt * Eigen::Matrix3d::Identity() + (Ja - Jt) * u * u.transpose();
  g.impactor_main_node = node0 + 1;

  Deck d;
  d.section = hbm::deck::Section::Starter;
  CardBuilder(d, "/BEGIN", 0, spec.name)
      .set_int(0, "Invers", 2024)
      .set_text(1, "mass", "kg").set_text(1, "length", "mm").set_text(1, "time", "ms")
      .set_text(2, "mass", "kg").set_text(2, "length", "mm").set_text(2, "time", "ms")
      .commit();
  const std::size_t n_begin = d.cards.size();
  std::vector<std::int64_t> secondaries;
  {
    CardBuilder nodes(d, "/NODE");
    auto put = [&](std::int64_t id, const Eigen::Vector3d& p) {
      const std::size_t r = nodes.add_row();
      nodes.row_set_int(r, "id", id).row_set(r, "X", tidy(p.x())).row_set(r, "Y", tidy(p.y())).row_set(r, "Z", tidy(p.z()));
    };
    put(g.impactor_main_node, g.face_centre + 0.5 * length * u);
    for (std::size_t i = 0; i < disc.nodes.size(); ++i) {
      secondaries.push_back(node0 + 2 + static_cast<std::int64_t>(i));
      put(secondaries.back(), disc.nodes[i]);
    }
    nodes.commit();
  }
  const std::int64_t part = obj + 1;
  CardBuilder(d, "/MAT/LAW1", part, "impactor steel (rigid body: elements inactive)")
      .set(0, "rho", kSteelDensity).set(1, "E", kSteelModulus).set(1, "nu", 0.3).commit();
  CardBuilder(d, "/PROP/TYPE1", part, "impactor shell").set(2, "Thick", kShellThickness).commit();
  CardBuilder(d, "/PART", part, "impactor").set_int(0, "prop_id", part).set_int(0, "mat_id", part).commit();
  {
    CardBuilder q(d, "/SHELL", part);
    std::int64_t e = elem0;
    for (const auto& s : disc.quads) {
      const std::size_t r = q.add_row();
      q.row_set_int(r, "id", ++e);
      for (int k = 0; k < 4; ++k) q.row_set_int(r, kN[k], secondaries[static_cast<std::size_t>(s[static_cast<std::size_t>(k)])]);
    }
    q.commit();
    CardBuilder t(d, "/SH3N", part);
    for (const auto& s : disc.trias) {
      const std::size_t r = t.add_row();
      t.row_set_int(r, "id", ++e);
      for (int k = 0; k < 3; ++k) t.row_set_int(r, kN[k], secondaries[static_cast<std::size_t>(s[static_cast<std::size_t>(k)])]);
    }
    t.commit();
  }
  add_node_group(d, obj + 1, "impactor secondary nodes", secondaries);
  add_node_group(d, obj + 2, "impactor main node", {g.impactor_main_node});
  std::vector<std::int64_t> all_impactor = secondaries;
  all_impactor.insert(all_impactor.begin(), g.impactor_main_node);
  add_node_group(d, obj + 3, "impactor all nodes", all_impactor);
  add_part_group(d, "/GRNOD/PART", obj + 4, "nodes in contact with the impactor (struck skin, limbs in the path)",
                 all_contact_parts);
  CardBuilder(d, "/RBODY", obj + 1, "impactor rigid body")
      .set_int(0, "node_id", g.impactor_main_node).set(0, "Mass", added_mass).set_int(0, "grnod_id", obj + 1)
      .set(1, "Jxx", tidy(J(0, 0))).set(1, "Jyy", tidy(J(1, 1))).set(1, "Jzz", tidy(J(2, 2)))
      .set(2, "Jxy", tidy(J(0, 1))).set(2, "Jyz", tidy(J(1, 2))).set(2, "Jxz", tidy(J(0, 2)))
      .commit();
  CardBuilder(d, "/BCS", obj + 1, "impactor guided: rotations fixed")
      .set_text(0, "Tra", "000").set_text(0, "rot", "111").set_int(0, "grnod_id", obj + 2).commit();
  const Eigen::Vector3d v0 = spec.speed_m_s * g.travel;
  CardBuilder(d, "/INIVEL/TRA", obj + 1, "impactor initial velocity")
      .set(0, "Vx", tidy(v0.x())).set(0, "Vy", tidy(v0.y())).set(0, "Vz", tidy(v0.z())).set_int(0, "grnod_id", obj + 3).commit();
  add_part_group(d, "/SURF/PART", obj + 1, "impactor face, rounded edge and rim", {part});
  CardBuilder(d, "/INTER/TYPE7", obj + 1, "impactor contact")
      .set_int(0, "grnod_id", obj + 4).set_int(0, "surf_id", obj + 1)
      .set(3, "Stfac", 1.0).set(3, "Fric", spec.friction).set(3, "Gapmin", spec.contact_gap_mm)
      .set(4, "VISs", spec.contact_damping)
      .commit();
  {
    CardBuilder t(d, "/TH/NODE", obj + 1, "impactor and landmarks");
    t.name_row_set_text(t.add_name_row(), "var1", "DEF");
    auto row = [&](std::int64_t n, const std::string& name) {
      const std::size_t r = t.add_row();
      t.row_set_int(r, "node_id", n).row_set_text(r, "name", name);
    };
    row(g.impactor_main_node, "impactor");
    row(g.spine_node, spec.spine_level);
    row(g.sternum_node, "sternum");
    t.commit();
  }
  add_th(d, "/TH/RBODY", obj + 2, "impactor rigid body", {"FX", "FY", "FZ", "VX", "VY", "VZ"}, {obj + 1});
  add_th(d, "/TH/INTER", obj + 3, "impactor contact", {"FN", "FT", "ECONT"}, {obj + 1});
  {
    // Internal and hourglass energy, added mass and deleted elements of every part: where
    // energy and mass go, and the failed rib elements of the rib fracture model
    // (hbm-deckgen --rib-fracture; the corridor cases count them).
    std::vector<std::int64_t> parts;
    for (const auto& [pid, title] : model.part_titles) parts.push_back(pid);
    parts.push_back(part);
    add_th(d, "/TH/PART", obj + 4, "parts", {"IE", "HE", "AM", "ER"}, parts);
  }

  // Texts.
  const std::string rel_model = fs::relative(fs::absolute(model_path), fs::absolute(out_dir)).generic_string();
  std::ostringstream head;
  head << "# " << spec.name << ": " << spec.title << ".\n"
       << "# Test: " << spec.reference << ". Corridor case: " << spec.corridor_case << ".\n"
       << "# Generated by hbm-loadcase from " << model_path.generic_string() << " (included below) and "
       << geometry_dir.generic_string() << "; regenerate rather than edit, or edit by hand and rerun.\n"
       << "# Impactor: rigid body " << obj + 1 << " (part " << part << ", main node " << g.impactor_main_node << "), "
       << fmt(spec.mass_kg, 2) << " kg = " << fmt(shell_mass, 4) << " kg shells + " << fmt(added_mass, 4)
       << " kg added, face diameter " << fmt(spec.face_diameter_mm, 0) << " mm (flat " << fmt(2 * (R - shape.edge_radius))
       << " mm, edge radius " << fmt(shape.edge_radius) << " mm), rotations fixed,\n"
       << "#   initial velocity " << fmt(spec.speed_m_s, 2) << " m/s (= mm/ms) along (" << fmt(g.travel.x(), 4) << ", "
       << fmt(g.travel.y(), 4) << ", " << fmt(g.travel.z(), 4) << ") in /INIVEL/TRA/" << obj + 1
       << "; face centre (" << fmt(g.face_centre.x()) << ", " << fmt(g.face_centre.y()) << ", " << fmt(g.face_centre.z())
       << ") mm,\n#   " << fmt(spec.initial_clearance_mm) << " mm clear of " << g.nearest_part << ", contact gap " << fmt(spec.contact_gap_mm)
       << " mm: first contact at about " << fmt(g.first_contact_ms, 3) << " ms.\n"
       << "# Contact /INTER/TYPE7/" << obj + 1 << ": nodes of the parts " ;
  for (std::size_t i = 0; i < all_contact_parts.size(); ++i)
    head << (i ? ", " : "") << model.part_titles.at(all_contact_parts[i]);
  head << " on the impactor face (friction " << fmt(spec.friction, 2)
       << ", critical damping VISs " << fmt(spec.contact_damping, 2) << ").\n"
       << (spec.posture.empty() ? std::string() : "# Posture: " + spec.posture + ", model " + spec.posed_model + " = " +
                                                     spec.posed_model_command() + ".\n")
       << "# Subject free (no seat, no back support, no gravity: the event lasts " << fmt(spec.tstop_ms, 0) << " ms).\n"
       << "# Time histories: /TH/NODE/" << obj + 1 << " (impactor main node, " << spec.spine_level << " node "
       << g.spine_node << ", sternum node " << g.sternum_node << "), /TH/RBODY/" << obj + 2 << ", /TH/INTER/" << obj + 3
       << ", /TH/PART/" << obj + 4 << " (IE HE AM ER of every part).\n# Run:  hbm-solver " << spec.name << "_0000.rad --out RUN_DIR\n"
       << "# Rate: hbm-corridors --case " << spec.corridor_case << " --th RUN_DIR --out REPORT_DIR\n";

  // Write into a temporary sibling folder, check, then rename.
  fs::path dir = fs::absolute(out_dir).lexically_normal();
  if (dir.filename().empty()) dir = dir.parent_path();  // "decks/case/"
  fs::create_directories(dir.parent_path());
  std::string tmp_name = dir.filename().string();
  tmp_name.insert(0, 1, '.');
  tmp_name += ".tmp-";
  tmp_name += std::to_string(::getpid());
  const fs::path tmp = dir.parent_path() / tmp_name;
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  try {
    const fs::path starter = tmp / (spec.name + "_0000.rad"), engine = tmp / (spec.name + "_0001.rad");
    {
      std::ofstream os(starter);
      os << "#RADIOSS STARTER\n" << head.str();
      hbm::deck::write_card(os, d.cards.front(), d);
      os << "#include " << rel_model << "\n";
      for (std::size_t i = n_begin; i < d.cards.size(); ++i) hbm::deck::write_card(os, d.cards[i], d);
      os << "/END\n";
      if (!os) throw std::runtime_error("cannot write " + starter.string());
    }
    {
      std::ofstream os(engine);
      os << "#RADIOSS ENGINE\n" << head.str()
         << "/RUN/" << spec.name << "/1\n" << spec.tstop_ms << "\n"
         << "/TFILE/4\n" << spec.th_interval_ms << "\n"
         << "/PRINT/-1000\n"
         << "/ANIM/DT\n0 " << spec.anim_interval_ms << "\n"
         << "/ANIM/VECT/DISP\n/ANIM/ELEM/VONM\n/ANIM/NODA/DMAS\n"
         << "# fixed step 1.5 us with nodal mass scaling, as the model is built for\n"
         << "/DT/NODA/CST/0\n0.9 1.5E-3\n"
         << "# a quad whose step falls to 1.5 us keeps its shape from then on (small strain): a skin\n"
         << "# quad folding at the neck base cannot outrun the mass scaling; the listing names them\n"
         << "/DT/SHELL/CST\n0.9 1.5E-3\n"
         << "# a brick whose step deformation brings below 1.4 us (a little under the fixed step: the\n"
         << "# undeformed organ bricks' own step is within Tsca of it), or whose volume to 0.3 of its\n"
         << "# initial one, keeps its geometry from then on (small strain): no inverted soft tissue\n"
         << "/DT/BRICK/CST/1\n0.9 1.4E-3\n0 0.3\n"
         << "# stop if the added mass exceeds 1 % of the model mass\n"
         << "/STOP\n0 0.01 0 1 1\n";
      if (!os) throw std::runtime_error("cannot write " + engine.string());
    }
    check_written(starter, hbm::deck::Section::Starter);
    check_written(engine, hbm::deck::Section::Engine);
    fs::remove_all(dir);
    fs::rename(tmp, dir);
  } catch (...) {
    fs::remove_all(tmp);
    throw;
  }
  g.starter = out_dir / (spec.name + "_0000.rad");
  g.engine = out_dir / (spec.name + "_0001.rad");
  return g;
}

void print_generated(std::ostream& os, const LoadCaseSpec& spec, const GeneratedCase& g) {
  os << spec.name << ": " << g.starter.generic_string() << ", " << g.engine.generic_string() << "\n"
     << "  impactor " << fmt(g.impactor_mass_kg, 3) << " kg at " << fmt(spec.speed_m_s, 2) << " m/s, face centre ("
     << fmt(g.face_centre.x()) << ", " << fmt(g.face_centre.y()) << ", " << fmt(g.face_centre.z())
     << ") mm, travel (" << fmt(g.travel.x(), 3) << ", " << fmt(g.travel.y(), 3) << ", " << fmt(g.travel.z(), 3)
     << "), first contact ~" << fmt(g.first_contact_ms, 3) << " ms\n"
     << "  contact nodes " << g.contact_nodes << " (" << g.limb_contact_nodes << " of limbs; " << g.footprint_contact_nodes
     << " in the footprint, nearest of " << g.nearest_part << "); "
     << spec.spine_level << " node " << g.spine_node << " (" << fmt(g.spine_node_distance_mm) << " mm from the body centre), sternum node "
     << g.sternum_node << ", impactor main node " << g.impactor_main_node << "\n";
  for (const auto& w : g.warnings) os << "  warning: " << w << "\n";
}

}  // namespace hbm::deckgen::loadcases
