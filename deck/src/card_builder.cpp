// SPDX-License-Identifier: GPL-3.0-or-later
// CardBuilder: programmatic construction of cards (deckgen, tests). A new card has every
// fixed line present with blank (default) values; fields are set by name; rows are
// appended. Misuse (unknown keyword, field or line) throws: it is a programming error.
#include "hbm/deck/io.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hbm::deck {

namespace {

Value blank_value(const FieldSpec& f) {
  Value v;
  v.real = f.default_value;
  v.integer = static_cast<std::int64_t>(f.default_value);
  v.blank = true;
  return v;
}

void push_row(Card& c, const LineSpec& ls) {
  Row r;
  r.layout = &ls;
  r.first = static_cast<std::uint32_t>(c.values.size());
  c.lines.push_back(r);
  for (const FieldSpec& f : ls.fields) c.values.push_back(blank_value(f));
}

Value& field_of(Card& c, Row& r, std::string_view field, const FieldSpec** spec_out) {
  const int i = field_index(*r.layout, field);
  if (i < 0)
    throw std::out_of_range("CardBuilder: " + std::string(c.keyword()) + " line '" + std::string(r.layout->name) +
                            "' has no field '" + std::string(field) + "'");
  *spec_out = &r.layout->fields[static_cast<std::size_t>(i)];
  return c.values[r.first + static_cast<std::size_t>(i)];
}

void set_real(Card& c, Row& r, std::string_view field, double v) {
  const FieldSpec* f = nullptr;
  Value& val = field_of(c, r, field, &f);
  if (f->type == FieldType::Text)
    throw std::invalid_argument("CardBuilder: field " + std::string(field) + " of " + std::string(c.keyword()) +
                                " is text");
  if (!std::isfinite(v))
    throw std::invalid_argument("CardBuilder: field " + std::string(field) + " of " + std::string(c.keyword()) +
                                " set to a non-finite value");
  if (f->zero_is_default && v == 0.0)
    throw std::invalid_argument("CardBuilder: field " + std::string(field) + " of " + std::string(c.keyword()) +
                                " set to 0, which reads as its default (as in OpenRadioss): write a tiny value "
                                "for none");
  if (f->type == FieldType::Int) {
    if (v != std::trunc(v) || std::fabs(v) > 9.0e15)
      throw std::invalid_argument("CardBuilder: integer field " + std::string(field) + " of " +
                                  std::string(c.keyword()) + " set to a non-integer value");
    val.integer = static_cast<std::int64_t>(v);
  }
  val.real = v;
  val.blank = false;
}

void set_int(Card& c, Row& r, std::string_view field, std::int64_t v) {
  const FieldSpec* f = nullptr;
  Value& val = field_of(c, r, field, &f);
  if (f->type == FieldType::Text)
    throw std::invalid_argument("CardBuilder: field " + std::string(field) + " of " + std::string(c.keyword()) +
                                " is text");
  val.integer = f->type == FieldType::Int ? v : 0;
  val.real = static_cast<double>(v);
  val.blank = false;
}

void set_text(Deck& d, Card& c, Row& r, std::string_view field, std::string_view v) {
  const FieldSpec* f = nullptr;
  Value& val = field_of(c, r, field, &f);
  if (f->type != FieldType::Text)
    throw std::invalid_argument("CardBuilder: field " + std::string(field) + " of " + std::string(c.keyword()) +
                                " is numeric");
  if (static_cast<int>(v.size()) > f->width)
    throw std::invalid_argument("CardBuilder: text '" + std::string(v) + "' is wider than field " +
                                std::string(field) + " (" + std::to_string(f->width) + " columns)");
  val.text = static_cast<std::uint32_t>(d.texts.size());
  d.texts.emplace_back(v);
  val.blank = v.empty();
}

}  // namespace

CardBuilder::CardBuilder(Deck& deck, std::string_view keyword, std::int64_t id, std::string title)
    : deck_(deck) {
  const KeywordSpec* spec = find_keyword(keyword, deck.section);
  if (!spec) spec = find_keyword_any(keyword);
  if (!spec) throw std::invalid_argument("CardBuilder: unsupported keyword " + std::string(keyword));
  card_.spec = spec;
  card_.id = id;
  card_.title = std::move(title);
  for (const LineSpec& ls : spec->lines) push_row(card_, ls);
}

CardBuilder& CardBuilder::set(std::size_t fixed_line, std::string_view field, double v) {
  if (fixed_line >= card_.n_fixed_lines())
    throw std::out_of_range("CardBuilder: " + std::string(card_.keyword()) + " has no fixed line " +
                            std::to_string(fixed_line));
  set_real(card_, card_.lines[fixed_line], field, v);
  return *this;
}

CardBuilder& CardBuilder::set_int(std::size_t fixed_line, std::string_view field, std::int64_t v) {
  if (fixed_line >= card_.n_fixed_lines())
    throw std::out_of_range("CardBuilder: " + std::string(card_.keyword()) + " has no fixed line " +
                            std::to_string(fixed_line));
  deck::set_int(card_, card_.lines[fixed_line], field, v);
  return *this;
}

CardBuilder& CardBuilder::set_text(std::size_t fixed_line, std::string_view field, std::string_view v) {
  if (fixed_line >= card_.n_fixed_lines())
    throw std::out_of_range("CardBuilder: " + std::string(card_.keyword()) + " has no fixed line " +
                            std::to_string(fixed_line));
  deck::set_text(deck_, card_, card_.lines[fixed_line], field, v);
  return *this;
}

std::size_t CardBuilder::add_row() {
  if (!card_.spec->rows)
    throw std::logic_error("CardBuilder: " + std::string(card_.keyword()) + " has no repeated rows");
  push_row(card_, *card_.spec->rows);
  return card_.n_rows() - 1;
}

std::size_t CardBuilder::add_name_row() {
  if (!card_.spec->name_rows)
    throw std::logic_error("CardBuilder: " + std::string(card_.keyword()) + " has no name rows");
  if (card_.n_rows() != 0)
    throw std::logic_error("CardBuilder: name rows of " + std::string(card_.keyword()) +
                           " must be added before the data rows");
  push_row(card_, *card_.spec->name_rows);
  return card_.n_name_rows() - 1;
}

CardBuilder& CardBuilder::name_row_set_text(std::size_t row, std::string_view field, std::string_view v) {
  deck::set_text(deck_, card_, card_.lines[card_.n_fixed_lines() + row], field, v);
  return *this;
}

namespace {
Row& data_row(Card& c, std::size_t row) { return const_cast<Row&>(c.row(row)); }
}  // namespace

CardBuilder& CardBuilder::row_set(std::size_t row, std::string_view field, double v) {
  set_real(card_, data_row(card_, row), field, v);
  return *this;
}

CardBuilder& CardBuilder::row_set_int(std::size_t row, std::string_view field, std::int64_t v) {
  deck::set_int(card_, data_row(card_, row), field, v);
  return *this;
}

CardBuilder& CardBuilder::row_set_text(std::size_t row, std::string_view field, std::string_view v) {
  deck::set_text(deck_, card_, data_row(card_, row), field, v);
  return *this;
}

Card& CardBuilder::card() { return card_; }

void CardBuilder::commit() { deck_.cards.push_back(std::move(card_)); card_ = Card{}; }

}  // namespace hbm::deck
