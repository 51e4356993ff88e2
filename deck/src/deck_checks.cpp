// SPDX-License-Identifier: GPL-3.0-or-later
// Model checks run after parsing (and by check_deck on decks built in memory): deck
// frame (/BEGIN, /END, /RUN), field ranges, duplicate and undefined ids, part/property/
// material compatibility, element shapes (brick Jacobian at the 8 corners, tetra volume,
// shell area), function abscissae, and the text flags of /BCS, /IMPVEL, /GRAV, /BEGIN.
#include "field_checks.hpp"
#include "id_index.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <string>
#include <tuple>

namespace hbm::deck::detail {

namespace {

constexpr std::size_t kRefKinds = static_cast<std::size_t>(RefKind::Rwall) + 1;

std::string_view ref_name(RefKind k) {
  switch (k) {
    case RefKind::None: return "object";
    case RefKind::Node: return "node";
    case RefKind::Part: return "part";
    case RefKind::Prop: return "property";
    case RefKind::Mat: return "material";
    case RefKind::Funct: return "function";
    case RefKind::Grnod: return "node group";
    case RefKind::Surf: return "surface";
    case RefKind::Skew: return "skew system";
    case RefKind::Sensor: return "sensor";
    case RefKind::Inter: return "interface";
    case RefKind::Rbody: return "rigid body";
    case RefKind::Spring: return "spring element";
    case RefKind::Rwall: return "rigid wall";
  }
  return "object";
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

// Object kind defined by a card (its own id), None if the card defines no referable object.
RefKind defines(const KeywordSpec& k) {
  const std::string_view kw = k.keyword;
  if (kw == "/PART") return RefKind::Part;
  if (starts_with(kw, "/PROP/")) return RefKind::Prop;
  if (starts_with(kw, "/MAT/")) return RefKind::Mat;
  if (kw == "/FUNCT") return RefKind::Funct;
  if (starts_with(kw, "/GRNOD/")) return RefKind::Grnod;
  if (starts_with(kw, "/SURF/")) return RefKind::Surf;
  if (starts_with(kw, "/INTER/")) return RefKind::Inter;
  if (kw == "/RBODY") return RefKind::Rbody;
  if (starts_with(kw, "/RWALL/")) return RefKind::Rwall;
  return RefKind::None;
}

enum class Family : std::uint8_t { None, Solid, Shell, Spring };

Family family(std::string_view kw) {
  if (kw == "/BRICK" || kw == "/TETRA4") return Family::Solid;
  if (kw == "/SHELL" || kw == "/SH3N") return Family::Shell;
  if (kw == "/SPRING") return Family::Spring;
  return Family::None;
}

struct Vec3 {
  double x, y, z;
};
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }

class Checker {
 public:
  Checker(const Deck& d, DiagSink& s, bool ranges) : deck_(d), sink_(s), ranges_(ranges) {}

  void run() {
    frame();
    fields_and_definitions();
    if (sink_.full()) return;
    build_indexes();
    if (sink_.full()) return;
    references_and_shapes();
    if (sink_.full()) return;
    card_rules();
  }

 private:
  const Deck& deck_;
  DiagSink& sink_;
  bool ranges_;

  IdIndex nodes_;
  std::vector<Vec3> xyz_;
  std::array<IdIndex, kRefKinds> objects_;
  std::array<std::vector<const Card*>, kRefKinds> object_cards_;
  IdIndex springs_;

  int col_of(const FieldSpec& f) const {
    return deck_.section == Section::Starter ? f.column + 1 : 1;
  }

  void frame() {
    const auto& cards = deck_.cards;
    if (deck_.section == Section::Starter) {
      const bool begin_first = !cards.empty() && cards.front().spec->keyword == "/BEGIN";
      bool has_end = false;
      for (const Card& c : cards) has_end = has_end || c.spec->keyword == "/END";
      if (!begin_first) {
        bool begin_anywhere = false;
        for (const Card& c : cards) begin_anywhere = begin_anywhere || c.spec->keyword == "/BEGIN";
        if (!begin_anywhere) sink_.error(SourceLoc{0, 1}, 1, "missing /BEGIN: the starter deck must start with /BEGIN");
      }
      if (!has_end) {
        SourceLoc last = cards.empty() ? SourceLoc{0, 1} : cards.back().loc;
        if (!cards.empty() && !cards.back().lines.empty() && cards.back().lines.back().loc.line > last.line)
          last = cards.back().lines.back().loc;
        sink_.error(last, 1, "missing /END: the starter deck must end with /END");
      }
    } else {
      if (cards.empty() || cards.front().spec->keyword != "/RUN")
        sink_.error(SourceLoc{0, 1}, 1, "missing /RUN: the engine deck must start with /RUN/name/1");
    }
  }

  // Ranges of values (all, or only blank defaults when the reader already checked the
  // values it parsed), node and spring-element ids, object ids.
  void fields_and_definitions() {
    for (const Card& c : deck_.cards) {
      if (sink_.full()) return;
      const bool read_card = c.loc.line != 0;
      for (const Row& r : c.lines) {
        if (read_card && r.loc.line == 0) continue;  // absent optional line (or reported missing)
        if (r.has_error) continue;                   // already reported by the reader
        const SourceLoc loc = r.loc.line ? r.loc : c.loc;
        for (std::size_t i = 0; i < r.layout->fields.size(); ++i) {
          const FieldSpec& f = r.layout->fields[i];
          const Value& v = c.values[r.first + i];
          if (!ranges_ && !v.blank) continue;
          if (auto p = range_problem(f, v)) sink_.error(loc, col_of(f), field_prefix(c, f, v, deck_) + *p);
        }
      }
    }
  }

  void build_indexes() {
    // Nodes.
    std::size_t n_nodes = 0;
    for (const Card& c : deck_.cards)
      if (c.spec->keyword == "/NODE") n_nodes += c.n_rows();
    xyz_.reserve(n_nodes);
    node_rows_.reserve(n_nodes);
    nodes_.reserve(n_nodes);
    for (std::size_t ci = 0; ci < deck_.cards.size(); ++ci) {
      const Card& c = deck_.cards[ci];
      if (c.spec->keyword != "/NODE") continue;
      const std::size_t n = c.n_rows();
      const std::size_t first = c.n_fixed_lines();
      for (std::size_t k = 0; k < n; ++k) {
        const Row& r = c.lines[first + k];
        const Value* v = &c.values[r.first];
        nodes_.add(v[0].integer, static_cast<std::uint32_t>(xyz_.size()));
        xyz_.push_back({v[1].real, v[2].real, v[3].real});
        node_rows_.push_back({&c, &r});
      }
    }
    nodes_.build([&](std::int64_t id, std::uint32_t a, std::uint32_t b) {
      sink_.error(node_rows_[b].second->loc, 1,
                  "/NODE field id = " + std::to_string(id) + ": duplicate node id (first defined at " +
                      deck_.where(node_rows_[a].second->loc) + ")");
    });
    // Objects with their own ids (and per-keyword uniqueness of the other object cards).
    std::vector<std::pair<std::string_view, IdIndex>> per_keyword;
    std::vector<const Card*> all_cards;
    for (const Card& c : deck_.cards) all_cards.push_back(&c);
    for (std::size_t ci = 0; ci < all_cards.size(); ++ci) {
      const Card& c = *all_cards[ci];
      const RefKind k = defines(*c.spec);
      if (k != RefKind::None) {
        auto& idx = objects_[static_cast<std::size_t>(k)];
        auto& list = object_cards_[static_cast<std::size_t>(k)];
        idx.add(c.id, static_cast<std::uint32_t>(list.size()));
        list.push_back(&c);
      } else if (c.spec->id == IdKind::Object && c.spec->section == Section::Starter) {
        IdIndex* idx = nullptr;
        for (auto& [kw, x] : per_keyword)
          if (kw == c.spec->keyword) idx = &x;
        if (!idx) idx = &per_keyword.emplace_back(c.spec->keyword, IdIndex{}).second;
        idx->add(c.id, static_cast<std::uint32_t>(ci));
      }
    }
    for (std::size_t k = 0; k < kRefKinds; ++k) {
      auto& list = object_cards_[k];
      objects_[k].build([&](std::int64_t id, std::uint32_t a, std::uint32_t b) {
        sink_.error(list[b]->loc, 1,
                    card_label(*list[b]) + ": duplicate " + std::string(ref_name(static_cast<RefKind>(k))) + " id " +
                        std::to_string(id) + " (first defined by " + card_label(*list[a]) + " at " +
                        deck_.where(list[a]->loc) + ")");
      });
    }
    for (auto& [kw, idx] : per_keyword) {
      idx.build([&](std::int64_t id, std::uint32_t a, std::uint32_t b) {
        sink_.error(all_cards[b]->loc, 1,
                    card_label(*all_cards[b]) + ": duplicate " + std::string(kw) + " id " + std::to_string(id) +
                        " (first defined at " + deck_.where(all_cards[a]->loc) + ")");
      });
    }
    // Element ids, unique per family.
    std::array<IdIndex, 4> elems;
    std::vector<const Row*> elem_rows;
    {
      std::array<std::size_t, 4> n{};
      for (const Card& c : deck_.cards) n[static_cast<std::size_t>(family(c.spec->keyword))] += c.n_rows();
      for (std::size_t f = 1; f < 4; ++f) elems[f].reserve(n[f]);
      springs_.reserve(n[3]);
      elem_rows.reserve(n[1] + n[2] + n[3]);
    }
    for (const Card& c : deck_.cards) {
      const Family fam = family(c.spec->keyword);
      if (fam == Family::None) continue;
      const std::size_t first = c.n_fixed_lines();
      for (std::size_t k = first; k < c.lines.size(); ++k) {
        const Row& r = c.lines[k];
        const std::int64_t id = c.values[r.first].integer;
        elems[static_cast<std::size_t>(fam)].add(id, static_cast<std::uint32_t>(elem_rows.size()));
        if (fam == Family::Spring) springs_.add(id, static_cast<std::uint32_t>(elem_rows.size()));
        elem_rows.push_back(&r);
      }
    }
    static constexpr std::string_view fam_names[] = {"", "solid", "shell", "spring"};
    for (std::size_t f = 1; f < 4; ++f) {
      elems[f].build([&](std::int64_t id, std::uint32_t a, std::uint32_t b) {
        sink_.error(elem_rows[b]->loc, 1,
                    "element id " + std::to_string(id) + ": duplicate " + std::string(fam_names[f]) +
                        " element id (first defined at " + deck_.where(elem_rows[a]->loc) + ")");
      });
    }
    springs_.build([](std::int64_t, std::uint32_t, std::uint32_t) {});
  }

  std::vector<std::pair<const Card*, const Row*>> node_rows_;

  bool defined(RefKind k, std::int64_t id) const {
    switch (k) {
      case RefKind::Node: return nodes_.contains(id);
      case RefKind::Spring: return springs_.contains(id);
      case RefKind::Skew:
      case RefKind::Sensor:
      case RefKind::None: return false;
      default: return objects_[static_cast<std::size_t>(k)].contains(id);
    }
  }

  const Card* object(RefKind k, std::int64_t id) const {
    const std::uint32_t i = objects_[static_cast<std::size_t>(k)].find(id);
    return i == IdIndex::kNone ? nullptr : object_cards_[static_cast<std::size_t>(k)][i];
  }

  void undefined(const Card& c, const FieldSpec& f, const Value& v, SourceLoc loc) {
    std::string why = std::string(ref_name(f.ref)) + " " + std::to_string(v.integer) + " is not defined";
    if (f.ref == RefKind::Skew) why += " (/SKEW is not supported: use 0)";
    if (f.ref == RefKind::Sensor) why += " (/SENSOR is not supported: use 0)";
    sink_.error(loc, col_of(f), field_prefix(c, f, v, deck_) + why);
  }

  void references_and_shapes() {
    for (const Card& c : deck_.cards) {
      if (sink_.full()) return;
      const bool read_card = c.loc.line != 0;
      // The part of an element block.
      const Family fam = family(c.spec->keyword);
      if (fam != Family::None) element_block_part(c, fam);
      for (const Row& r : c.lines) {
        if (read_card && r.loc.line == 0) continue;
        if (r.has_error) continue;
        const SourceLoc loc = r.loc.line ? r.loc : c.loc;
        bool refs_ok = true;
        for (std::size_t i = 0; i < r.layout->fields.size(); ++i) {
          const FieldSpec& f = r.layout->fields[i];
          if (f.ref == RefKind::None) continue;
          const Value& v = c.values[r.first + i];
          if (v.integer == 0) {
            if (!f.ref_optional) refs_ok = false;  // reported as a range error
            continue;
          }
          if (!defined(f.ref, v.integer)) {
            undefined(c, f, v, loc);
            refs_ok = false;
          }
        }
        if (refs_ok && fam != Family::None) element_shape(c, r, loc);
      }
    }
  }

  void element_block_part(const Card& c, Family fam) {
    const Card* part = object(RefKind::Part, c.id);
    if (!part) {
      sink_.error(c.loc, 1, card_label(c) + ": part " + std::to_string(c.id) + " is not defined (no /PART/" +
                                std::to_string(c.id) + ")");
      return;
    }
    const Card* prop = object(RefKind::Prop, part->integer(0, "prop_id"));
    const std::int64_t mat_id = part->integer(0, "mat_id");
    const Card* mat = mat_id ? object(RefKind::Mat, mat_id) : nullptr;
    if (prop) {
      const std::string_view pk = prop->spec->keyword;
      const bool ok = (fam == Family::Solid && pk == "/PROP/TYPE14") || (fam == Family::Shell && pk == "/PROP/TYPE1") ||
                      (fam == Family::Spring && (pk == "/PROP/TYPE4" || pk == "/PROP/TYPE8" || pk == "/PROP/TYPE13"));
      if (!ok) {
        static constexpr std::string_view need[] = {"", "/PROP/TYPE14", "/PROP/TYPE1",
                                                    "/PROP/TYPE4, /PROP/TYPE8 or /PROP/TYPE13"};
        sink_.error(c.loc, 1, card_label(c) + ": part " + std::to_string(c.id) + " has property " + card_label(*prop) +
                                  "; " + std::string(c.keyword()) + " elements need " +
                                  std::string(need[static_cast<std::size_t>(fam)]));
      }
    }
    if (fam != Family::Spring) {
      if (mat_id == 0) {
        sink_.error(c.loc, 1, card_label(c) + ": part " + std::to_string(c.id) +
                                  " has no material (mat_id = 0); solid and shell parts need one");
      } else if (mat) {
        const std::string_view mk = mat->spec->keyword;
        if (fam == Family::Shell && mk == "/MAT/LAW34")
          sink_.error(c.loc, 1, card_label(c) + ": part " + std::to_string(c.id) + " has material " +
                                    card_label(*mat) + ", which applies to solid elements only");
        if (fam == Family::Solid && mk == "/MAT/LAW42")
          sink_.error(c.loc, 1, card_label(c) + ": part " + std::to_string(c.id) + " has material " +
                                    card_label(*mat) + ", which this library applies to shell elements only");
      }
    }
  }

  Vec3 node_xyz(std::int64_t id) const { return xyz_[nodes_.find(id)]; }

  void element_shape(const Card& c, const Row& r, SourceLoc loc) {
    const std::string_view kw = c.spec->keyword;
    const Value* v = &c.values[r.first];
    const std::int64_t eid = v[0].integer;
    if (kw == "/BRICK") brick(c, v, eid, loc);
    else if (kw == "/TETRA4") tetra(c, v, eid, loc);
    else if (kw == "/SHELL" || kw == "/SH3N") {
      shell(c, v, eid, loc, kw == "/SHELL" ? 4 : 3);
      shell_thickness(c, r, eid, loc);
    }
  }

  // Thickness as the engine takes it: the element's, else its part's, else the property's
  // (OpenRadioss accepts a /PROP/TYPE1 Thick of 0 when the part or the element gives one).
  void shell_thickness(const Card& c, const Row& r, std::int64_t eid, SourceLoc loc) {
    if (c.real(r, "thick") > 0) return;
    const Card* part = object(RefKind::Part, c.id);
    if (!part || part->real(0, "thick") > 0) return;  // no part: reported by element_block_part
    const Card* prop = object(RefKind::Prop, part->integer(0, "prop_id"));
    if (!prop || prop->spec->keyword != "/PROP/TYPE1" || prop->real(2, "Thick") > 0) return;
    sink_.error(loc, 1, card_label(c) + " element " + std::to_string(eid) + ": shell thickness 0 (element thick, /PART/" +
                            std::to_string(part->id) + " thick and " + card_label(*prop) + " Thick all 0 or blank)");
  }

  // Trilinear hexahedron: det J at the 8 corners must be >= 0 and the volume > 0; a corner
  // may be flat only where nodes are repeated (Radioss degenerate bricks: prisms).
  void brick(const Card& c, const Value* v, std::int64_t eid, SourceLoc loc) {
    static constexpr int xi[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    Vec3 x[8];
    double lmax = 0;
    for (int i = 0; i < 8; ++i) x[i] = node_xyz(v[1 + i].integer);
    for (int i = 0; i < 8; ++i)
      for (int j = i + 1; j < 8; ++j) lmax = std::max(lmax, norm(x[i] - x[j]));
    const double tol = 1e-10 * lmax * lmax * lmax;
    auto detj = [&](double a, double b, double g) {
      Vec3 d[3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
      for (int i = 0; i < 8; ++i) {
        const double dn[3] = {xi[i][0] * (1 + xi[i][1] * b) * (1 + xi[i][2] * g) / 8,
                              xi[i][1] * (1 + xi[i][0] * a) * (1 + xi[i][2] * g) / 8,
                              xi[i][2] * (1 + xi[i][0] * a) * (1 + xi[i][1] * b) / 8};
        for (int k = 0; k < 3; ++k) {
          d[k].x += dn[k] * x[i].x;
          d[k].y += dn[k] * x[i].y;
          d[k].z += dn[k] * x[i].z;
        }
      }
      return dot(cross(d[0], d[1]), d[2]);
    };
    if (!(lmax > 0) || detj(0, 0, 0) <= tol) {
      sink_.error(loc, 1, card_label(c) + " element " + std::to_string(eid) +
                              ": inverted or degenerate brick: Jacobian at the centre = " + fmt(detj(0, 0, 0)) +
                              " (needs (n2-n1)x(n4-n1).(n5-n1) > 0: n1-n4 counter-clockwise seen from the "
                              "n5-n8 side)");
      return;
    }
    for (int i = 0; i < 8; ++i) {
      const double dj = detj(xi[i][0], xi[i][1], xi[i][2]);
      bool repeated = false;
      for (int j = 0; j < 8; ++j)
        if (j != i && v[1 + j].integer == v[1 + i].integer) repeated = true;
      if (dj < -tol || (dj <= tol && !repeated)) {
        sink_.error(loc, 11 + 10 * i, card_label(c) + " element " + std::to_string(eid) + ": Jacobian at node n" +
                                          std::to_string(i + 1) + " is " + fmt(dj) +
                                          " (must be > 0: the brick is inverted or folded there)");
        return;
      }
    }
  }

  void tetra(const Card& c, const Value* v, std::int64_t eid, SourceLoc loc) {
    const Vec3 a = node_xyz(v[1].integer), b = node_xyz(v[2].integer), cc = node_xyz(v[3].integer),
               d = node_xyz(v[4].integer);
    const double v6 = dot(cross(b - a, cc - a), d - a);
    const double l = std::max({norm(b - a), norm(cc - a), norm(d - a), norm(cc - b), norm(d - b), norm(d - cc)});
    if (v6 <= 1e-10 * l * l * l)
      sink_.error(loc, 1, card_label(c) + " element " + std::to_string(eid) + ": " +
                              (v6 < 0 ? "inverted" : "degenerate") + " tetrahedron (6 x volume = " + fmt(v6) +
                              "; needs (n2-n1)x(n3-n1).(n4-n1) > 0)");
  }

  void shell(const Card& c, const Value* v, std::int64_t eid, SourceLoc loc, int n) {
    Vec3 x[4];
    for (int i = 0; i < n; ++i) x[i] = node_xyz(v[1 + i].integer);
    double area = 0, l = 0;
    if (n == 4) {
      area = 0.5 * norm(cross(x[2] - x[0], x[3] - x[1]));
      for (int i = 0; i < 4; ++i) l = std::max(l, norm(x[(i + 1) % 4] - x[i]));
    } else {
      area = 0.5 * norm(cross(x[1] - x[0], x[2] - x[0]));
      for (int i = 0; i < 3; ++i) l = std::max(l, norm(x[(i + 1) % 3] - x[i]));
    }
    if (!(area > 1e-10 * l * l))
      sink_.error(loc, 1, card_label(c) + " element " + std::to_string(eid) + ": degenerate shell (area " +
                              fmt(area) + ")");
  }

  static std::string fmt(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", x);
    return buf;
  }

  // Card-specific rules that relate several fields.
  void card_rules() {
    for (const Card& c : deck_.cards) {
      if (sink_.full()) return;
      const std::string_view kw = c.spec->keyword;
      if (kw == "/FUNCT") funct(c);
      else if (kw == "/BCS") bcs(c);
      else if (kw == "/IMPVEL") direction(c, true);
      else if (kw == "/GRAV") direction(c, false);
      else if (kw == "/MAT/LAW34") law34(c);
      else if (kw == "/MAT/LAW36") law36(c);
      else if (kw == "/BEGIN") units(c);
      else if (starts_with(kw, "/TH/")) time_history(c);
      else if (kw == "/RWALL/PLANE") rwall(c);
      else if (starts_with(kw, "/GRNOD/") && c.n_rows() == 0)
        sink_.warning(c.loc, 1, card_label(c) + ": empty group");
    }
  }

  // /TH/*: variable names are single words (letters, digits, _), at least one object.
  void time_history(const Card& c) {
    if (c.n_name_rows() == 0) sink_.error(c.loc, 1, card_label(c) + ": no output variable line (e.g. DEF)");
    for (std::size_t i = 0; i < c.n_name_rows(); ++i) {
      const Row& r = c.name_row(i);
      if (r.has_error) continue;
      for (std::size_t f = 0; f < r.layout->fields.size(); ++f) {
        const Value& v = c.values[r.first + f];
        if (v.blank) continue;
        const std::string_view t = deck_.text(v);
        bool ok = !t.empty() && std::isalpha(static_cast<unsigned char>(t[0]));
        for (char ch : t) ok = ok && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_');
        if (!ok) {
          const FieldSpec& fs = r.layout->fields[f];
          sink_.error(r.loc.line ? r.loc : c.loc, col_of(fs),
                      field_prefix(c, fs, v, deck_) + "a variable name is one word of letters, digits and _");
        }
      }
    }
    if (c.n_rows() == 0) sink_.error(c.loc, 1, card_label(c) + ": no objects listed");
  }

  void rwall(const Card& c) {
    const double dx = c.real(3, "XM1") - c.real(2, "XM"), dy = c.real(3, "YM1") - c.real(2, "YM"),
                 dz = c.real(3, "ZM1") - c.real(2, "ZM");
    if (!(dx * dx + dy * dy + dz * dz > 0)) {
      const Row& r = c.lines[3];
      sink_.error(r.loc.line ? r.loc : c.loc, 1, card_label(c) + ": M1 equals M, the wall normal M->M1 is undefined");
    }
  }

  void funct(const Card& c) {
    const std::size_t n = c.n_rows();
    if (n < 2) {
      sink_.error(c.loc, 1, card_label(c) + ": a function needs at least 2 points, found " + std::to_string(n));
      return;
    }
    double prev = c.real(c.row(0), "X");
    for (std::size_t i = 1; i < n; ++i) {
      const Row& r = c.row(i);
      const double x = c.real(r, "X");
      if (!(x > prev)) {
        sink_.error(r.loc.line ? r.loc : c.loc, col_of(r.layout->fields[0]),
                    card_label(c) + " field X = " + fmt(x) + ": abscissa must increase (previous point X = " +
                        fmt(prev) + ")");
        return;
      }
      prev = x;
    }
  }

  void bcs(const Card& c) {
    const Row& r = c.lines[0];
    for (std::string_view f : {"Tra", "rot"}) {
      const Value& v = c.value(r, f);
      if (v.blank) continue;
      const std::string_view t = deck_.text(v);
      bool ok = t.size() == 3;
      for (char ch : t) ok = ok && (ch == '0' || ch == '1');
      if (!ok) {
        const FieldSpec& fs = r.layout->fields[static_cast<std::size_t>(field_index(*r.layout, f))];
        sink_.error(r.loc.line ? r.loc : c.loc, col_of(fs),
                    field_prefix(c, fs, v, deck_) + "must be three digits 0/1 for X Y Z (e.g. 111) in columns " +
                        std::to_string(fs.column + 1) + "-" + std::to_string(fs.column + 3));
      }
    }
  }

  void direction(const Card& c, bool rotations) {
    const Row& r = c.lines[0];
    const Value& v = c.value(r, "Dir");
    const std::string_view t = v.blank ? std::string_view{} : deck_.text(v);
    const bool ok = t == "X" || t == "Y" || t == "Z" || (rotations && (t == "XX" || t == "YY" || t == "ZZ"));
    if (!ok) {
      const FieldSpec& fs = r.layout->fields[1];
      sink_.error(r.loc.line ? r.loc : c.loc, col_of(fs),
                  field_prefix(c, fs, v, deck_) + (rotations ? "must be X, Y, Z, XX, YY or ZZ" : "must be X, Y or Z"));
    }
  }

  void law34(const Card& c) {
    const double g0 = c.real(2, "G0"), ginf = c.real(2, "Ginf");
    if (ginf > g0) {
      const Row& r = c.lines[2];
      sink_.error(r.loc.line ? r.loc : c.loc, col_of(r.layout->fields[1]),
                  card_label(c) + " field Ginf = " + fmt(ginf) + ": must be <= G0 = " + fmt(g0) +
                      " (long-time shear modulus above the short-time one)");
    }
  }

  void law36(const Card& c) {
    const std::int64_t n = c.integer(2, "N_funct");
    const Row& r = c.lines[4];
    for (std::int64_t k = 0; k < std::min<std::int64_t>(n, 5); ++k) {
      const Value& v = c.values[r.first + static_cast<std::size_t>(k)];
      if (v.integer == 0) {
        const FieldSpec& fs = r.layout->fields[static_cast<std::size_t>(k)];
        sink_.error(r.loc.line ? r.loc : c.loc, col_of(fs),
                    field_prefix(c, fs, v, deck_) + "N_funct = " + std::to_string(n) + " needs yield curve " +
                        std::to_string(k + 1));
      }
    }
  }

  // Radioss unit names: an SI prefix (y z a f p n mu m c d da h k M G T P E Z Y, or none)
  // followed by g (mass), m (length) or s (time), as in the reference guide's /BEGIN.
  static bool unit_ok(std::string_view t, char base) { return unit_factor(t, base).has_value(); }

  void units(const Card& c) {
    for (std::size_t line = 1; line <= 2; ++line) {
      const Row& r = c.lines[line];
      if (r.has_error) continue;
      for (auto [field, base, example] : {std::tuple{"mass", 'g', "kg, g, Mg"}, std::tuple{"length", 'm', "mm, m"},
                                          std::tuple{"time", 's', "ms, s, mus"}}) {
        const Value& v = c.value(r, field);
        if (v.blank || unit_ok(deck_.text(v), base)) continue;
        const FieldSpec& fs = r.layout->fields[static_cast<std::size_t>(field_index(*r.layout, field))];
        sink_.error(r.loc.line ? r.loc : c.loc, col_of(fs),
                    field_prefix(c, fs, v, deck_) + "unknown unit (an SI prefix and " + std::string(1, base) +
                        ", e.g. " + example + ")");
      }
    }
  }
};

}  // namespace

void check_model(const Deck& deck, DiagSink& sink, bool with_ranges) {
  Checker(deck, sink, with_ranges).run();
}

}  // namespace hbm::deck::detail

namespace hbm::deck {

std::vector<Diagnostic> check_deck(const Deck& deck) {
  std::vector<Diagnostic> out;
  detail::DiagSink sink(out);
  detail::check_model(deck, sink, true);
  return out;
}

}  // namespace hbm::deck
