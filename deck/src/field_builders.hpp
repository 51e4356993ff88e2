// SPDX-License-Identifier: GPL-3.0-or-later
// Small constructors for FieldSpec / LineSpec so that the keyword tables read like the
// reference guide: one line per field with its columns, type, dimension, range, meaning.
#pragma once

#include "hbm/deck/schema.hpp"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace hbm::deck::tables {

// Valid range of a numeric field.
struct Range {
  double min = -kNoLimit, max = kNoLimit;
  bool min_exclusive = false, max_exclusive = false;
};
inline constexpr Range kAny{};
inline constexpr Range kPositive{0, kNoLimit, true, false};
inline constexpr Range kNonNegative{0, kNoLimit, false, false};
inline constexpr Range kUnit{0, 1, false, false};
inline constexpr Range kPoisson{-1, 0.5, true, true};

// Id field (10 columns) referring to an object of kind `ref`; `required` means 0/blank is
// an error.
inline FieldSpec id_field(std::string_view name, int col, RefKind ref, bool required,
                          std::string_view meaning) {
  FieldSpec f;
  f.name = name;
  f.column = col;
  f.width = 10;
  f.type = FieldType::Int;
  f.dim = Dimension::Id;
  f.min = required ? 1 : 0;
  f.ref = ref;
  f.ref_optional = !required;
  f.meaning = meaning;
  return f;
}

// Element / object own id (required, >= 1, no reference).
inline FieldSpec own_id(std::string_view name, int col, std::string_view meaning) {
  FieldSpec f = id_field(name, col, RefKind::None, true, meaning);
  return f;
}

// Integer flag or count (10 columns).
inline FieldSpec int_field(std::string_view name, int col, double min, double max, double def,
                           std::string_view meaning, Dimension dim = Dimension::Flag) {
  FieldSpec f;
  f.name = name;
  f.column = col;
  f.width = 10;
  f.type = FieldType::Int;
  f.dim = dim;
  f.min = min;
  f.max = max;
  f.default_value = def;
  f.meaning = meaning;
  return f;
}

// Real field (20 columns unless `width` says otherwise).
inline FieldSpec real_field(std::string_view name, int col, Dimension dim, Range r, double def,
                            std::string_view meaning, int width = 20) {
  FieldSpec f;
  f.name = name;
  f.column = col;
  f.width = width;
  f.type = FieldType::Real;
  f.dim = dim;
  f.min = r.min;
  f.max = r.max;
  f.min_exclusive = r.min_exclusive;
  f.max_exclusive = r.max_exclusive;
  f.default_value = def;
  f.meaning = meaning;
  return f;
}

// The same field with a typed 0 read as its default (FieldSpec::zero_is_default).
inline FieldSpec zero_means_default(FieldSpec f) {
  f.zero_is_default = true;
  return f;
}

// The same field with a typed `from` read as `to` (FieldSpec::replace_value).
inline FieldSpec replacing(FieldSpec f, double from, double to) {
  f.replace_value = from;
  f.replaced_by = to;
  return f;
}

// Poisson's ratio: 0.5 reads as 0.499 (OpenRadioss hm_read_mat01.F, mat02, mat36:
// IF(ANU == HALF) ANU = ZEP499), below which the bulk modulus stays finite.
inline FieldSpec poisson_field(std::string_view name, int col) {
  return replacing(real_field(name, col, Dimension::None, kPoisson, 0, "Poisson's ratio (0.5 reads as 0.499)"), 0.5, 0.499);
}

inline FieldSpec text_field(std::string_view name, int col, int width, std::string_view meaning) {
  FieldSpec f;
  f.name = name;
  f.column = col;
  f.width = width;
  f.type = FieldType::Text;
  f.dim = Dimension::None;
  f.meaning = meaning;
  return f;
}

inline LineSpec line(std::string_view name, std::vector<FieldSpec> fields, bool optional = false) {
  LineSpec l;
  l.name = name;
  l.fields = std::move(fields);
  l.optional = optional;
  return l;
}

// Tables of each section, assembled by keyword_table().
// A keyword of `section`: what its id is, whether a title line follows, what it means.
inline KeywordSpec keyword(std::string_view kw, Section section, IdKind id, bool has_title,
                           std::string_view meaning) {
  KeywordSpec k;
  k.keyword = kw;
  k.section = section;
  k.id = id;
  k.has_title = has_title;
  k.meaning = meaning;
  return k;
}

// A starter object card with an id and a title line (/MAT/..., /PROP/..., /INTER/...).
inline KeywordSpec object(std::string_view kw, std::string_view meaning) {
  return keyword(kw, Section::Starter, IdKind::Object, true, meaning);
}

// Field names of id lists written 10 per line (/GRNOD, /SURF/PART, /TH objects).
inline constexpr std::array<std::string_view, 10> kIdNames = {"id1", "id2", "id3", "id4", "id5",
                                                              "id6", "id7", "id8", "id9", "id10"};

void add_starter_geometry(std::vector<KeywordSpec>& out);
void add_starter_model(std::vector<KeywordSpec>& out);
void add_starter_loads(std::vector<KeywordSpec>& out);
void add_starter_contact(std::vector<KeywordSpec>& out);
void add_engine(std::vector<KeywordSpec>& out);

}  // namespace hbm::deck::tables
