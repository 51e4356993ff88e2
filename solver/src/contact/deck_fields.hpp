// SPDX-License-Identifier: GPL-3.0-or-later
// Reading the contact cards' fields by name, tolerant of optional lines that are absent
// (their fields take the schema default) and of the few names that differ between the
// Radioss manual editions (e.g. "VIS_S" / "VISs"): the first name the card's layout
// knows is used. A field the layout does not know at all is a programming error.
#pragma once

#include "hbm/deck/deck.hpp"

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>

namespace hbm::solver::contact {

struct FieldRef {
  const hbm::deck::Row* row = nullptr;        // the line, or nullptr if the line is absent
  const hbm::deck::FieldSpec* spec = nullptr; // the field's spec
};

// Fixed line k of `card` (nullptr when absent) and the spec of the first known name.
inline FieldRef find_field(const hbm::deck::Card& card, std::size_t k,
                           std::initializer_list<std::string_view> names) {
  FieldRef r;
  if (!card.spec || k >= card.spec->lines.size())
    throw std::logic_error("contact: " + std::string(card.keyword()) + " has no line " + std::to_string(k));
  const hbm::deck::LineSpec& ls = card.spec->lines[k];
  for (std::string_view n : names)
    for (const hbm::deck::FieldSpec& f : ls.fields)
      if (f.name == n) {
        r.spec = &f;
        break;
      }
  if (!r.spec) {
    std::string msg = "contact: " + std::string(card.keyword()) + " line " + std::to_string(k + 1) + " has none of the fields";
    for (std::string_view n : names) msg.append(" ").append(n);
    throw std::logic_error(msg);
  }
  if (k < card.lines.size() && card.lines[k].layout == &ls) r.row = &card.lines[k];
  return r;
}

inline double real_of(const hbm::deck::Card& card, std::size_t k,
                      std::initializer_list<std::string_view> names) {
  const FieldRef r = find_field(card, k, names);
  if (!r.row) return r.spec->default_value;
  return card.value(*r.row, r.spec->name).real;
}

inline std::int64_t int_of(const hbm::deck::Card& card, std::size_t k,
                           std::initializer_list<std::string_view> names) {
  const FieldRef r = find_field(card, k, names);
  if (!r.row) return static_cast<std::int64_t>(r.spec->default_value);
  return card.value(*r.row, r.spec->name).integer;
}

inline bool blank_of(const hbm::deck::Card& card, std::size_t k,
                     std::initializer_list<std::string_view> names) {
  const FieldRef r = find_field(card, k, names);
  if (!r.row) return true;
  return card.value(*r.row, r.spec->name).blank;
}

// Same, searching every fixed line for the first known name (layouts differ between
// editions in which line a field sits on). Returns the line index in `line`.
inline FieldRef find_any(const hbm::deck::Card& card, std::initializer_list<std::string_view> names,
                         std::size_t* line = nullptr) {
  if (card.spec)
    for (std::string_view n : names)
      for (std::size_t k = 0; k < card.spec->lines.size(); ++k)
        for (const hbm::deck::FieldSpec& f : card.spec->lines[k].fields)
          if (f.name == n) {
            FieldRef r;
            r.spec = &f;
            if (k < card.lines.size() && card.lines[k].layout == &card.spec->lines[k]) r.row = &card.lines[k];
            if (line) *line = k;
            return r;
          }
  std::string msg = "contact: " + std::string(card.keyword()) + " has none of the fields";
  for (std::string_view n : names) msg.append(" ").append(n);
  throw std::logic_error(msg);
}
inline double real_any(const hbm::deck::Card& card, std::initializer_list<std::string_view> names) {
  const FieldRef r = find_any(card, names);
  return r.row ? card.value(*r.row, r.spec->name).real : r.spec->default_value;
}
inline std::int64_t int_any(const hbm::deck::Card& card, std::initializer_list<std::string_view> names) {
  const FieldRef r = find_any(card, names);
  return r.row ? card.value(*r.row, r.spec->name).integer : static_cast<std::int64_t>(r.spec->default_value);
}
inline bool blank_any(const hbm::deck::Card& card, std::initializer_list<std::string_view> names) {
  const FieldRef r = find_any(card, names);
  return r.row ? card.value(*r.row, r.spec->name).blank : true;
}
inline bool has_any(const hbm::deck::Card& card, std::initializer_list<std::string_view> names) {
  if (!card.spec) return false;
  for (std::string_view n : names)
    for (const auto& l : card.spec->lines)
      for (const auto& f : l.fields)
        if (f.name == n) return true;
  return false;
}

// Field of a repeated row by the first known name.
inline const hbm::deck::Value& row_value(const hbm::deck::Card& card, const hbm::deck::Row& row,
                                         std::initializer_list<std::string_view> names) {
  for (std::string_view n : names)
    for (const hbm::deck::FieldSpec& f : row.layout->fields)
      if (f.name == n) return card.value(row, n);
  std::string msg = "contact: " + std::string(card.keyword()) + " row has none of the fields";
  for (std::string_view n : names) msg.append(" ").append(n);
  throw std::logic_error(msg);
}

}  // namespace hbm::solver::contact
