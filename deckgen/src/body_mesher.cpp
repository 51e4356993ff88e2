// SPDX-License-Identifier: GPL-3.0-or-later
// Body model construction from the geometry sources (see body_mesher.hpp). The torso and
// the neck are structured O-grids (trunk_grid.hpp); every cell's role (organ, flesh,
// vertebra, disc, sacrum) comes from its layer and ring; the rib cage, sternum, cartilage
// and pelvis are shells on the inner-wall ring sharing the hexahedra nodes (as in the
// seed model); head and limbs are shell envelopes in rigid bodies.
#include "hbm/deckgen/body_mesher.hpp"
#include "hbm/deckgen/abdominal_wall.hpp"
#include "hbm/deckgen/organ_variants.hpp"
#include "hbm/deckgen/rib_fracture.hpp"

#include "hbm/deckgen/surface_tools.hpp"
#include "hbm/deckgen/trunk_grid.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace hbm::deckgen {

EquivalentPlate sandwich_plate(double total, double cortical) {
  const double T = total, tc = std::min(cortical, total / 2);  // tc = T / 2: a solid plate
  const double Iw = (T * T * T - std::pow(T - 2 * tc, 3)) / 12, Aw = 2 * tc;
  EquivalentPlate p;
  p.thickness = std::sqrt(12 * Iw / Aw);
  p.modulus_scale = Aw / p.thickness;
  return p;
}

namespace {

// mm: the greater trochanter and femoral neck medial of its landmark (the lateral bony
// surface), est; torso nodes within it join the femur rigid body.
constexpr double kTrochanterBone = 30.0;

// The sternum spans the front cells of the T1 to T7 body layers (manubrium at the rib-1 band,
// xiphisternal junction at the rib-7 band).
constexpr const char* kSternumHighestBody = "T1";
constexpr const char* kSternumLowestBody = "T7";

// A point at the trochanter's bone: within kTrochanterBone of the landmark gt and not lateral
// of it (the tissue lateral of the landmark stays deformable).
bool at_trochanter_bone(const Eigen::Vector3d& x, const Eigen::Vector3d& gt) {
  return (x - gt).norm() <= kTrochanterBone && std::abs(x.y()) <= std::abs(gt.y());
}

constexpr double kDensity = 1e-9;  // kg/m^3 -> kg/mm^3
constexpr double kModulus = 1e-3;  // MPa -> GPa
constexpr double kRate = 1e-3;     // 1/s -> 1/ms

double sgnpow(double v, double e) { return std::copysign(std::pow(std::abs(v), e), v); }

enum class LayerKind { Flesh, Sacrum, Body, Disc };

struct LayerInfo {
  LayerKind kind = LayerKind::Flesh;
  std::string vertebra;  // Body: "T5"; Disc: "T4T5" (upper then lower)
  std::string region;    // thorax, abdomen, pelvis, neck
};

FeMaterial convert(const MaterialSpec& s, const std::string& name) {
  FeMaterial m;
  m.name = name;
  m.law = s.law;
  m.rho = s.density * kDensity;
  m.source = s.source;
  if (s.law == "LAW1") {
    m.E = s.e_or_k * kModulus;
    m.nu = s.nu;
  } else {
    m.K = s.e_or_k * kModulus;
    m.G0 = s.g0 * kModulus;
    m.Ginf = s.ginf * kModulus;
    m.beta = s.beta * kRate;
  }
  return m;
}

class Builder {
 public:
  Builder(const GeometrySources& g, const MesherOptions& o) : g_(g), o_(o) {}

  FeModel run(ModelLandmarks* lm);

 private:
  int material(const std::string& name) {
    int i = m_.find_material(name);
    if (i >= 0) return i;
    return m_.add_material(convert(g_.material(name), name));
  }
  // Material `name` for a sandwich plate of section `section` (shell_sections.csv) made of the
  // cortical material `cortex`: modulus scaled to the plate's equivalent shell
  // (sandwich_plate), density keeping the cortices' and the core's mass. Returns the
  // material and the equivalent thickness.
  std::pair<int, double> sandwich_material(const std::string& name, const std::string& cortex, const std::string& section) {
    const auto& sec = g_.shell_sections.at(section);
    const EquivalentPlate eq = sandwich_plate(sec.total_thickness, sec.cortical);
    FeMaterial m = convert(g_.material(cortex), name);
    const double T = sec.total_thickness, tc = std::min(sec.cortical, T / 2);
    m.E *= eq.modulus_scale;
    m.rho = (2 * tc * m.rho + (T - 2 * tc) * sec.core_density * kDensity) / eq.thickness;
    m.source += "; sandwich-equivalent thickness, modulus and density (shell_sections.csv)";
    return {m_.add_material(m), eq.thickness};
  }
  int part(const std::string& name, ElementKind kind, int mat, const std::string& segment, const std::string& region,
           double thickness = 0) {
    int i = m_.find_part(name);
    if (i >= 0) return i;
    FePart p;
    p.name = name;
    p.kind = kind;
    p.material = mat;
    p.segment = segment;
    p.region = region;
    p.thickness = thickness;
    return m_.add_part(p);
  }
  void brick(int part_index, const std::array<int, 8>& h) {
    m_.bricks.push_back(h);
    m_.brick_part.push_back(part_index);
  }
  void shell(int part_index, const std::array<int, 4>& q, double t = 0) {
    m_.shells.push_back(q);
    m_.shell_part.push_back(part_index);
    m_.shell_thick.push_back(t);
  }
  // A skin quad whose two triangulations differ by more than 15 deg (warpage) is split
  // into two triangles along its shorter diagonal (part `tri_part`).
  // Returns the shells made, triangles as quads with n4 = n3.
  std::vector<std::array<int, 4>> skin_quad(int quad_part, int tri_part, const std::array<int, 4>& q) {
    auto P = [&](int i) { return m_.nodes[static_cast<std::size_t>(q[static_cast<std::size_t>(i)])]; };
    if (quad_warpage_deg(P(0), P(1), P(2), P(3)) <= 15) {
      shell(quad_part, q);
      return {q};
    }
    std::array<int, 3> a{q[0], q[1], q[3]}, b{q[1], q[2], q[3]};
    if ((P(2) - P(0)).norm() <= (P(3) - P(1)).norm()) a = {q[0], q[1], q[2]}, b = {q[0], q[2], q[3]};
    tria(tri_part, a, 0);
    tria(tri_part, b, 0);
    return {{a[0], a[1], a[2], a[2]}, {b[0], b[1], b[2], b[2]}};
  }
  void tria(int part_index, const std::array<int, 3>& t, double th) {
    m_.trias.push_back(t);
    m_.tria_part.push_back(part_index);
    m_.tria_thick.push_back(th);
  }
  int spring(int part_index, int a, int b) {
    m_.springs.push_back({a, b});
    m_.spring_part.push_back(part_index);
    return static_cast<int>(m_.springs.size()) - 1;
  }
  int rigid(const std::string& name, const std::string& segment, int main, std::vector<int> nodes) {
    FeRigidBody r;
    r.id = static_cast<int>(m_.rigid_bodies.size()) + 1;
    r.name = name;
    r.segment = segment;
    r.main_node = main;
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    for (int n : nodes)
      if (rigid_of_.count(n))
        throw std::logic_error("node " + std::to_string(n + 1) + " in rigid bodies " + rigid_of_[n] + " and " + name);
    for (int n : nodes) rigid_of_[n] = name;
    r.nodes = std::move(nodes);
    m_.rigid_bodies.push_back(r);
    return static_cast<int>(m_.rigid_bodies.size()) - 1;
  }
  int spring_part(const std::string& joint_name) {
    std::string pname = "joint_" + joint_name;
    int i = m_.find_part(pname);
    if (i >= 0) return i;
    const JointSpec& j = g_.joint(joint_name);
    FeSpringProp sp;
    sp.id = static_cast<int>(m_.spring_props.size()) + 1;
    sp.name = joint_name;
    if (j.kind == "TYPE8") {
      sp.type = 8;
      for (int k = 0; k < 3; ++k) {
        sp.k[static_cast<std::size_t>(k)] = j.k[k] * 1e-3;        // N/mm -> kN/mm
        sp.k[static_cast<std::size_t>(k + 3)] = j.kr[k];          // N*m/rad = kN*mm/rad
        sp.c[static_cast<std::size_t>(k)] = j.c_trans;            // N*s/mm = kN*ms/mm
        sp.c[static_cast<std::size_t>(k + 3)] = j.c_rot * 1e3;    // N*m*s/rad -> kN*mm*ms/rad
      }
    } else {
      sp.type = 4;
      sp.k[0] = j.k[0] * 1e-3;
      sp.c[0] = j.c_trans;
    }
    m_.spring_props.push_back(sp);
    FePart p;
    p.name = pname;
    p.kind = ElementKind::Spring;
    p.material = -1;
    p.spring_prop = static_cast<int>(m_.spring_props.size()) - 1;
    p.segment = "joints";
    p.region = "joints";
    return m_.add_part(p);
  }
  Eigen::Vector3d moved(const std::string& link, const Eigen::Vector3d& p) const { return g_.skeleton.motion(link) * p; }

  void build_torso();
  int layer_of_body(const std::string& vertebra) const;  // torso layer of that vertebral body
  bool is_tetra_flesh_cell(int r, int j) const;
  // A flesh cell over the sternum: the front angular cells 0 and N-1 (the sternum's own) of
  // layers first_layer..last_layer within the sternum's span.
  bool is_presternal_cell(int first_layer, int last_layer, int j) const;
  void build_tetra_flesh(const std::map<std::string, int>& flesh, int presternal, const std::map<std::string, int>& skin,
                         const std::map<std::string, int>& skin_tri);
  void calibrate_disc(int layer, int part_index, double k_n_per_mm);
  void build_neck();
  void build_ribcage();
  void build_pelvis();
  void build_shoulders();
  void build_head();
  void build_limbs();
  // Shell envelope of a limb segment along p0 -> p1 (sections of limb_sections.csv `table`);
  // with clear_of, it begins where its section lies outside that closed surface, and not
  // before the axis fraction f_min.
  std::vector<int> limb_envelope(const std::string& link, const std::string& table, const Eigen::Vector3d& p0,
                                 const Eigen::Vector3d& p1, int part_index, const TriSurface* clear_of = nullptr,
                                 double f_min = -1e9);
  void build_contacts();
  void finalize_rigid_bodies();

  const GeometrySources& g_;
  const MesherOptions& o_;
  FeModel m_;
  std::map<int, std::string> rigid_of_;
  std::unique_ptr<TrunkGrid> torso_, neck_;
  std::vector<LayerInfo> torso_layers_, neck_layers_;
  std::pair<int, int> sternum_layers_{-1, -1};  // torso body layers of the sternum's lowest and highest vertebra
  int neck_top_level_ = 0;
  std::vector<std::array<int, 4>> torso_skin_, neck_skin_;
  std::vector<std::array<int, 8>> torso_hexes_;   // the fine grid's cells (also where flesh is tetras)
  std::vector<std::array<int, 4>> torso_top_faces_;  // top faces of the torso's solid cells (neck base tie)
  std::vector<std::pair<int, int>> tetra_flesh_rows_;  // flesh_tetra: bottom and top level of each cell row
  std::vector<std::array<int, 4>> cage_segments_;  // triangles as quads with n4 = n3
  std::set<int> pelvis_shell_nodes_, sternum_nodes_;
  int cart_part = -1, cart_mat = -1;
  double cart_ratio = 0;
  std::vector<int> head_env_nodes_, arm_env_nodes_[2], clavicle_nodes_[2];
  std::map<std::string, int> joint_node_;      // named joint nodes
  std::map<std::string, std::vector<int>> rb_nodes_;  // rigid-body secondary nodes by name
  std::map<std::string, Eigen::Vector3d> rb_main_at_;
  ModelLandmarks lm_;
};

// --- torso --------------------------------------------------------------------------------

void Builder::build_torso() {
  const auto& S1 = g_.vertebra("S1");
  // Level tilt: each disc layer keeps one tilt on both its surfaces (the mean of the rib
  // inclinations of its two vertebrae) so that thin discs never fold; the body layer between
  // two discs absorbs the change. Below T12 the tilt fades linearly to 0 at the L5 lower
  // plate (no ribs).
  const double incl12 = g_.ribs[11].inclination_deg * M_PI / 180;
  const double z_t12 = g_.vertebra("T12").lower.y(), z_l3 = g_.vertebra("L5").lower.y();
  auto incl_of = [&](const std::string& vert, double z) {
    if (vert.size() > 1 && vert[0] == 'T') return g_.ribs[static_cast<std::size_t>(std::stoi(vert.substr(1)) - 1)].inclination_deg * M_PI / 180;
    return incl12 * std::clamp((z - z_l3) / (z_t12 - z_l3), 0.0, 1.0);
  };
  auto tilt_at = [&](const std::string& name, double z) {
    // name: "T5_upper" / "T5_lower" / other; the disc above an upper plate is shared with the
    // vertebra above, the disc below a lower plate with the vertebra below.
    std::size_t us = name.find('_');
    if (us == std::string::npos) return incl_of("", z);
    std::string vert = name.substr(0, us), plate = name.substr(us + 1);
    int i = -1;
    for (std::size_t k = 0; k < g_.spine.size(); ++k)
      if (g_.spine[k].name == vert) i = static_cast<int>(k);
    if (i < 0 || (vert[0] != 'T' && vert[0] != 'L')) return incl_of("", z);
    int other = plate == "upper" ? i - 1 : i + 1;
    const auto& o = g_.spine[static_cast<std::size_t>(other)];
    double zo = plate == "upper" ? o.lower.y() : o.upper.y();
    double a = incl_of(vert, z), b = (o.name[0] == 'T' || o.name[0] == 'L') ? incl_of(o.name, zo) : a;
    return 0.5 * (a + b);
  };
  std::vector<GridLevel> lv;
  auto add = [&](const std::string& name, double x, double z, const std::string& vert, double r) {
    GridLevel l;
    l.name = name;
    l.x_spine = x;
    l.z_spine = z;
    (void)vert;
    l.tilt = tilt_at(name, z);
    l.body_radius = r;
    lv.push_back(l);
  };
  const double z_seat = g_.torso.rows.front().z;
  const Eigen::Vector2d apex = S1.lower, plate = S1.upper;
  add("seat", apex.x(), z_seat, "", 20);
  add("buttock", apex.x(), 0.5 * (z_seat + apex.y()), "", 20);
  for (int k = 0; k <= 3; ++k) {
    Eigen::Vector2d p = apex + (plate - apex) * (k / 3.0);
    add(k == 0 ? "sacral_apex" : k == 3 ? "S1_upper" : "sacrum_" + std::to_string(k), p.x(), p.y(), "", 20);
  }
  std::vector<LayerInfo> layers{{LayerKind::Flesh, "", "pelvis"}, {LayerKind::Flesh, "", "pelvis"},
                                {LayerKind::Sacrum, "S1", "pelvis"}, {LayerKind::Sacrum, "S1", "pelvis"},
                                {LayerKind::Sacrum, "S1", "pelvis"}};
  // Mass-property regions follow the Zatsiorsky trunk segmentation at vertebral levels:
  // thorax (upper trunk) down to the xiphisternal joint (T9 lower plate), abdomen (middle
  // trunk) down to the omphalion (L3 lower plate), pelvis (lower trunk) below (Gray's
  // Anatomy surface landmarks: xiphisternal joint T9, umbilicus L3-L4).
  std::string below = "S1";
  bool past_l3 = false, past_t9 = false;  // walking upwards
  for (int i = static_cast<int>(g_.spine.size()) - 2; i >= 0; --i) {
    const auto& v = g_.spine[static_cast<std::size_t>(i)];
    if (v.name[0] == 'C') break;
    bool lumbar = v.name[0] == 'L';
    double r = lumbar ? 20 : 15;
    std::string disc_region = !past_l3 ? "pelvis" : !past_t9 ? "abdomen" : "thorax";
    if (v.name == "L3") past_l3 = true;
    if (v.name == "T9") past_t9 = true;
    std::string region = !past_l3 ? "pelvis" : !past_t9 ? "abdomen" : "thorax";
    if (v.name == "L3") region = "abdomen";
    if (v.name == "T9") region = "thorax";
    add(v.name + "_lower", v.lower.x(), v.lower.y(), v.name, r);
    layers.push_back({LayerKind::Disc, v.name + below, disc_region});
    add(v.name + "_upper", v.upper.x(), v.upper.y(), v.name, r);
    layers.push_back({LayerKind::Body, v.name, region});
    below = v.name;
  }
  // Disc layers keep one spine x on both surfaces (the mean of the two endplate centres):
  // the source's endplate centres shift up to 7 mm across a 3 mm disc (T10-T11), which
  // would shear the thin layer; the vertebral body layers absorb the shift instead.
  for (std::size_t k = 0; k < layers.size(); ++k)
    if (layers[k].kind == LayerKind::Disc) {
      double xm = 0.5 * (lv[k].x_spine + lv[k + 1].x_spine);
      lv[k].x_spine = lv[k + 1].x_spine = xm;
    }
  GridParams gp;
  gp.n = o_.torso_around;
  torso_ = std::make_unique<TrunkGrid>(m_, g_.torso, lv, gp);
  torso_layers_ = layers;
  sternum_layers_ = {layer_of_body(kSternumLowestBody), layer_of_body(kSternumHighestBody)};

  const int N = torso_->n(), m = torso_->m();
  const int vert_mat = material("vertebra");
  std::map<std::string, int> flesh, skin, skin_tri;
  const auto& skin_sec = g_.shell_sections.at("skin");
  for (const char* region : {"thorax", "abdomen", "pelvis"}) {
    std::string r = region;
    // The trunk wall's flesh is mostly muscle; the seated pelvis's soft tissue, where the
    // pelvis bears load (over the trochanters, under the ischia), is subcutaneous fat
    // (materials.csv flesh, subcutaneous_fat; calibration.md).
    flesh[r] = part("flesh_" + r, ElementKind::Brick, material(r == "pelvis" ? "subcutaneous_fat" : "flesh"), r, "flesh");
    skin[r] = part("skin_" + r, ElementKind::Shell, material("skin"), r, "skin", skin_sec.total_thickness);
    skin_tri[r] = part("skin_" + r + "_tria", ElementKind::Tria, material("skin"), r, "skin", skin_sec.total_thickness);
  }
  // Over the sternum there is no muscle: skin on subcutaneous fat on the bone (the pectoralis
  // major arises beside the midline; CT: 11.3 mm of fat, 12.7 mm skin to cortex; calibration.md).
  const int presternal = part("flesh_presternal", ElementKind::Brick, material("subcutaneous_fat"), "thorax", "flesh");
  // Organ sets: thoracic inside the rib cage (T1-T12 layers), abdominal below; one part per
  // (set, mass region).
  auto organ_part = [&](const LayerInfo& L) {
    // The organ block under the diaphragm (T10-T12 layers, abdomen region: liver, stomach,
    // spleen inside the lower rib cage) takes the abdominal set, as the seed model's
    // thoracic/abdominal split follows the diaphragm, not the vertebral level.
    bool thoracic = L.vertebra.size() > 1 && L.vertebra[0] == 'T' && L.region == "thorax";
    std::string set = thoracic ? "thoracic_organs" : "abdominal_organs";
    std::string name = set + (L.region == (thoracic ? "thorax" : "abdomen") ? "" : "_" + L.region);
    // MesherOptions::lungs (the default): the thoracic part is the lungs alone (the
    // mediastinum is cut out of it in build_body_model); without it the seed's block.
    return part(name, ElementKind::Brick, material(thoracic && o_.lungs ? "lungs" : set), L.region, "organs");
  };
  for (int l = 0; l + 1 < torso_->levels(); ++l) {
    const LayerInfo& L = layers[static_cast<std::size_t>(l)];
    int column = -1;
    if (L.kind == LayerKind::Body)
      column = part(L.vertebra[0] == 'T' ? "thoracic_vertebrae" : "lumbar_vertebrae", ElementKind::Brick, vert_mat, L.region, "spine");
    else if (L.kind == LayerKind::Sacrum)
      column = part("sacrum", ElementKind::Brick, vert_mat, "pelvis", "pelvis");
    else if (L.kind == LayerKind::Disc) {
      // One material per disc: its modulus is calibrated below from the cell geometry.
      FeMaterial dm = convert(g_.material("disc_thoracolumbar"), "disc_" + L.vertebra);
      int mi = m_.add_material(dm);
      column = part("disc_" + L.vertebra, ElementKind::Brick, mi, L.region, "spine");
    } else
      column = flesh.at(L.region);
    const bool top = l + 2 == torso_->levels();
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b) {
        auto h = torso_->block_cell(l, a, b);
        brick(organ_part(L), h);
        torso_hexes_.push_back(h);
        if (top) torso_top_faces_.push_back({h[4], h[5], h[6], h[7]});
      }
    for (int r = 0; r < 3; ++r)
      for (int j = 0; j < N; ++j) {
        auto h = torso_->ring_cell(l, r, j);
        torso_hexes_.push_back(h);  // the fine grid's volume: inside tests of the contacts and limbs
        if (o_.flesh_tetra && is_tetra_flesh_cell(r, j)) continue;  // meshed over the layer pairs below
        int p = torso_->is_column_cell(r, j) ? column
                : r == 0                     ? organ_part(L)
                : is_presternal_cell(l, l, j) ? presternal
                                              : flesh.at(L.region);
        brick(p, h);
        if (top) torso_top_faces_.push_back({h[4], h[5], h[6], h[7]});
      }
    if (!o_.flesh_tetra)
      for (int j = 0; j < N; ++j) {
        auto q = torso_->ring_face(l, 3, j);
        skin_quad(skin.at(L.region), skin_tri.at(L.region), q);
        torso_skin_.push_back(q);
      }
    if (L.kind == LayerKind::Disc) calibrate_disc(l, column, g_.disc_stiffness.at(L.vertebra));
  }
  if (o_.flesh_tetra) build_tetra_flesh(flesh, presternal, skin, skin_tri);
  // Thoracic inlet: the suprapleural membrane (Sibson's fascia) over the top faces of the
  // organ block and organ ring at the top level, from the rib cage wall to the spinal
  // column (geometry/materials.csv). Without it the organ block extrudes upward through
  // the open inlet under a frontal chest impact.
  {
    const int l = torso_->levels() - 2;
    const auto& fs = g_.shell_sections.at("thoracic_inlet_fascia");
    const int mi = material("thoracic_inlet_fascia");
    const int inlet = part("thoracic_inlet_fascia", ElementKind::Shell, mi, "thorax", "organs", fs.total_thickness);
    const int inlet_tri = part("thoracic_inlet_fascia_tria", ElementKind::Tria, mi, "thorax", "organs", fs.total_thickness);
    for (int a = 0; a < m; ++a)
      for (int c = 0; c < m; ++c) {
        auto h = torso_->block_cell(l, a, c);
        skin_quad(inlet, inlet_tri, {h[4], h[5], h[6], h[7]});
      }
    // Ring cells two by two (a single cell's top face is a radial sliver, aspect 9-12),
    // from the first cell after the column round to the last one before it.
    int j0 = 0;  // first cell after the column (0 if the ring had no column cell)
    for (int k = 0; k < N; ++k)
      if (torso_->is_column_cell(0, k) && !torso_->is_column_cell(0, (k + 1) % N)) j0 = (k + 1) % N;
    std::vector<int> free_cells;
    for (int k = 0; k < N; ++k)
      if (!torso_->is_column_cell(0, (j0 + k) % N)) free_cells.push_back((j0 + k) % N);
    for (std::size_t k = 0; k + 1 < free_cells.size(); k += 2) {
      auto a = torso_->ring_cell(l, 0, free_cells[k]), c = torso_->ring_cell(l, 0, free_cells[k + 1]);
      skin_quad(inlet, inlet_tri, {a[4], a[5], c[6], c[7]});
    }
    if (free_cells.size() % 2 == 1) {
      auto h = torso_->ring_cell(l, 0, free_cells.back());
      skin_quad(inlet, inlet_tri, {h[4], h[5], h[6], h[7]});
    }
  }
  // Landmarks for the trunk CoG reference: centres of the skin curve at region boundaries.
  auto centre = [&](const std::string& level_name) {
    for (int l = 0; l < torso_->levels(); ++l)
      if (torso_->level(l).name == level_name) {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (int j = 0; j < N; ++j) c += m_.nodes[static_cast<std::size_t>(torso_->ring_node(l, 3, j))];
        return Eigen::Vector3d(c / N);
      }
    throw std::logic_error("no torso level " + level_name);
  };
  lm_.boundary_centres["T1_upper"] = centre("T1_upper");
  lm_.boundary_centres["T9_lower"] = centre("T9_lower");
  lm_.boundary_centres["L3_lower"] = centre("L3_lower");
  lm_.boundary_centres["seat"] = centre("seat");
  for (int l = 0; l < torso_->levels(); ++l) lm_.trunk_centreline.push_back(centre(torso_->level(l).name));
  for (int l = 0; l < torso_->levels(); ++l)
    if (torso_->level(l).name == "L3_lower") lm_.points["omphalion"] = m_.nodes[static_cast<std::size_t>(torso_->ring_node(l, 3, 0))];
}

// Flesh as average nodal pressure tetras (MesherOptions::flesh_tetra). The bricks' two
// flesh rings and their skin quads give way to one cell from the rib cage wall (ring 1) to
// the skin (ring 3) over two layers, cut into the six tetras around its diagonal: a tetra
// has no hourglass mode and the nodal pressure does not lock (docs/engine-design.md §12.9),
// and the coarser cell keeps the element count of the brick layout (4 bricks + 2 skin quads
// become 6 tetras + 1 quad). Layers are paired from the bottom of each region (pelvis,
// abdomen, thorax), so every pair is a vertebral body with the disc above it; a region with
// an odd count ends with a single layer. Behind the spinal column (cells j = N/2-1, N/2,
// whose ring layers 0-1 are bone) a cell starts at ring 2, and so do the column-side edges
// of the two cells beside it, which keeps the tetras conforming among themselves (a wedge
// beside the column's flesh-facing side is left empty). The cells' inner faces rest on
// every other ring-1 level: the wall nodes between (rib edges, organ ring corners) are not
// tetra nodes (the wall is the stiffer side, its own elements carry them).
bool Builder::is_tetra_flesh_cell(int r, int j) const {
  // Flesh bricks of ring layers 1 and 2; the column cells of ring layer 1 stay bricks (bone,
  // or in the buttock layers flesh under the coccyx that the tetra cells start above).
  return r == 2 || (r == 1 && !torso_->is_column_cell(1, j));
}

void Builder::build_tetra_flesh(const std::map<std::string, int>& flesh, int presternal, const std::map<std::string, int>& skin,
                                const std::map<std::string, int>& skin_tri) {
  const int N = torso_->n(), layers = torso_->levels() - 1;
  std::vector<std::pair<int, int>> pairs;  // first and last layer of each cell row
  for (int l = 0; l < layers;) {
    const auto& region = torso_layers_[static_cast<std::size_t>(l)].region;
    bool two = l + 1 < layers && torso_layers_[static_cast<std::size_t>(l + 1)].region == region;
    pairs.push_back({l, two ? l + 1 : l});
    l += two ? 2 : 1;
  }
  auto column_node = [&](int j) {
    j = ((j % N) + N) % N;
    return j >= N / 2 - 1 && j <= N / 2 + 1;
  };
  // The cells over the greater trochanters start at ring 2 where that ring's nodes are at the
  // bone (build_pelvis puts them in the femur rigid body, as in the brick layout), so that
  // the lateral hip's tissue lies between the skin and the trochanter, not the pelvic wall.
  std::set<int> at_trochanter;
  for (const char* side : {"greater_trochanter_r", "greater_trochanter_l"}) {
    const Eigen::Vector3d gt = g_.pelvis.at(side);
    for (const auto& [l0, l1] : pairs)
      for (int lv : {l0, l1 + 1})
        for (int j = 0; j < N; ++j) {
          int n = torso_->ring_node(lv, 2, j);
          if (at_trochanter_bone(m_.nodes[static_cast<std::size_t>(n)], gt)) at_trochanter.insert(n);
        }
  }
  // Kuhn's six tetras around the diagonal n1-n7: every face of the cell is cut along its
  // diagonal through n1 or n7, so cells ordered alike share their cuts.
  static constexpr int kKuhn[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  auto X = [&](int n) { return m_.nodes[static_cast<std::size_t>(n)]; };
  for (const auto& [l0, l1] : pairs) {
    const LayerInfo& L = torso_layers_[static_cast<std::size_t>(l0)];
    const int lb = l0, lt = l1 + 1;
    for (int j = 0; j < N; ++j) {
      auto inner = [&](int l, int k) {
        int r2 = torso_->ring_node(l, 2, k);
        return column_node(k) || at_trochanter.count(r2) ? r2 : torso_->ring_node(l, 1, k);
      };
      std::array<int, 8> c{inner(lb, j), torso_->ring_node(lb, 3, j), torso_->ring_node(lb, 3, j + 1), inner(lb, j + 1),
                           inner(lt, j), torso_->ring_node(lt, 3, j), torso_->ring_node(lt, 3, j + 1), inner(lt, j + 1)};
      // Cut around the diagonal from the skin at the lower level to the wall at the upper
      // one: the levels descend towards the front (rib inclination), and this diagonal
      // gives the sheared cells their least flat tetras (largest edge / altitude 24 against
      // 29 for the wall-to-skin diagonal).
      c = {c[1], c[0], c[3], c[2], c[5], c[4], c[7], c[6]};
      std::array<int, 8> h = torso_->oriented_cell(c);
      for (const auto& t : kKuhn) {
        std::array<int, 4> tn{h[static_cast<std::size_t>(t[0])], h[static_cast<std::size_t>(t[1])], h[static_cast<std::size_t>(t[2])],
                              h[static_cast<std::size_t>(t[3])]};
        auto vol = [&] { return (X(tn[1]) - X(tn[0])).dot((X(tn[2]) - X(tn[0])).cross(X(tn[3]) - X(tn[0]))); };
        if (vol() < 0) std::swap(tn[2], tn[3]);
        if (vol() <= 0)
          throw std::runtime_error("torso flesh: tetra of zero volume in the cell of layers " + torso_->level(lb).name + " - " +
                                   torso_->level(lt).name + ", angular cell " + std::to_string(j) + " (torso_sections.csv)");
        m_.tetras.push_back(tn);
        m_.tetra_part.push_back(is_presternal_cell(l0, l1, j) ? presternal : flesh.at(L.region));
      }
      if (lt + 1 == torso_->levels()) torso_top_faces_.push_back({h[4], h[5], h[6], h[7]});
      // The contacts on the skin take its shells as they are (a warped face's triangles):
      // the tetras' outer faces are triangles of their own cut, not these quads.
      for (const auto& f : skin_quad(skin.at(L.region), skin_tri.at(L.region), torso_->ring_face_span(lb, lt, 3, j))) torso_skin_.push_back(f);
    }
    tetra_flesh_rows_.push_back({lb, lt});
  }
}

// Young's modulus of a disc part from its axial stiffness: E = k h / A over the disc
// column cells (A: mean of the bottom and top face areas, h = V / A).
void Builder::calibrate_disc(int l, int part_index, double k) {
  double area = 0, volume = 0;
  for (int r = 0; r < 2; ++r)
    for (int j = torso_->back() - 1; j <= torso_->back(); ++j) {
      auto h = torso_->ring_cell(l, r, j);
      auto P = [&](int i) { return m_.nodes[static_cast<std::size_t>(h[static_cast<std::size_t>(i)])]; };
      double ab = 0.5 * (P(2) - P(0)).cross(P(3) - P(1)).norm(), at = 0.5 * (P(6) - P(4)).cross(P(7) - P(5)).norm();
      double a = 0.5 * (ab + at);
      // height: mean of the four vertical edges
      double hh = 0.25 * ((P(4) - P(0)).norm() + (P(5) - P(1)).norm() + (P(6) - P(2)).norm() + (P(7) - P(3)).norm());
      area += a;
      volume += a * hh;
    }
  double h = volume / area;
  FeMaterial& mat = m_.materials[static_cast<std::size_t>(m_.parts[static_cast<std::size_t>(part_index)].material)];
  mat.E = k * h / area * 1e-3;  // N/mm * mm / mm^2 = MPa -> GPa
  mat.source += "; E calibrated to k = " + std::to_string(static_cast<int>(k)) + " N/mm (disc_stiffness.csv)";
}

// --- rib cage -----------------------------------------------------------------------------

int Builder::layer_of_body(const std::string& vertebra) const {
  for (std::size_t l = 0; l < torso_layers_.size(); ++l)
    if (torso_layers_[l].kind == LayerKind::Body && torso_layers_[l].vertebra == vertebra) return static_cast<int>(l);
  throw std::logic_error("no body layer " + vertebra);
}

bool Builder::is_presternal_cell(int first_layer, int last_layer, int j) const {
  const int N = torso_->n();
  return (j == 0 || j == N - 1) && first_layer >= sternum_layers_.first && last_layer <= sternum_layers_.second;
}

void Builder::build_ribcage() {
  const int N = torso_->n(), half = N / 2;
  auto P = [&](int n) { return m_.nodes[static_cast<std::size_t>(n)]; };
  // Split a wall quad (left/right mirrored diagonals) into two triangles.
  auto split = [&](int l, int j, bool left) {
    int a = torso_->ring_node(l, 1, j), b = torso_->ring_node(l, 1, j + 1);
    int c = torso_->ring_node(l + 1, 1, j + 1), d = torso_->ring_node(l + 1, 1, j);
    std::array<std::array<int, 3>, 2> t;
    if (left) t = {{{a, b, c}, {a, c, d}}};
    else t = {{{a, b, d}, {b, c, d}}};
    return t;
  };
  auto band = [&](int l, int j) {
    int a = torso_->ring_node(l, 1, j), b = torso_->ring_node(l, 1, j + 1);
    int c = torso_->ring_node(l + 1, 1, j + 1), d = torso_->ring_node(l + 1, 1, j);
    double h = 0.5 * ((P(d) - P(a)).norm() + (P(c) - P(b)).norm());
    double len = 0.5 * ((P(b) - P(a)).norm() + (P(c) - P(d)).norm());
    return std::pair<double, double>(h, len);
  };
  const MaterialSpec& rib_spec = g_.material("rib_cortical");
  for (const RibSpec& rib : g_.ribs) {
    int l = layer_of_body(rib.vertebra);
    int j0 = static_cast<int>(std::lround(half * (1 - rib.end_fraction)));
    j0 = std::max(j0, 2);
    const int jh = half - 2;  // cell next to the vertebral column
    struct Elem { std::array<int, 3> t; double th; };
    std::vector<Elem> elems;
    double real_mass_area = 0, model_volume = 0;
    double fibre_ratio_sum = 0;  // t_eq / w over the strip's cells (rib fracture model)
    int cells = 0;
    for (int j = j0; j <= jh; ++j) {
      double s = (jh - j + 0.5) / (jh - j0 + 1);  // abscissa 0 at the head, 1 at the end
      auto interp = [&](const double v[3]) { return s < 0.5 ? v[0] + (v[1] - v[0]) * s / 0.5 : v[1] + (v[2] - v[1]) * (s - 0.5) / 0.5; };
      double h = interp(rib.height), w = interp(rib.width), t = interp(rib.cortical);
      for (int side = 0; side < 2; ++side) {
        bool left = side == 0;
        int jj = left ? j : N - 1 - j;
        auto [bh, len] = band(l, jj);
        double teq = equivalent_rib_thickness(h, w, t);
        fibre_ratio_sum += teq / w;
        ++cells;
        real_mass_area += hollow_ellipse_area(h, w, t) * len;
        model_volume += bh * len * teq;
        for (const auto& tri : split(l, jj, left)) elems.push_back({tri, teq});
      }
    }
    // Modulus and density scaled by real section area / strip section (h t): axial stiffness
    // E A, bending stiffness E I and mass of the real rib, unchanged wave speed.
    FeMaterial rm = convert(rib_spec, "rib_" + std::string(rib.index < 10 ? "0" : "") + std::to_string(rib.index));
    rm.rho *= real_mass_area / model_volume;
    rm.E *= real_mass_area / model_volume;
    rm.source += "; E and density scaled by real/strip section area (equivalent strip, calibration.md)";
    const bool fracture = o_.rib_fracture_age >= 0;
    if (fracture) {
      // Elastoplastic strip with deletion at the bone's failure strain (rib_fracture.hpp): yields
      // and breaks at the real section's curvatures through the model's 3-point shells.
      const StripPlasticity sp = strip_plasticity(g_.rib_bone, o_.rib_fracture_age, real_mass_area / model_volume,
                                                  fibre_ratio_sum / cells, three_point_outer_zeta());
      rm.law = "LAW2";
      rm.yield = sp.yield_stress * kModulus;
      rm.hardening = sp.plastic_modulus * kModulus;
      rm.eps_p_max = sp.eps_p_max;
      rm.source += "; elastoplastic with failure at the median ultimate strain of a " + std::to_string(std::lround(o_.rib_fracture_age)) +
                   "-year-old (rib_fracture.csv, rib_fracture.hpp)";
    }
    int mi = m_.add_material(rm);
    int p = part(rm.name, ElementKind::Tria, mi, "thorax", "ribs");
    // An element is deleted when two of its three through-thickness points have failed:
    // both outer fibres, i.e. a fracture through the section.
    if (fracture) m_.parts[static_cast<std::size_t>(p)].fail_fraction = 0.5;
    for (const auto& e : elems) {
      tria(p, e.t, e.th);
      cage_segments_.push_back({e.t[0], e.t[1], e.t[2], e.t[2]});
    }
    // Costal cartilage: cells between the sternum (cells 0 and N-1) and the rib end.
    if (rib.cartilage != CartilageKind::None) {
      const auto& cs = g_.shell_sections.at("costal_cartilage");
      double a = cs.width / 2, b = cs.height / 2, I = M_PI / 4 * b * a * a * a, A = M_PI * a * b;
      std::vector<Elem> ce;
      double ra = 0, mv = 0;
      for (int j = 1; j < j0; ++j)
        for (int side = 0; side < 2; ++side) {
          bool left = side == 0;
          int jj = left ? j : N - 1 - j;
          auto [bh, len] = band(l, jj);
          double teq = std::sqrt(12 * I / A);
          ra += A * len;
          mv += bh * len * teq;
          for (const auto& tri : split(l, jj, left)) ce.push_back({tri, teq});
        }
      if (cart_part < 0) {
        FeMaterial cm = convert(g_.material("costal_cartilage"), "costal_cartilage");
        cart_mat = m_.add_material(cm);
        cart_part = part("costal_cartilage", ElementKind::Tria, cart_mat, "thorax", "cartilage");
        cart_ratio = mv > 0 ? ra / mv : 1;
        m_.materials[static_cast<std::size_t>(cart_mat)].rho *= cart_ratio;
        m_.materials[static_cast<std::size_t>(cart_mat)].E *= cart_ratio;
        m_.materials[static_cast<std::size_t>(cart_mat)].source += "; E and density scaled by real/strip section area";
      }
      for (const auto& e : ce) {
        tria(cart_part, e.t, e.th);
        cage_segments_.push_back({e.t[0], e.t[1], e.t[2], e.t[2]});
      }
    }
  }
  // Sternum: front cells from the rib-1 band to the rib-7 band.
  const auto [smi, teq] = sandwich_material("sternum", "sternum_cortical", "sternum");
  int sp = part("sternum", ElementKind::Tria, smi, "thorax", "sternum", teq);
  const auto [l7, l1] = sternum_layers_;
  for (int l = l7; l <= l1; ++l)
    for (int side = 0; side < 2; ++side) {
      bool left = side == 0;
      int jj = left ? 0 : N - 1;
      for (const auto& tri : split(l, jj, left)) {
        tria(sp, tri, teq);
        cage_segments_.push_back({tri[0], tri[1], tri[2], tri[2]});
        for (int n : tri) sternum_nodes_.insert(n);
      }
    }
  lm_.points["suprasternale"] = P(torso_->ring_node(l1 + 1, 3, 0));
  lm_.points["xiphion"] = P(torso_->ring_node(l7, 3, 0));
}

// --- pelvis --------------------------------------------------------------------------------

void Builder::build_pelvis() {
  const int N = torso_->n(), half = N / 2;
  // Pelvic bone: a sandwich plate of two cortices over a trabecular core (shell_sections.csv).
  const auto [cortex_mat, cortex_t] = sandwich_material("pelvis_cortical", "pelvis_cortical", "pelvis_cortex");
  int cortex = part("pelvis_cortex", ElementKind::Shell, cortex_mat, "pelvis", "pelvis", cortex_t);
  // Sacroiliac joints and pubic symphysis: bands of shells one ring cell long across the
  // joint, as deep as the joint surfaces (shell_sections.csv pelvic_joints). A band of length
  // L stands for fibrocartilage of the joint space g: the same axial stiffness E A / g needs
  // the modulus E L / g (set below from the bands' mean length).
  const auto& js = g_.shell_sections.at("pelvic_joints");
  const int joint_mat = m_.add_material(convert(g_.material("pelvic_joint"), "pelvic_joint"));
  int joint_part = part("pelvic_joints", ElementKind::Shell, joint_mat, "pelvis", "pelvis", js.total_thickness);
  double band_length = 0;
  int bands = 0;
  auto joint_band = [&](const std::array<int, 4>& q) {
    shell(joint_part, q);
    auto P = [&](int i) { return m_.nodes[static_cast<std::size_t>(q[static_cast<std::size_t>(i)])]; };
    band_length += 0.5 * ((P(1) - P(0)).norm() + (P(2) - P(3)).norm());  // across the joint: the ring direction
    ++bands;
  };
  const double z_pubis = g_.pelvis.at("pubic_symphysis").z(), z_isch = g_.pelvis.at("ischial_tuberosity_r").z();
  const double z_crest = std::max(g_.pelvis.at("asis_r").z(), g_.pelvis.at("iliac_tubercle_r").z());
  for (int l = 0; l + 1 < torso_->levels(); ++l) {
    const LayerInfo& L = torso_layers_[static_cast<std::size_t>(l)];
    double zb = torso_->level(l).z_spine, zt = torso_->level(l + 1).z_spine, zm = 0.5 * (zb + zt);
    if (zt <= z_isch - 10 || zb >= z_crest) continue;
    // Angular extent: iliac wings above the pubis end at the ASIS (62 % of the half wall from
    // the back); the pubic level closes the ring to the symphysis; the ischium below ends at
    // 75 %. Estimates of the pelvic ring shape (pelvis_landmarks.csv gives the heights).
    int jf = 0;
    bool pubic = std::abs(zm - z_pubis) <= 25;
    if (pubic) jf = 1;
    else if (zm > z_pubis) jf = static_cast<int>(std::lround(half * (1 - 0.62)));
    else jf = static_cast<int>(std::lround(half * (1 - 0.75)));
    bool sacral = L.kind == LayerKind::Sacrum;
    int jb = half - 2;  // next to the column
    for (int j = jf; j <= jb; ++j)
      for (int side = 0; side < 2; ++side) {
        int jj = side == 0 ? j : N - 1 - j;
        bool si = j == jb;
        if (si && !sacral) continue;  // the posterior iliac edge is free above/below the sacrum
        auto q = torso_->ring_face(l, 1, jj);
        if (si) joint_band(q);
        else shell(cortex, q);
        for (int n : q) pelvis_shell_nodes_.insert(n);
      }
    if (pubic)
      for (int jj : {0, N - 1}) {
        auto q = torso_->ring_face(l, 1, jj);
        joint_band(q);
        for (int n : q) pelvis_shell_nodes_.insert(n);
      }
  }
  if (bands == 0) throw std::runtime_error("pelvis: no sacroiliac or pubic joint band (pelvis_landmarks.csv heights)");
  {
    FeMaterial& jm = m_.materials[static_cast<std::size_t>(joint_mat)];
    const double L = band_length / bands;
    jm.E *= L / js.joint_gap;
    std::ostringstream src;
    src << "; E x band length " << std::fixed << std::setprecision(1) << L << " mm / joint space " << js.joint_gap
        << " mm (shell_sections.csv pelvic_joints)";
    jm.source += src.str();
  }
  // Rigid acetabula (pelvis shell nodes within 40 mm of the acetabular centre) with the hip
  // joint centre as main node; rigid greater trochanter nodes join the femur rigid body
  // (nodes of elements only: not the fine grid's nodes the tetra flesh leaves out).
  const std::vector<char> in_element = m_.nodes_in_elements();
  for (const char* s : {"r", "l"}) {
    std::string side = s;
    Eigen::Vector3d ac = g_.pelvis.at("acetabulum_" + side);
    std::vector<int> nodes;
    for (int n : pelvis_shell_nodes_)
      if ((m_.nodes[static_cast<std::size_t>(n)] - ac).norm() <= 40) nodes.push_back(n);
    if (nodes.size() < 3) throw std::runtime_error("pelvis: fewer than 3 cortex nodes within 40 mm of acetabulum_" + side +
                                                   " (check pelvis_landmarks.csv and torso_sections.csv wall)");
    // Joint node at the hip centre (secondary); main node at the centroid.
    Eigen::Vector3d hip = g_.skeleton.link("femur_" + side).joint_origin;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int n : nodes) c += m_.nodes[static_cast<std::size_t>(n)];
    int joint = m_.add_node(hip);
    nodes.push_back(joint);
    int main = m_.add_node(c / static_cast<double>(nodes.size() - 1));
    rigid("acetabulum_" + side, "pelvis", main, nodes);
    joint_node_["hip_pelvis_" + side] = joint;
    // Greater trochanter: the torso nodes at the bone (within kTrochanterBone of the
    // landmark, the lateral bony surface, and medial of it) join the femur rigid body; the
    // flesh and skin lateral of it stay deformable: 31 +- 11.5 mm of trochanteric soft tissue in men
    // (Nielson et al. 2009, J Clin Endocrinol Metab 94:491, DXA, MrOS), the skin at the
    // seated hip half-breadth over it (torso_sections.csv widest_forward_mm at z = 0).
    std::set<int> skin_nodes;
    for (const auto& q : torso_skin_) skin_nodes.insert(q.begin(), q.end());
    std::vector<int> troch;
    Eigen::Vector3d gt = g_.pelvis.at("greater_trochanter_" + side);
    for (int n = 0; n < static_cast<int>(m_.nodes.size()); ++n)
      if (at_trochanter_bone(m_.nodes[static_cast<std::size_t>(n)], gt) && !rigid_of_.count(n) && in_element[static_cast<std::size_t>(n)])
        troch.push_back(n);
    if (troch.empty())
      throw std::runtime_error("pelvis: no torso node within " + std::to_string(kTrochanterBone) + " mm of greater_trochanter_" + side +
                               " (pelvis_landmarks.csv)");
    for (int n : troch)
      if (skin_nodes.count(n))
        throw std::runtime_error("pelvis: skin node " + std::to_string(n + 1) + " within " + std::to_string(kTrochanterBone) +
                                 " mm of greater_trochanter_" + side + ": no deformable tissue over the trochanter (torso_sections.csv)");
    rb_nodes_["femur_" + side] = troch;
  }
}

// --- neck ----------------------------------------------------------------------------------

void Builder::build_neck() {
  const GridLevel base = torso_->level(torso_->levels() - 1);
  std::vector<GridLevel> lv;
  std::vector<LayerInfo> layers;
  GridLevel b0 = base;
  b0.name = "neck_base";
  b0.body_radius = 8;
  lv.push_back(b0);
  std::string below = "T1";
  for (int i = 6; i >= 0; --i) {
    const auto& v = g_.spine[static_cast<std::size_t>(i)];
    GridLevel lo{v.name + "_lower", v.lower.x(), v.lower.y(), 0, 8}, up{v.name + "_upper", v.upper.x(), v.upper.y(), 0, 8};
    lv.push_back(lo);
    layers.push_back({LayerKind::Disc, v.name + below, "neck"});
    lv.push_back(up);
    layers.push_back({LayerKind::Body, v.name, "neck"});
    below = v.name;
  }
  // Atlanto-occipital layer: 6 mm capsule between the C1 upper facet and the skull base.
  const auto& c1 = g_.vertebra("C1");
  lv.push_back({"C0", c1.upper.x(), c1.upper.y() + 6.0, 0, 8});
  layers.push_back({LayerKind::Disc, "C0C1", "neck"});
  for (std::size_t k = 1; k < layers.size(); ++k)  // same disc treatment as the torso (base excluded: tied)
    if (layers[k].kind == LayerKind::Disc) {
      double xm = 0.5 * (lv[k].x_spine + lv[k + 1].x_spine);
      lv[k].x_spine = lv[k + 1].x_spine = xm;
    }
  // Tilt: from the torso top value at the base to 0 at the skull base, linear in level index.
  const int L = static_cast<int>(lv.size());
  for (int l = 0; l < L; ++l) lv[static_cast<std::size_t>(l)].tilt = base.tilt * (1.0 - static_cast<double>(l) / (L - 1));
  GridParams gp;
  gp.n = o_.neck_around;
  gp.relax_length = 30;
  neck_ = std::make_unique<TrunkGrid>(m_, g_.neck, lv, gp);
  neck_layers_ = layers;
  neck_top_level_ = L - 1;
  lm_.boundary_centres["C0"] = Eigen::Vector3d(c1.upper.x(), 0, c1.upper.y() + 6.0);

  const int N = neck_->n(), m = neck_->m();
  int visceral = part("neck_visceral", ElementKind::Brick, material("flesh"), "neck", "neck");
  int muscles = part("neck_muscles", ElementKind::Brick, material("muscle"), "neck", "neck");
  int skin = part("skin_neck", ElementKind::Shell, material("skin"), "neck", "skin", g_.shell_sections.at("skin").total_thickness);
  int skin_tri = part("skin_neck_tria", ElementKind::Tria, material("skin"), "neck", "skin", g_.shell_sections.at("skin").total_thickness);
  int vmat = material("vertebra"), dmat = material("disc_cervical");
  for (int l = 0; l + 1 < L; ++l) {
    const LayerInfo& Ly = layers[static_cast<std::size_t>(l)];
    int column = Ly.kind == LayerKind::Body
                     ? part("vertebra_" + Ly.vertebra, ElementKind::Brick, vmat, "neck", "neck")
                     : part((Ly.vertebra == "C0C1" || Ly.vertebra == "C1C2" ? "joint_capsule_" : "disc_") + Ly.vertebra,
                            ElementKind::Brick, dmat, "neck", "neck");
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b) brick(visceral, neck_->block_cell(l, a, b));
    std::vector<int> col_nodes;
    for (int r = 0; r < 3; ++r)
      for (int j = 0; j < N; ++j) {
        auto h = neck_->ring_cell(l, r, j);
        bool col = neck_->is_column_cell(r, j);
        brick(col ? column : r == 0 ? visceral : muscles, h);
        if (col) col_nodes.insert(col_nodes.end(), h.begin(), h.end());
      }
    for (int j = 0; j < N; ++j) {
      auto q = neck_->ring_face(l, 3, j);
      skin_quad(skin, skin_tri, q);
      neck_skin_.push_back(q);
    }
    if (Ly.kind == LayerKind::Body) rb_nodes_["vertebra_" + Ly.vertebra] = col_nodes;
  }
  // Rigid cervical vertebrae C1..C7: main node at the centroid of the column nodes.
  for (int i = 0; i < 7; ++i) {
    std::string name = "vertebra_C" + std::to_string(i + 1);
    auto& nodes = rb_nodes_[name];
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int n : nodes) c += m_.nodes[static_cast<std::size_t>(n)];
    c /= static_cast<double>(nodes.size());
    rb_main_at_[name] = c;
  }
  // Ligament springs across each disc C2-C3 ... C7-T1: anterior longitudinal (ring 0 midline),
  // posterior longitudinal (ring 1 midline), ligamentum flavum / interspinous (ring 2 midline),
  // capsular (ring 2 either side).
  int lig = spring_part("cervical_ligament");
  for (int l = 0; l + 1 < L; ++l) {
    const LayerInfo& Ly = layers[static_cast<std::size_t>(l)];
    if (Ly.kind != LayerKind::Disc || Ly.vertebra == "C0C1" || Ly.vertebra == "C1C2") continue;
    const int bk = neck_->back();
    for (auto [r, j] : std::vector<std::pair<int, int>>{{0, bk}, {1, bk}, {2, bk}, {2, bk - 1}, {2, bk + 1}})
      spring(lig, neck_->ring_node(l, r, j), neck_->ring_node(l + 1, r, j));
  }
  // Occiput-C1 and C1-odontoid generalized springs (nodes at the joint centres, one on each
  // rigid body).
  Eigen::Vector3d oc(c1.upper.x(), 0, c1.upper.y());
  Eigen::Vector3d c12(0.5 * (c1.lower.x() + g_.vertebra("C2").upper.x()), 0, 0.5 * (c1.lower.y() + g_.vertebra("C2").upper.y()));
  int oc_head = m_.add_node(oc), oc_c1 = m_.add_node(oc), c12_c1 = m_.add_node(c12), c12_c2 = m_.add_node(c12);
  spring(spring_part("occiput_c1"), oc_c1, oc_head);
  spring(spring_part("odontoid_c1"), c12_c2, c12_c1);
  rb_nodes_["vertebra_C1"].push_back(oc_c1);
  rb_nodes_["vertebra_C1"].push_back(c12_c1);
  rb_nodes_["vertebra_C2"].push_back(c12_c2);
  rb_nodes_["head"].push_back(oc_head);
  for (int n : neck_->level_nodes(neck_top_level_)) rb_nodes_["head"].push_back(n);
}

// --- head ----------------------------------------------------------------------------------

void Builder::build_head() {
  const SkeletonLink& hl = g_.skeleton.link("head");
  const HeadEnvelope& he = g_.head;
  Eigen::Vector3d c = hl.cog + Eigen::Vector3d(0, 0, he.centre_above_cog);
  int env = part("head_envelope", ElementKind::Shell, material("envelope"), "head", "head", g_.shell_sections.at("envelope").total_thickness);
  // Cube-sphere: each cube face gridded k x k, projected to the unit sphere, scaled to the
  // ellipsoid semi-axes.
  const int k = o_.head_cells;
  std::map<std::array<long, 3>, int> ids;
  auto node_at = [&](const Eigen::Vector3d& cube) {
    std::array<long, 3> key{std::lround(cube.x() * 1000), std::lround(cube.y() * 1000), std::lround(cube.z() * 1000)};
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    Eigen::Vector3d u = cube.normalized();
    Eigen::Vector3d p = c + Eigen::Vector3d(u.x() * he.ax, u.y() * he.ay, u.z() * he.az);
    int n = m_.add_node(moved("head", p));
    ids[key] = n;
    head_env_nodes_.push_back(n);
    return n;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int sgn : {1, -1}) {
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          auto corner = [&](int a, int b) {
            Eigen::Vector3d q;
            double u = -1 + 2.0 * a / k, v = -1 + 2.0 * b / k;
            q[axis] = sgn;
            q[(axis + 1) % 3] = u;
            q[(axis + 2) % 3] = v;
            return q;
          };
          std::array<int, 4> quad{node_at(corner(i, j)), node_at(corner(i + 1, j)), node_at(corner(i + 1, j + 1)), node_at(corner(i, j + 1))};
          if (sgn < 0) std::swap(quad[1], quad[3]);
          shell(env, quad);
        }
    }
  for (int n : head_env_nodes_) rb_nodes_["head"].push_back(n);
  rb_main_at_["head"] = moved("head", hl.cog);
}

// --- limbs ---------------------------------------------------------------------------------

std::vector<int> Builder::limb_envelope(const std::string& link, const std::string& table, const Eigen::Vector3d& p0,
                                        const Eigen::Vector3d& p1, int part_index, const TriSurface* clear_of, double f_min) {
  const auto& secs = g_.limbs.at(table);
  const double Lseg = (p1 - p0).norm();
  Eigen::Vector3d a = (p1 - p0) / Lseg;
  Eigen::Vector3d ew = Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitY().dot(a) * a;
  if (ew.norm() < 0.2) ew = Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ().dot(a) * a;
  ew.normalize();
  Eigen::Vector3d ed = a.cross(ew);
  const int na = o_.limb_around;
  // Ring of the section at fraction f along the axis, in the posture.
  auto ring_at = [&](double f) {
    std::size_t i = 1;
    while (i + 1 < secs.size() && secs[i].fraction < f) ++i;
    const LimbSection &s0 = secs[i - 1], &s1 = secs[i];
    double t = std::clamp((f - s0.fraction) / (s1.fraction - s0.fraction), 0.0, 1.0);
    double hw = s0.half_width + t * (s1.half_width - s0.half_width);
    double hd = s0.half_depth + t * (s1.half_depth - s0.half_depth);
    double ex = s0.exponent + t * (s1.exponent - s0.exponent);
    Eigen::Vector3d c = p0 + f * Lseg * a;
    std::vector<Eigen::Vector3d> pts;
    for (int k = 0; k < na; ++k) {
      double th = 2 * M_PI * k / na;
      pts.push_back(moved(link, c + ed * hd * sgnpow(std::cos(th), 2.0 / ex) + ew * hw * sgnpow(std::sin(th), 2.0 / ex)));
    }
    return pts;
  };
  double f0 = secs.front().fraction, f1 = secs.back().fraction;
  if (clear_of) {
    // The envelope begins where its section has left the torso: proximal of it the limb's
    // tissue is torso flesh (deformable), and a rigid envelope inside that flesh would be
    // met through it (the lateral hip over the greater trochanter, issue #8). First
    // fraction, in 1 mm steps, whose ring lies outside the torso surface by at least
    // kEnvelopeClearance (twice the 1-2 mm contact gaps used on the skin).
    constexpr double kEnvelopeClearance = 4.0;
    const double step = 1.0 / Lseg;
    double f = std::max(f0, f_min);
    for (; f < f1; f += step) {
      auto pts = ring_at(f);
      auto in = inside_surface(*clear_of, pts);
      auto dist = distance_to_surface(*clear_of, pts);
      bool clear = true;
      for (std::size_t k = 0; k < pts.size(); ++k) clear = clear && !in[k] && dist[k] >= kEnvelopeClearance;
      if (clear) break;
    }
    if (f >= 0.5 * (f0 + f1))
      throw std::runtime_error("limb envelope " + link + ": its section stays inside the torso up to fraction " + std::to_string(f) +
                               " (check limb_sections.csv " + table + " rows and torso_sections.csv)");
    f0 = f;
  }
  int rings = std::max(2, static_cast<int>(std::ceil((f1 - f0) * Lseg / o_.limb_ring_spacing)) + 1);
  std::vector<int> nodes;
  std::vector<std::vector<int>> ring_ids;
  for (int r = 0; r < rings; ++r) {
    double f = f0 + (f1 - f0) * r / (rings - 1);
    std::vector<int> ids;
    for (const auto& p : ring_at(f)) {
      int n = m_.add_node(p);
      ids.push_back(n);
      nodes.push_back(n);
    }
    ring_ids.push_back(ids);
  }
  for (int r = 0; r + 1 < rings; ++r)
    for (int k = 0; k < na; ++k) {
      auto ru = static_cast<std::size_t>(r), kk = static_cast<std::size_t>(k), k1 = static_cast<std::size_t>((k + 1) % na);
      // Outward normal: ring direction ed -> ew is counter-clockwise about a.
      shell(part_index, {ring_ids[ru][kk], ring_ids[ru][k1], ring_ids[ru + 1][k1], ring_ids[ru + 1][kk]});
    }
  return nodes;
}

void Builder::build_limbs() {
  // The thigh envelope starts clear of the torso (buttock and lateral hip are torso flesh).
  const TriSurface torso_surface = triangulate(m_.nodes, hex_boundary_faces(torso_hexes_));
  const double env_t = g_.shell_sections.at("envelope").total_thickness;
  int env_mat = material("envelope");
  for (const char* s : {"r", "l"}) {
    std::string side = s;
    int si = side == "r" ? 0 : 1;
    const SkeletonLink& hum = g_.skeleton.link("humerus_" + side);
    const SkeletonLink& fa = g_.skeleton.link("forearm_" + side);
    const SkeletonLink& fem = g_.skeleton.link("femur_" + side);
    const SkeletonLink& tib = g_.skeleton.link("tibia_" + side);
    Eigen::Vector3d elbow = fa.joint_origin, shoulder = hum.joint_origin;
    Eigen::Vector3d wrist = g_.limb_points.at("wrist_" + side);
    int hp = part("upper_arm_" + side, ElementKind::Shell, env_mat, "humerus_" + side, "limbs", env_t);
    int fp = part("forearm_hand_" + side, ElementKind::Shell, env_mat, "forearm_" + side, "limbs", env_t);
    int tp = part("thigh_" + side, ElementKind::Shell, env_mat, "femur_" + side, "limbs", env_t);
    int lp = part("leg_foot_" + side, ElementKind::Shell, env_mat, "tibia_" + side, "limbs", env_t);
    auto hn = limb_envelope("humerus_" + side, "humerus", shoulder, elbow, hp);
    auto fn = limb_envelope("forearm_" + side, "forearm", elbow, wrist, fp);
    Eigen::Vector3d hip = fem.joint_origin, knee = tib.joint_origin;
    // The rigid thigh envelope begins distal of the trochanteric region (the lateral hip:
    // greater trochanter to below the lesser trochanter, kTrochantericRegion along the
    // femur, est), which is deformable torso flesh over the trochanter (issue #8: a lateral
    // impact on the trochanter must meet soft tissue, not the rigid thigh).
    constexpr double kTrochantericRegion = 80.0;  // mm
    const Eigen::Vector3d gt = g_.pelvis.at("greater_trochanter_" + side);
    const double f_troch = ((gt - hip).dot((knee - hip).normalized()) + kTrochantericRegion) / (knee - hip).norm();
    auto tn = limb_envelope("femur_" + side, "femur", hip, knee, tp, &torso_surface, f_troch);
    Eigen::Vector3d ankle = g_.limb_points.at("ankle_" + side);
    auto ln = limb_envelope("tibia_" + side, "tibia", knee, ankle, lp);
    Eigen::Vector3d heel = g_.limb_points.at("heel_" + side), toe = g_.limb_points.at("toe_" + side);
    auto ft = limb_envelope("tibia_" + side, "foot", heel, toe, lp);
    ln.insert(ln.end(), ft.begin(), ft.end());
    arm_env_nodes_[si] = hn;
    arm_env_nodes_[si].insert(arm_env_nodes_[si].end(), fn.begin(), fn.end());
    // Joint nodes (one per rigid body at each joint centre) and the spring joints.
    int gh_h = m_.add_node(moved("humerus_" + side, shoulder));
    int el_h = m_.add_node(moved("humerus_" + side, elbow)), el_f = m_.add_node(moved("forearm_" + side, elbow));
    int hip_f = m_.add_node(moved("femur_" + side, hip));
    int kn_f = m_.add_node(moved("femur_" + side, knee)), kn_t = m_.add_node(moved("tibia_" + side, knee));
    spring(spring_part("shoulder"), joint_node_.at("gh_scapula_" + side), gh_h);
    spring(spring_part("elbow"), el_h, el_f);
    spring(spring_part("hip"), joint_node_.at("hip_pelvis_" + side), hip_f);
    spring(spring_part("knee"), kn_f, kn_t);
    auto push = [&](const std::string& rb, const std::vector<int>& v) {
      auto& d = rb_nodes_[rb];
      d.insert(d.end(), v.begin(), v.end());
    };
    push("humerus_" + side, hn);
    push("humerus_" + side, {gh_h, el_h});
    push("forearm_" + side, fn);
    push("forearm_" + side, {el_f});
    push("femur_" + side, tn);
    push("femur_" + side, {hip_f, kn_f});
    push("tibia_" + side, ln);
    push("tibia_" + side, {kn_t});
    for (const char* l : {"humerus_", "forearm_", "femur_", "tibia_"}) {
      std::string ln2 = l + side;
      rb_main_at_[ln2] = moved(ln2, g_.skeleton.link(ln2).cog);
    }
  }
}

// --- shoulders -----------------------------------------------------------------------------

void Builder::build_shoulders() {
  const int N = torso_->n();
  const auto& cs = g_.shell_sections.at("clavicle");
  double R = cs.total_thickness / 2 - cs.cortical / 2;  // mid-surface radius
  FeMaterial cm = convert(g_.material("clavicle_cortical"), "clavicle");
  {
    double ro = cs.total_thickness / 2, ri = ro - cs.cortical;
    double a_cort = M_PI * (ro * ro - ri * ri), a_core = M_PI * ri * ri;
    cm.rho = (a_cort * cm.rho + a_core * cs.core_density * kDensity) / (2 * M_PI * R * cs.cortical);
    cm.source += "; density includes the core (shell_sections.csv)";
  }
  int cmi = m_.add_material(cm);
  int env_mat = material("envelope");
  double env_t = g_.shell_sections.at("envelope").total_thickness;
  for (const char* s : {"r", "l"}) {
    std::string side = s;
    int si = side == "r" ? 0 : 1;
    // Scapula: the faces over the posterior upper thorax's posterolateral cells (levels
    // T2-T6): ring 2 in the brick flesh; the skin with the tetra flesh, whose cells have no
    // ring 2 (the rigid patch then lies at the skin, further out than the bone).
    int sp = part("scapula_" + side, ElementKind::Shell, env_mat, "thorax", "shoulder", env_t);
    int sp_tri = o_.flesh_tetra ? part("scapula_" + side + "_tria", ElementKind::Tria, env_mat, "thorax", "shoulder", env_t) : -1;
    std::vector<int> scap;
    std::vector<std::pair<int, int>> rows = tetra_flesh_rows_;
    if (!o_.flesh_tetra)
      for (int l = 0; l + 1 < torso_->levels(); ++l) rows.push_back({l, l + 1});
    for (const auto& [lb, lt] : rows) {
      const LayerInfo& L = torso_layers_[static_cast<std::size_t>(lb)];
      double zb = torso_->level(lb).z_spine;
      if (zb < 360 || torso_->level(lt).z_spine > 475 || L.region != "thorax") continue;
      for (int j = N / 2 - 6; j <= N / 2 - 3; ++j) {
        int jj = side == "l" ? j : N - 1 - j;
        auto q = torso_->ring_face_span(lb, lt, o_.flesh_tetra ? 3 : 2, jj);
        if (o_.flesh_tetra) skin_quad(sp, sp_tri, q);  // faces over two layers warp more
        else shell(sp, q);
        scap.insert(scap.end(), q.begin(), q.end());
      }
    }
    // Clavicle tube from the sternoclavicular to the acromioclavicular joint.
    Eigen::Vector3d sc = g_.skeleton.link("clavicle_" + side).joint_origin;
    Eigen::Vector3d ac = g_.skeleton.link("scapula_" + side).joint_origin;
    Eigen::Vector3d a = (ac - sc).normalized();
    Eigen::Vector3d e1 = (Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ().dot(a) * a).normalized(), e2 = a.cross(e1);
    int cp = part("clavicle_" + side, ElementKind::Shell, cmi, "thorax", "shoulder", cs.cortical);
    const int na = o_.clavicle_around, nl = o_.clavicle_along;
    std::vector<std::vector<int>> rings;
    for (int r = 0; r <= nl; ++r) {
      Eigen::Vector3d c = sc + (ac - sc) * (static_cast<double>(r) / nl);
      std::vector<int> ids;
      for (int k = 0; k < na; ++k) {
        double th = 2 * M_PI * k / na;
        int n = m_.add_node(c + R * (std::cos(th) * e1 + std::sin(th) * e2));
        ids.push_back(n);
        clavicle_nodes_[si].push_back(n);
      }
      rings.push_back(ids);
    }
    for (int r = 0; r < nl; ++r)
      for (int k = 0; k < na; ++k) {
        auto ru = static_cast<std::size_t>(r), kk = static_cast<std::size_t>(k), k1 = static_cast<std::size_t>((k + 1) % na);
        shell(cp, {rings[ru][kk], rings[ru][k1], rings[ru + 1][k1], rings[ru + 1][kk]});
      }
    // Medial end: small rigid body at the SC joint, spring to the nearest sternum node.
    int sc_main = m_.add_node(sc);  // joint node (secondary) at the SC joint centre
    std::vector<int> medial = rings.front();
    medial.push_back(sc_main);
    Eigen::Vector3d mc = Eigen::Vector3d::Zero();
    for (int n : rings.front()) mc += m_.nodes[static_cast<std::size_t>(n)];
    rigid("clavicle_medial_" + side, "thorax", m_.add_node(mc / static_cast<double>(rings.front().size())), medial);
    int nearest = -1;
    double best = 1e30;
    for (int n : sternum_nodes_) {
      double d = (m_.nodes[static_cast<std::size_t>(n)] - sc).norm();
      if (d < best) { best = d; nearest = n; }
    }
    spring(spring_part("sternoclavicular"), nearest, sc_main);
    // Lateral end and the glenohumeral node join the scapula rigid body (AC joint rigid).
    scap.insert(scap.end(), rings.back().begin(), rings.back().end());
    int gh = m_.add_node(g_.skeleton.link("humerus_" + side).joint_origin);
    joint_node_["gh_scapula_" + side] = gh;
    scap.push_back(gh);
    rb_nodes_["scapula_" + side] = scap;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int n : scap) c += m_.nodes[static_cast<std::size_t>(n)];
    rb_main_at_["scapula_" + side] = c / static_cast<double>(scap.size());
  }
}

// --- contacts ------------------------------------------------------------------------------

void Builder::build_contacts() {
  // Closed torso surface (boundary of the torso hexahedra) for inside/outside tests.
  auto boundary = hex_boundary_faces(torso_hexes_);
  TriSurface torso_surface = triangulate(m_.nodes, boundary);
  // Secondary nodes on one side of the torso surface (outside, or inside for the clavicle)
  // and at least twice the contact gap from it, so that no contact starts penetrated.
  auto clear_of_torso = [&](const std::vector<int>& nodes, double gap, bool want_inside) {
    std::vector<Eigen::Vector3d> q;
    for (int n : nodes) q.push_back(m_.nodes[static_cast<std::size_t>(n)]);
    auto in = inside_surface(torso_surface, q);
    auto dist = distance_to_surface(torso_surface, q);
    std::vector<int> out;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (in[i] == want_inside && dist[i] >= 2 * gap) out.push_back(nodes[i]);
    return out;
  };
  auto outside = [&](const std::vector<int>& nodes, double gap) { return clear_of_torso(nodes, gap, false); };
  std::vector<std::array<int, 4>> skin = torso_skin_;
  skin.insert(skin.end(), neck_skin_.begin(), neck_skin_.end());
  auto add = [&](const std::string& name, int type, std::vector<int> sec, std::vector<std::array<int, 4>> main, double gap) {
    FeInterface f;
    f.id = static_cast<int>(m_.interfaces.size()) + 1;
    f.type = type;
    f.name = name;
    std::sort(sec.begin(), sec.end());
    sec.erase(std::unique(sec.begin(), sec.end()), sec.end());
    f.secondary = std::move(sec);
    f.main_segments = std::move(main);
    f.gap = gap;
    f.stiffness_factor = 1.0;
    f.friction = type == 7 ? 0.2 : 0;
    f.search = type == 2 ? 5.0 : 0;
    m_.interfaces.push_back(std::move(f));
  };
  // Neck base tied to the torso top (non-matching grids).
  {
    add("neck_base_tied_to_torso", 2, neck_->level_nodes(0), torso_top_faces_, 0);
  }
  std::vector<int> arms = arm_env_nodes_[0];
  arms.insert(arms.end(), arm_env_nodes_[1].begin(), arm_env_nodes_[1].end());
  add("arm_thorax", 7, outside(arms, 2.0), skin, 2.0);
  std::vector<int> clav = clavicle_nodes_[0];
  clav.insert(clav.end(), clavicle_nodes_[1].begin(), clavicle_nodes_[1].end());
  add("clavicle_ribcage", 7, clav, cage_segments_, 1.0);
  add("head_thorax", 7, outside(head_env_nodes_, 2.0), torso_skin_, 2.0);
  // Clavicle-skin: the clavicle runs under the skin through the flesh (its nodes do not
  // belong to the flesh bricks). The main surface is the skin PARTS (/SURF/PART): shell
  // segments, two-sided, so a clavicle node is repelled only when it comes within the gap of
  // the skin membrane. As /SURF/SEG the same quads would coincide with the flesh bricks' outer
  // faces and be taken as one-sided solid faces, which count every node up to half an element
  // deep under the skin as penetrating (33.9 % energy error at cycle 0 in the drop deck).
  // Secondaries: the clavicle nodes inside the torso at least two gaps from the skin.
  {
    add("clavicle_skin", 7, clear_of_torso(clav, 1.0, true), {}, 1.0);
    auto& f = m_.interfaces.back();
    for (std::size_t p = 0; p < m_.parts.size(); ++p)
      if (m_.parts[p].name.rfind("skin_", 0) == 0) f.main_parts.push_back(static_cast<int>(p));
  }
}

// --- rigid bodies ----------------------------------------------------------------------------

void Builder::finalize_rigid_bodies() {
  for (auto& [name, nodes] : rb_nodes_) {
    int main = m_.add_node(rb_main_at_.at(name));
    std::string seg = name.rfind("vertebra_", 0) == 0 ? "neck" : name.rfind("scapula_", 0) == 0 ? "thorax" : name;
    rigid(name, seg, main, nodes);
  }
}

FeModel Builder::run(ModelLandmarks* lm) {
  build_torso();
  build_ribcage();
  build_pelvis();
  build_neck();
  build_shoulders();
  build_head();
  build_limbs();
  build_contacts();
  finalize_rigid_bodies();
  // The fine grid's ring-2 nodes and the skin and wall nodes between the tetra flesh's cell
  // rows belong to no element when the flesh is tetras.
  m_.remove_unreferenced_nodes();
  // Parts whose every node is in a rigid body are flagged rigid (their elements do not
  // limit the time step: the solver treats them as rigid).
  std::vector<bool> in_rb(m_.nodes.size(), false);
  for (const auto& r : m_.rigid_bodies)
    for (int n : r.nodes) in_rb[static_cast<std::size_t>(n)] = true;
  std::vector<int> free_count(m_.parts.size(), 0), total(m_.parts.size(), 0);
  auto visit = [&](int p, const int* nodes, int k) {
    for (int i = 0; i < k; ++i) {
      total[static_cast<std::size_t>(p)]++;
      if (!in_rb[static_cast<std::size_t>(nodes[i])]) free_count[static_cast<std::size_t>(p)]++;
    }
  };
  for (std::size_t e = 0; e < m_.bricks.size(); ++e) visit(m_.brick_part[e], m_.bricks[e].data(), 8);
  for (std::size_t e = 0; e < m_.tetras.size(); ++e) visit(m_.tetra_part[e], m_.tetras[e].data(), 4);
  for (std::size_t e = 0; e < m_.shells.size(); ++e) visit(m_.shell_part[e], m_.shells[e].data(), 4);
  for (std::size_t e = 0; e < m_.trias.size(); ++e) visit(m_.tria_part[e], m_.trias[e].data(), 3);
  for (std::size_t p = 0; p < m_.parts.size(); ++p)
    m_.parts[p].rigid = m_.parts[p].kind != ElementKind::Spring && total[p] > 0 && free_count[p] == 0;
  if (lm) *lm = lm_;
  return std::move(m_);
}

}  // namespace

FeModel build_body_model(const GeometrySources& g, const MesherOptions& opt, ModelLandmarks* landmarks) {
  Builder b(g, opt);
  FeModel m = b.run(landmarks);
  // The organ block's water-like mediastinum (thoracic_organs.csv), from the diaphragm up to
  // the top vertebra's upper endplate; the rest is the lungs.
  if (opt.lungs) {
    const double half_width = opt.mediastinum_half_width > 0 ? opt.mediastinum_half_width : g.mediastinum.half_width;
    const double top_z = g.vertebra(g.mediastinum.top_vertebra).upper.y();  // upper endplate (x, z): its height
    add_mediastinum(m, half_width, top_z);
  }
  if (opt.abdominal_wall)
    add_abdominal_wall(m, convert(g.material("abdominal_wall"), "abdominal_wall"), g.shell_sections.at("abdominal_wall").total_thickness,
                       g.pelvis.at("pubic_symphysis").z());
  return m;
}

}  // namespace hbm::deckgen
