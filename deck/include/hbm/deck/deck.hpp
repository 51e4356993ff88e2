// SPDX-License-Identifier: GPL-3.0-or-later
// In-memory deck: the cards of a Radioss block-format starter or engine deck, each with
// its values laid out by its KeywordSpec, and the source location of every line.
// The solver's build phase and deckgen's writer both work on this representation.
#pragma once

#include "hbm/deck/schema.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hbm::deck {

// Where a line came from: index into Deck::files and 1-based line number.
struct SourceLoc {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
};

// One field value. `blank` is true when the field was empty (the default applies and
// `real`/`integer` already hold the default).
struct Value {
  double real = 0;
  std::int64_t integer = 0;
  std::uint32_t text = 0;  // index into Deck::texts for Text fields
  bool blank = true;
};

// One data line of a card, laid out by `layout`.
struct Row {
  const LineSpec* layout = nullptr;
  SourceLoc loc;
  std::uint32_t first = 0;  // index of the first value in Card::values
  bool has_error = false;   // the reader reported a lexical error on this line
};

struct Card {
  const KeywordSpec* spec = nullptr;
  std::int64_t id = 0;      // object id, or part id for element cards; 0 if none
  std::string title;
  SourceLoc loc;            // the keyword line
  std::vector<Row> lines;   // fixed lines (spec->lines), then repeated rows (spec->rows)
  std::vector<Value> values;

  std::string_view keyword() const { return spec ? spec->keyword : std::string_view{}; }
  std::size_t n_fixed_lines() const;        // lines present among spec->lines
  std::size_t n_rows() const;               // repeated rows
  const Row& row(std::size_t i) const;      // i-th repeated row
  std::size_t n_name_rows() const;          // name lines of /TH/* cards (variable lists)
  const Row& name_row(std::size_t i) const; // i-th name line

  // Field access by name on a line (fixed line index or row). Throws std::out_of_range
  // naming the keyword and field if the layout has no such field (a programming error).
  const Value& value(const Row& line, std::string_view field) const;
  double real(const Row& line, std::string_view field) const;
  std::int64_t integer(const Row& line, std::string_view field) const;
  bool blank(const Row& line, std::string_view field) const;
  // Fixed line k (0-based); a missing optional line yields defaults.
  double real(std::size_t line, std::string_view field) const;
  std::int64_t integer(std::size_t line, std::string_view field) const;
};

struct Units {
  std::string mass = "kg", length = "mm", time = "ms";  // work units from /BEGIN
};

// Factor of a Radioss unit name (an SI prefix and `base`: 'g', 'm' or 's') to its base unit:
// unit_factor("ms", 's') = 1e-3, unit_factor("kg", 'g') = 1e3; none if the name is not one.
std::optional<double> unit_factor(std::string_view name, char base);

struct Deck {
  Section section = Section::Starter;
  std::vector<std::filesystem::path> files;  // files[0] is the main deck
  std::vector<SourceLoc> included_from;      // per file: where it was #included (file 0: none)
  std::vector<std::string> texts;            // storage for Text field values
  std::string run_name;                      // from /BEGIN (starter) or /RUN (engine)
  int invers = 2024;
  Units input_units, work_units;
  std::vector<Card> cards;

  std::string_view text(const Value& v) const { return texts[v.text]; }
  std::string text(const Card& c, const Row& line, std::string_view field) const;
  // Cards of one keyword (without id, e.g. "/MAT/LAW1"), in deck order.
  std::vector<const Card*> cards_of(std::string_view keyword) const;
  // "file:line" for a location, used in every message.
  std::string where(SourceLoc loc) const;
};

}  // namespace hbm::deck
