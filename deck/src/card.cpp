// SPDX-License-Identifier: GPL-3.0-or-later
// Field access on cards by name (Card, Deck helpers). Names are matched without regard
// to case, so "Thick" and "thick" both work; an unknown name is a programming error and
// throws std::out_of_range naming the keyword and the field.
#include "hbm/deck/deck.hpp"

#include "field_checks.hpp"

#include <stdexcept>
#include <string>

namespace hbm::deck {

namespace {

[[noreturn]] void no_field(const Card& c, const Row& line, std::string_view field) {
  std::string msg = "deck: " + std::string(c.keyword()) + " has no field '" + std::string(field) + "'";
  if (line.layout) {
    msg.append(" on its line '").append(line.layout->name).append("' (fields:");
    for (const FieldSpec& f : line.layout->fields) msg.append(" ").append(f.name);
    msg += ")";
  }
  throw std::out_of_range(msg);
}

}  // namespace

std::size_t Card::n_fixed_lines() const { return spec ? spec->lines.size() : 0; }

std::size_t Card::n_name_rows() const {
  if (!spec || !spec->name_rows) return 0;
  std::size_t n = 0;
  for (std::size_t i = n_fixed_lines(); i < lines.size() && lines[i].layout == &*spec->name_rows; ++i) ++n;
  return n;
}

const Row& Card::name_row(std::size_t i) const {
  if (i >= n_name_rows())
    throw std::out_of_range("deck: " + std::string(keyword()) + " has no name row " + std::to_string(i));
  return lines[n_fixed_lines() + i];
}

std::size_t Card::n_rows() const {
  if (!spec || !spec->rows) return 0;
  return lines.size() - n_fixed_lines() - n_name_rows();
}

const Row& Card::row(std::size_t i) const {
  const std::size_t first = n_fixed_lines() + n_name_rows();
  if (first + i >= lines.size())
    throw std::out_of_range("deck: " + std::string(keyword()) + " has no row " + std::to_string(i));
  return lines[first + i];
}

const Value& Card::value(const Row& line, std::string_view field) const {
  if (!line.layout) no_field(*this, line, field);
  const int i = field_index(*line.layout, field);
  if (i < 0) no_field(*this, line, field);
  return values[line.first + static_cast<std::size_t>(i)];
}

double Card::real(const Row& line, std::string_view field) const { return value(line, field).real; }
std::int64_t Card::integer(const Row& line, std::string_view field) const { return value(line, field).integer; }
bool Card::blank(const Row& line, std::string_view field) const { return value(line, field).blank; }

double Card::real(std::size_t line, std::string_view field) const {
  if (line >= n_fixed_lines())
    throw std::out_of_range("deck: " + std::string(keyword()) + " has no fixed line " + std::to_string(line));
  return real(lines[line], field);
}

std::int64_t Card::integer(std::size_t line, std::string_view field) const {
  if (line >= n_fixed_lines())
    throw std::out_of_range("deck: " + std::string(keyword()) + " has no fixed line " + std::to_string(line));
  return integer(lines[line], field);
}

std::string Deck::text(const Card& c, const Row& line, std::string_view field) const {
  const Value& v = c.value(line, field);
  if (v.blank) return {};
  return std::string(texts[v.text]);
}

std::vector<const Card*> Deck::cards_of(std::string_view keyword) const {
  std::vector<const Card*> out;
  for (const Card& c : cards)
    if (c.spec && c.spec->keyword == keyword) out.push_back(&c);
  return out;
}

std::string Deck::where(SourceLoc loc) const {
  std::string f = loc.file < files.size() ? files[loc.file].string() : std::string("<generated>");
  if (loc.line == 0) return f;
  return f + ":" + std::to_string(loc.line);
}

}  // namespace hbm::deck
