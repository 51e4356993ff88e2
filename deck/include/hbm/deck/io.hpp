// SPDX-License-Identifier: GPL-3.0-or-later
// Reading, checking and writing decks. Every problem found is a Diagnostic; the reader
// collects them all before it reports, and a deck with any error is rejected whole.
#pragma once

#include "hbm/deck/deck.hpp"

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace hbm::deck {

enum class Severity : std::uint8_t { Error, Warning };

// A message pointing into the deck, formatted as
//   file:line:col: error: /MAT/LAW1/17 field E = -1: must be > 0
//     included from main_0000.rad:12
struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLoc loc;
  int column = 0;  // 1-based, 0 if unknown
  std::string message;
};

struct ReadResult {
  Deck deck;
  std::vector<Diagnostic> diagnostics;
  bool ok() const;  // no Error diagnostics
};

// Lex and parse a deck (follows #include relative to the including file), then run the
// checks (ids, references, node counts, ranges, element shapes). Never throws on bad
// input: everything wrong is in `diagnostics`.
ReadResult read_deck(const std::filesystem::path& path, Section section);
// Same, from text already in memory (`name` is used in messages).
ReadResult read_deck_text(std::string_view text, std::string name, Section section);

// Checks a deck built in memory (CardBuilder): the same model checks as read_deck plus
// the field ranges; locations are those of the cards (none for generated cards).
std::vector<Diagnostic> check_deck(const Deck& deck);

// Format one diagnostic with its include chain; format all, one per line.
std::string format(const Diagnostic& d, const Deck& deck);
void print_diagnostics(std::ostream& os, const ReadResult& r);

// Canonical fixed-width output (starter) or free format (engine) of a card / a deck.
// Text written and read back gives the same cards.
void write_card(std::ostream& os, const Card& card, const Deck& deck);
void write_deck(std::ostream& os, const Deck& deck);
// Write to `path` via a temporary file renamed on success: the file is complete or absent.
void write_deck_file(const std::filesystem::path& path, const Deck& deck);

// Programmatic construction (deckgen, tests): a card with all fields blank (defaults),
// then set fields by name. Rows are appended with add_row().
class CardBuilder {
 public:
  CardBuilder(Deck& deck, std::string_view keyword, std::int64_t id = 0, std::string title = {});
  CardBuilder& set(std::size_t fixed_line, std::string_view field, double v);
  CardBuilder& set_int(std::size_t fixed_line, std::string_view field, std::int64_t v);
  CardBuilder& set_text(std::size_t fixed_line, std::string_view field, std::string_view v);
  std::size_t add_row();  // returns the row index
  // Name lines of /TH/* cards (var1..var10), added before any data row.
  std::size_t add_name_row();
  CardBuilder& name_row_set_text(std::size_t row, std::string_view field, std::string_view v);
  CardBuilder& row_set(std::size_t row, std::string_view field, double v);
  CardBuilder& row_set_int(std::size_t row, std::string_view field, std::int64_t v);
  CardBuilder& row_set_text(std::size_t row, std::string_view field, std::string_view v);
  Card& card();
  void commit();  // appends the card to the deck

 private:
  Deck& deck_;
  Card card_;
};

}  // namespace hbm::deck
