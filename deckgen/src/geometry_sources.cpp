// SPDX-License-Identifier: GPL-3.0-or-later
// Readers of the geometry/ tables with range and consistency checks (file:line errors).
#include "hbm/deckgen/geometry_sources.hpp"

#include "hbm/deckgen/table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hbm::deckgen {

namespace {

// Level name such as "C7" or "T12". Built by appending: GCC 12 reports a false -Wrestrict
// on "T" + std::to_string(i) (the prepend of the literal into the temporary).
std::string level_name(char region, int i) {
  std::string name(1, region);
  name += std::to_string(i);
  return name;
}

}  // namespace

TrunkSection SectionTable::at(double z) const {
  if (z <= rows.front().z) return rows.front();
  if (z >= rows.back().z) return rows.back();
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (z <= rows[i].z) {
      const TrunkSection &a = rows[i - 1], &b = rows[i];
      double t = (z - a.z) / (b.z - a.z);
      auto l = [t](double p, double q) { return p + t * (q - p); };
      TrunkSection s;
      s.z = z;
      s.half_width = l(a.half_width, b.half_width);
      s.half_depth = l(a.half_depth, b.half_depth);
      s.exponent = l(a.exponent, b.exponent);
      s.back = l(a.back, b.back);
      s.widest_forward = l(a.widest_forward, b.widest_forward);
      s.wall_half_width = l(a.wall_half_width, b.wall_half_width);
      s.wall_depth = l(a.wall_depth, b.wall_depth);
      s.wall_exponent = l(a.wall_exponent, b.wall_exponent);
      return s;
    }
  }
  return rows.back();
}

std::vector<VertebraLandmarks> read_spine(const std::filesystem::path& file) {
  Table t = Table::read(file);
  std::vector<VertebraLandmarks> out;
  static const std::vector<std::string> expected = [] {
    std::vector<std::string> v;
    for (int i = 1; i <= 7; ++i) v.push_back(level_name('C', i));
    for (int i = 1; i <= 12; ++i) v.push_back(level_name('T', i));
    for (int i = 1; i <= 5; ++i) v.push_back(level_name('L', i));
    v.push_back("S1");
    return v;
  }();
  for (const auto& r : t.rows()) {
    VertebraLandmarks v;
    v.name = t.text(r, "level");
    v.line = r.line;
    if (out.size() >= expected.size() || v.name != expected[out.size()])
      t.fail(r, "level", "expected " + (out.size() < expected.size() ? expected[out.size()] : std::string("end of table")) +
                             " (levels C1..C7, T1..T12, L1..L5, S1 in order)");
    v.upper = {t.number_in(r, "upper_x_mm", -1000, 1000), t.number_in(r, "upper_z_mm", -500, 2000)};
    v.lower = {t.number_in(r, "lower_x_mm", -1000, 1000), t.number_in(r, "lower_z_mm", -500, 2000)};
    if (!(v.upper.y() > v.lower.y())) t.fail(r, "upper_z_mm", "upper endplate must lie above the lower one");
    if (!out.empty() && !(out.back().lower.y() > v.upper.y()))
      t.fail(r, "upper_z_mm", "upper endplate must lie below the lower endplate of " + out.back().name + " (disc height > 0)");
    out.push_back(v);
  }
  if (out.size() != expected.size())
    throw SourceError(file, t.rows().back().line, "level", "table ends before S1");
  return out;
}

SectionTable read_sections(const std::filesystem::path& file) {
  Table t = Table::read(file);
  SectionTable s;
  for (const auto& r : t.rows()) {
    TrunkSection c;
    c.z = t.number_in(r, "z_mm", -500, 2000);
    c.half_width = t.number_in(r, "half_width_mm", 5, 500);
    c.half_depth = t.number_in(r, "half_depth_mm", 5, 500);
    c.exponent = t.number_in(r, "exponent", 1.5, 10);
    c.back = t.number_in(r, "back_mm", 5, 300);
    // Optional: the widest point of the skin curve ahead of its depth centre (0: symmetric).
    if (t.has_column("widest_forward_mm") && !t.blank(r, "widest_forward_mm")) {
      c.widest_forward = t.number(r, "widest_forward_mm");
      if (std::abs(c.widest_forward) > 0.6 * c.half_depth)
        t.fail(r, "widest_forward_mm", "the widest point must lie within 0.6 half_depth_mm of the depth centre");
    }
    c.wall_half_width = t.number_in(r, "wall_half_width_mm", 5, 500);
    c.wall_depth = t.number_in(r, "wall_depth_mm", 5, 500);
    c.wall_exponent = t.number_in(r, "wall_exponent", 1.5, 10);
    if (c.wall_half_width >= c.half_width) t.fail(r, "wall_half_width_mm", "the wall must lie inside the skin (wall half-width < half-width)");
    if (c.back + c.wall_depth >= 2 * c.half_depth + 1e-9)
      t.fail(r, "wall_depth_mm", "the wall must lie inside the skin (back_mm + wall_depth_mm < 2 half_depth_mm)");
    if (!s.rows.empty() && c.z <= s.rows.back().z) t.fail(r, "z_mm", "sections must be given in increasing z");
    s.rows.push_back(c);
  }
  if (s.rows.size() < 2) throw SourceError(file, t.rows().back().line, "", "at least two sections are needed");
  return s;
}

std::vector<RibSpec> read_ribs(const std::filesystem::path& file) {
  Table t = Table::read(file);
  std::vector<RibSpec> out;
  for (const auto& r : t.rows()) {
    RibSpec s;
    s.line = r.line;
    s.index = t.integer(r, "rib");
    if (s.index != static_cast<int>(out.size()) + 1) t.fail(r, "rib", "ribs must be numbered 1..12 in order");
    s.vertebra = t.text(r, "vertebra");
    const std::string thoracic = level_name('T', s.index);
    if (s.vertebra != thoracic) t.fail(r, "vertebra", "rib " + std::to_string(s.index) + " attaches to " + thoracic);
    s.inclination_deg = t.number_in(r, "inclination_deg", 0, 45);
    s.end_fraction = t.number_in(r, "end_fraction", 0.2, 0.95);
    std::string c = t.text(r, "cartilage");
    if (c == "sternum") s.cartilage = CartilageKind::Sternum;
    else if (c == "costal_margin") s.cartilage = CartilageKind::CostalMargin;
    else if (c == "none") s.cartilage = CartilageKind::None;
    else t.fail(r, "cartilage", "'" + c + "': expected sternum, costal_margin or none");
    const char* st[3] = {"head", "mid", "end"};
    for (int i = 0; i < 3; ++i) {
      s.height[i] = t.number_in(r, std::string("height_") + st[i] + "_mm", 2, 40);
      s.width[i] = t.number_in(r, std::string("width_") + st[i] + "_mm", 2, 30);
      s.cortical[i] = t.number_in(r, std::string("cortical_") + st[i] + "_mm", 0.1, 5);
      if (2 * s.cortical[i] >= std::min(s.height[i], s.width[i]))
        t.fail(r, std::string("cortical_") + st[i] + "_mm", "cortex thicker than half the section");
    }
    out.push_back(s);
  }
  if (out.size() != 12) throw SourceError(file, t.rows().back().line, "rib", "12 rib pairs are required");
  return out;
}

std::map<std::string, MaterialSpec> read_materials(const std::filesystem::path& file) {
  Table t = Table::read(file);
  std::map<std::string, MaterialSpec> out;
  for (const auto& r : t.rows()) {
    MaterialSpec m;
    m.line = r.line;
    m.name = t.text(r, "name");
    m.law = t.text(r, "law");
    m.source = t.text(r, "source");
    if (m.source.empty()) t.fail(r, "source", "every material needs its source");
    m.density = t.number_in(r, "density", 1, 20000);
    if (m.law == "LAW1") {
      m.e_or_k = t.number_in(r, "E_or_K", 0, 1e6);
      m.nu = t.number_in(r, "nu", -0.99, 0.4999);
    } else if (m.law == "LAW34") {
      m.e_or_k = t.number_in(r, "E_or_K", 1e-9, 1e6);
      m.g0 = t.number_in(r, "G0", 1e-9, 1e6);
      m.ginf = t.number_in(r, "Ginf", 0, 1e6);
      m.beta = t.number_in(r, "beta", 0, 1e9);
      if (m.ginf > m.g0) t.fail(r, "Ginf", "long-time shear modulus above the short-time one");
    } else {
      t.fail(r, "law", "'" + m.law + "': expected LAW1 or LAW34");
    }
    if (out.count(m.name)) t.fail(r, "name", "duplicate material '" + m.name + "'");
    out[m.name] = m;
  }
  for (const char* need : {"rib_cortical", "sternum_cortical", "costal_cartilage", "clavicle_cortical", "pelvis_cortical",
                           "pelvic_joint", "vertebra", "disc_thoracolumbar", "disc_cervical", "thoracic_organs", "lungs",
                           "abdominal_organs", "flesh", "subcutaneous_fat", "muscle", "skin", "envelope", "thoracic_inlet_fascia"})
    if (!out.count(need)) throw SourceError(file, t.rows().back().line, "name", std::string("material '") + need + "' is missing");
  return out;
}

namespace {

HeadEnvelope read_head(const std::filesystem::path& file) {
  Table t = Table::read(file);
  HeadEnvelope h;
  std::map<std::string, double*> f{{"semi_axis_x", &h.ax}, {"semi_axis_y", &h.ay}, {"semi_axis_z", &h.az},
                                   {"centre_above_cog", &h.centre_above_cog}};
  for (const auto& r : t.rows()) {
    auto it = f.find(t.text(r, "quantity"));
    if (it == f.end()) t.fail(r, "quantity", "unknown quantity '" + t.text(r, "quantity") + "'");
    *it->second = t.number_in(r, "value_mm", -100, 300);
  }
  if (h.ax < 50 || h.ay < 50 || h.az < 50) throw SourceError(file, t.rows().back().line, "value_mm", "head semi-axes missing or below 50 mm");
  return h;
}

std::map<std::string, std::vector<LimbSection>> read_limbs(const std::filesystem::path& file) {
  Table t = Table::read(file);
  std::map<std::string, std::vector<LimbSection>> out;
  for (const auto& r : t.rows()) {
    std::string seg = t.text(r, "segment");
    if (seg != "humerus" && seg != "forearm" && seg != "femur" && seg != "tibia" && seg != "foot")
      t.fail(r, "segment", "'" + seg + "': expected humerus, forearm, femur, tibia or foot");
    LimbSection s;
    s.fraction = t.number_in(r, "fraction", -0.5, 2.5);
    s.half_width = t.number_in(r, "half_width_mm", 3, 200);
    s.half_depth = t.number_in(r, "half_depth_mm", 3, 200);
    s.exponent = t.number_in(r, "exponent", 1.5, 10);
    auto& v = out[seg];
    if (!v.empty() && s.fraction <= v.back().fraction) t.fail(r, "fraction", "fractions must increase along a segment");
    v.push_back(s);
  }
  for (const char* s : {"humerus", "forearm", "femur", "tibia", "foot"})
    if (out[s].size() < 2) throw SourceError(file, t.rows().back().line, "segment", std::string("segment '") + s + "' needs at least two sections");
  return out;
}

std::map<std::string, Eigen::Vector3d> read_pelvis(const std::filesystem::path& file) {
  Table t = Table::read(file);
  std::map<std::string, Eigen::Vector3d> out;
  for (const auto& r : t.rows()) {
    std::string n = t.text(r, "name");
    Eigen::Vector3d p(t.number_in(r, "x_mm", -500, 500), t.number_in(r, "y_mm", -500, 500), t.number_in(r, "z_mm", -500, 500));
    if (n.size() > 2 && n.substr(n.size() - 2) == "_r") {
      if (p.y() >= 0) t.fail(r, "y_mm", "right-side landmark must have y < 0 (y points to the occupant's left)");
      out[n] = p;
      std::string l = n.substr(0, n.size() - 2) + "_l";
      if (!out.count(l)) out[l] = Eigen::Vector3d(p.x(), -p.y(), p.z());
    } else if (n.size() > 2 && n.substr(n.size() - 2) == "_l") {
      if (p.y() <= 0) t.fail(r, "y_mm", "left-side landmark must have y > 0");
      out[n] = p;
    } else {
      out[n] = p;
    }
  }
  for (const char* need : {"acetabulum_r", "acetabulum_l", "S1_plate", "asis_r", "psis_r", "iliac_tubercle_r",
                           "pubic_symphysis", "ischial_tuberosity_r", "greater_trochanter_r", "sacral_apex"})
    if (!out.count(need)) throw SourceError(file, t.rows().back().line, "name", std::string("landmark '") + need + "' is missing");
  return out;
}

std::map<std::string, Eigen::Vector3d> read_limb_points(const std::filesystem::path& file) {
  Table t = Table::read(file);
  std::map<std::string, Eigen::Vector3d> out;
  for (const auto& r : t.rows()) {
    std::string n = t.text(r, "name");
    Eigen::Vector3d p(t.number_in(r, "x_mm", -1500, 1500), t.number_in(r, "y_mm", -500, 500), t.number_in(r, "z_mm", -1000, 1500));
    bool right = n.size() > 2 && n.substr(n.size() - 2) == "_r";
    if ((right && p.y() >= 0) || (!right && p.y() <= 0)) t.fail(r, "y_mm", "side suffix and sign of y disagree (y > 0 is the left side)");
    out[n] = p;
  }
  for (const char* need : {"wrist_r", "wrist_l", "ankle_r", "ankle_l", "heel_r", "heel_l", "toe_r", "toe_l"})
    if (!out.count(need)) throw SourceError(file, t.rows().back().line, "name", std::string("point '") + need + "' is missing");
  return out;
}

std::map<std::string, JointSpec> read_joints(const std::filesystem::path& file) {
  Table t = Table::read(file);
  std::map<std::string, JointSpec> out;
  for (const auto& r : t.rows()) {
    JointSpec j;
    j.line = r.line;
    j.name = t.text(r, "name");
    j.kind = t.text(r, "kind");
    if (j.kind == "TYPE8") {
      const char* kn[3] = {"kx", "ky", "kz"};
      const char* rn[3] = {"krx", "kry", "krz"};
      for (int i = 0; i < 3; ++i) {
        j.k[i] = t.number_in(r, kn[i], 1e-6, 1e7);
        j.kr[i] = t.number_in(r, rn[i], 1e-6, 1e6);
      }
      j.c_rot = t.number_in(r, "c_rot", 0, 1e4);
    } else if (j.kind == "TYPE4") {
      j.k[0] = t.number_in(r, "kx", 1e-6, 1e7);
    } else {
      t.fail(r, "kind", "'" + j.kind + "': expected TYPE8 or TYPE4");
    }
    j.c_trans = t.number_in(r, "c_trans", 0, 1e4);
    out[j.name] = j;
  }
  for (const char* need : {"hip", "knee", "elbow", "shoulder", "sternoclavicular", "occiput_c1", "odontoid_c1", "cervical_ligament"})
    if (!out.count(need)) throw SourceError(file, t.rows().back().line, "name", std::string("joint '") + need + "' is missing");
  return out;
}

std::vector<SegmentTarget> read_targets(const std::filesystem::path& file) {
  Table t = Table::read(file);
  std::vector<SegmentTarget> out;
  for (const auto& r : t.rows()) {
    SegmentTarget s;
    s.line = r.line;
    s.name = t.text(r, "segment");
    s.mass = t.number_in(r, "mass_kg", 0.01, 200);
    s.cog_mode = t.text(r, "cog_mode");
    if (s.cog_mode == "axis") s.axis_fraction = t.number_in(r, "axis_fraction", 0, 1);
    else if (s.cog_mode != "link" && s.cog_mode != "none") t.fail(r, "cog_mode", "expected link, axis or none");
    s.check_mass = t.integer(r, "check_mass") != 0;
    s.check_cog = t.integer(r, "check_cog") != 0;
    if (t.has_column("neck_share_kg") && !t.blank(r, "neck_share_kg")) s.neck_share = t.number_in(r, "neck_share_kg", 0, 5);
    s.source = t.text(r, "source");
    if (s.source.empty()) t.fail(r, "source", "every target needs its source");
    out.push_back(s);
  }
  return out;
}

std::map<std::string, ShellSection> read_shell_sections(const std::filesystem::path& file) {
  Table t = Table::read(file);
  std::map<std::string, ShellSection> out;
  for (const auto& r : t.rows()) {
    ShellSection s;
    s.line = r.line;
    s.total_thickness = t.number_or(r, "total_thickness_mm", 0);
    s.cortical = t.number_or(r, "cortical_mm", 0);
    s.height = t.number_or(r, "height_mm", 0);
    s.width = t.number_or(r, "width_mm", 0);
    s.core_density = t.number_or(r, "core_density", 0);
    s.joint_gap = t.number_or(r, "joint_gap_mm", 0);
    if (s.total_thickness < 0 || s.cortical < 0 || s.height < 0 || s.width < 0 || s.core_density < 0 || s.joint_gap < 0)
      t.fail(r, "", "negative section value");
    if (s.cortical > s.total_thickness / 2 + 1e-12 && s.total_thickness > 0 && s.cortical != s.total_thickness)
      t.fail(r, "cortical_mm", "cortex thicker than half the section");
    out[t.text(r, "name")] = s;
  }
  for (const char* need : {"sternum", "costal_cartilage", "clavicle", "pelvis_cortex", "pelvic_joints", "skin", "envelope",
                           "thoracic_inlet_fascia", "abdominal_wall"})
    if (!out.count(need)) throw SourceError(file, t.rows().back().line, "name", std::string("section '") + need + "' is missing");
  const ShellSection& cc = out["costal_cartilage"];
  if (cc.height <= 0 || cc.width <= 0) throw SourceError(file, cc.line, "height_mm", "costal cartilage needs height and width");
  if (out["pelvic_joints"].joint_gap <= 0)
    throw SourceError(file, out["pelvic_joints"].line, "joint_gap_mm", "the pelvic joint bands need the joint space they stand for (> 0)");
  for (const char* need : {"sternum", "clavicle", "pelvis_cortex", "pelvic_joints", "skin", "envelope", "thoracic_inlet_fascia",
                           "abdominal_wall"})
    if (out[need].total_thickness <= 0) throw SourceError(file, out[need].line, "total_thickness_mm", std::string(need) + " needs a thickness > 0");
  return out;
}

// Rib cortical bone beyond yield (rib_fracture.csv): one row per quantity.
RibBoneFailure read_rib_fracture(const std::filesystem::path& file, double E) {
  Table t = Table::read(file);
  std::map<std::string, std::pair<double, int>> q;
  for (const auto& r : t.rows()) {
    const std::string name = t.text(r, "quantity");
    if (q.count(name)) t.fail(r, "quantity", "duplicate quantity '" + name + "'");
    if (t.text(r, "source").empty()) t.fail(r, "source", "every quantity needs its source");
    q[name] = {t.number(r, "value"), r.line};
  }
  auto get = [&](const char* name, double lo, double hi) {
    auto it = q.find(name);
    if (it == q.end()) throw SourceError(file, t.rows().empty() ? 0 : t.rows().back().line, "quantity", std::string("'") + name + "' is missing");
    const double v = it->second.first;
    if (!(v >= lo && v <= hi))
      throw SourceError(file, it->second.second, "value", std::string(name) + " = " + std::to_string(v) + " is outside [" +
                                                             std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
  };
  RibBoneFailure b;
  b.E = E;
  b.yield_stress = get("yield_stress", 1, 1000);
  b.plastic_modulus = get("plastic_modulus", 0, 1e5);
  b.log_median_intercept = get("ultimate_strain_log_median_intercept", -10, 0);
  b.log_median_age_slope = get("ultimate_strain_log_median_age_slope", -1, 1);
  b.age_min = get("age_min", 0, 120);
  b.age_max = get("age_max", 0, 120);
  if (b.age_max <= b.age_min) throw SourceError(file, q["age_max"].second, "value", "age_max must exceed age_min");
  // The failure strain must lie beyond yield over the whole age range.
  for (double age : {b.age_min, b.age_max})
    if (b.ultimate_strain(age) <= b.yield_strain())
      throw SourceError(file, q["ultimate_strain_log_median_intercept"].second, "value",
                        "the median ultimate strain at " + std::to_string(age) + " y is below the yield strain");
  return b;
}

std::map<std::string, double> read_disc_stiffness(const std::filesystem::path& file) {
  Table t = Table::read(file);
  std::map<std::string, double> out;
  for (const auto& r : t.rows()) {
    std::string d = t.text(r, "disc");
    if (out.count(d)) t.fail(r, "disc", "duplicate disc '" + d + "'");
    out[d] = t.number_in(r, "k_axial_N_per_mm", 1, 1e6);
    if (t.text(r, "source").empty()) t.fail(r, "source", "every stiffness needs its source");
  }
  std::vector<std::string> need{"T1T2", "T2T3", "T3T4", "T4T5", "T5T6", "T6T7", "T7T8", "T8T9", "T9T10", "T10T11", "T11T12",
                                "T12L1", "L1L2", "L2L3", "L3L4", "L4L5", "L5S1"};
  for (const auto& n : need)
    if (!out.count(n)) throw SourceError(file, t.rows().back().line, "disc", "disc '" + n + "' is missing");
  return out;
}

MediastinumSpec read_thoracic_organs(const std::filesystem::path& file, const std::vector<VertebraLandmarks>& spine) {
  Table t = Table::read(file);
  MediastinumSpec m;
  for (const auto& r : t.rows()) {
    const std::string part = t.text(r, "part");
    if (part != "mediastinum") t.fail(r, "part", "unknown part '" + part + "' (expected mediastinum)");
    if (m.line) t.fail(r, "part", "duplicate part 'mediastinum'");
    m.line = r.line;
    m.half_width = t.number_in(r, "half_width_mm", 1, 150);
    m.top_vertebra = t.text(r, "top_vertebra");
    const bool thoracic = std::any_of(spine.begin(), spine.end(), [&](const VertebraLandmarks& v) { return v.name == m.top_vertebra; }) &&
                          m.top_vertebra.size() > 1 && m.top_vertebra[0] == 'T';
    if (!thoracic) t.fail(r, "top_vertebra", "'" + m.top_vertebra + "' is not a thoracic vertebra of spine_landmarks.csv");
    if (t.text(r, "source").empty()) t.fail(r, "source", "the mediastinum needs its source");
  }
  if (!m.line) throw SourceError(file, 0, "part", "part 'mediastinum' is missing");
  return m;
}

}  // namespace

const VertebraLandmarks& GeometrySources::vertebra(const std::string& name) const {
  for (const auto& v : spine)
    if (v.name == name) return v;
  throw SourceError(dir / "spine_landmarks.csv", 0, "level", "vertebra '" + name + "' is missing");
}
// The readers require every name the mesher asks for; these lookups still name the file
// (not a bare map::at) should a caller ask for one they do not require.
const MaterialSpec& GeometrySources::material(const std::string& name) const {
  auto it = materials.find(name);
  if (it == materials.end()) throw SourceError(dir / "materials.csv", 0, "name", "material '" + name + "' is missing");
  return it->second;
}
const JointSpec& GeometrySources::joint(const std::string& name) const {
  auto it = joints.find(name);
  if (it == joints.end()) throw SourceError(dir / "joints.csv", 0, "name", "joint '" + name + "' is missing");
  return it->second;
}

GeometrySources load_geometry(const std::filesystem::path& dir) {
  GeometrySources g;
  g.dir = dir;
  g.spine = read_spine(dir / "spine_landmarks.csv");
  g.torso = read_sections(dir / "torso_sections.csv");
  g.neck = read_sections(dir / "neck_sections.csv");
  g.head = read_head(dir / "head_envelope.csv");
  g.limbs = read_limbs(dir / "limb_sections.csv");
  g.ribs = read_ribs(dir / "rib_cage.csv");
  g.pelvis = read_pelvis(dir / "pelvis_landmarks.csv");
  g.limb_points = read_limb_points(dir / "limb_landmarks.csv");
  g.materials = read_materials(dir / "materials.csv");
  g.joints = read_joints(dir / "joints.csv");
  g.targets = read_targets(dir / "segment_targets.csv");
  g.shell_sections = read_shell_sections(dir / "shell_sections.csv");
  g.disc_stiffness = read_disc_stiffness(dir / "disc_stiffness.csv");
  g.rib_bone = read_rib_fracture(dir / "rib_fracture.csv", g.material("rib_cortical").e_or_k);
  g.mediastinum = read_thoracic_organs(dir / "thoracic_organs.csv", g.spine);
  g.skeleton = Skeleton::read(dir / "skeleton.urdf");
  return g;
}

}  // namespace hbm::deckgen
