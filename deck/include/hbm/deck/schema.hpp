// SPDX-License-Identifier: GPL-3.0-or-later
// Keyword schema: one declarative table per Radioss keyword (field name, columns, type,
// unit dimension, valid range, default, meaning). The reader, the writer, the checks and
// docs/deck-format.md are all driven by these tables (deck/src/keywords_*.cpp).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

namespace hbm::deck {

enum class Section : std::uint8_t { Starter, Engine };

enum class FieldType : std::uint8_t {
  Int,   // integer, right-aligned in its field (10 columns by convention)
  Real,  // real, Fortran exponents accepted (1.5E-3, 1.5D-3), 20 columns by convention
  Text,  // fixed-width text (titles, /BCS flags, /TH variable names, unit names)
};

// Physical dimension of a field, in the deck's declared work units (see /BEGIN).
enum class Dimension : std::uint8_t {
  None, Id, Count, Flag, Length, Area, Time, Mass, Density, Velocity, Acceleration,
  Force, Moment, Stress, Stiffness, RotStiffness, Damping, RotDamping, Energy, Inertia,
  Angle, Frequency, Strain, StrainRate, Temperature, Momentum
};

// What an Id field refers to, so the checks can resolve it.
enum class RefKind : std::uint8_t {
  None, Node, Part, Prop, Mat, Funct, Grnod, Surf, Skew, Sensor, Inter, Rbody, Spring, Rwall
};

inline constexpr double kNoLimit = std::numeric_limits<double>::infinity();

struct FieldSpec {
  std::string_view name;     // e.g. "E", "nu", "node_id"
  int column = 0;            // first column, 0-based (starter fixed format)
  int width = 10;            // columns
  FieldType type = FieldType::Real;
  Dimension dim = Dimension::None;
  double min = -kNoLimit;    // valid range; a value outside is a deck error
  double max = kNoLimit;
  bool min_exclusive = false;
  bool max_exclusive = false;
  double default_value = 0;  // used when the field is blank
  // A typed 0 also means the default (as OpenRadioss reads the field: its starter sets
  // IF(X == ZERO) X = default, and reads a blank as 0). The value then reads as blank.
  bool zero_is_default = false;
  // A typed value that OpenRadioss replaces when it reads the field (its starter:
  // IF(ANU == HALF) ANU = ZEP499 for Poisson's ratio): replace_value reads as replaced_by,
  // with a warning. NaN: none.
  double replace_value = std::numeric_limits<double>::quiet_NaN();
  double replaced_by = 0;
  RefKind ref = RefKind::None;
  bool ref_optional = true;  // 0 / blank means "none" for an Id field
  std::string_view meaning;  // one line, for docs/deck-format.md
};

struct LineSpec {
  std::string_view name;             // e.g. "line 1", "node", "element"
  std::vector<FieldSpec> fields;
  bool optional = false;             // a fixed line that may be absent (defaults apply)
};

enum class IdKind : std::uint8_t {
  None,       // /BEGIN, /END, /NODE
  Object,     // /MAT/LAW1/17: the object's own id
  Part,       // /BRICK/12: the elements belong to part 12
  Optional,   // id may be omitted
};

struct KeywordSpec {
  std::string_view keyword;      // "/MAT/LAW1" (without the id)
  Section section = Section::Starter;
  IdKind id = IdKind::Object;
  bool has_title = false;
  std::vector<LineSpec> lines;   // fixed data lines, in order
  std::optional<LineSpec> rows;  // repeated data lines until the next keyword
  std::string_view meaning;      // one line, for docs/deck-format.md
  // Repeated name lines before `rows` (the variable lists of /TH/* cards). A data line
  // belongs here while its first non-blank character is a letter.
  std::optional<LineSpec> name_rows;
};

// All supported keywords (starter and engine). A keyword not in this table is an error.
const std::vector<KeywordSpec>& keyword_table();
// Exact match on the keyword without id ("/MAT/LAW1"), nullptr if unsupported.
const KeywordSpec* find_keyword(std::string_view keyword, Section section);
// Exact match in either section (starter first).
const KeywordSpec* find_keyword_any(std::string_view keyword);
// Index of a field in a line layout by name (case-insensitive), -1 if absent.
int field_index(const LineSpec& line, std::string_view field);
// Nearest supported keyword (edit distance), for "did you mean" messages.
std::string_view nearest_keyword(std::string_view keyword, Section section);

std::string_view to_string(Dimension d);

}  // namespace hbm::deck
