// SPDX-License-Identifier: GPL-3.0-or-later
// Per-field validation shared by the reader (which knows the exact column) and
// check_deck() (decks built in memory): the valid range of a FieldSpec, and the
// "/MAT/LAW1/17 field E = -1" prefix of messages.
#pragma once

#include "hbm/deck/deck.hpp"
#include "hbm/deck/io.hpp"

#include <optional>
#include <string>

namespace hbm::deck::detail {

// "/MAT/LAW1/17", "/NODE", "/RUN/name/1".
std::string card_label(const Card& card);
// Text of a value for messages: number, quoted text, or "blank (default 0)".
std::string value_text(const FieldSpec& f, const Value& v, const Deck& deck);
// "must be > 0", "must be in (-1, 0.5)"... or nothing when the value is valid.
std::optional<std::string> range_problem(const FieldSpec& f, const Value& v);
// "/MAT/LAW1/17 field E = -1: " (the caller appends the problem).
std::string field_prefix(const Card& card, const FieldSpec& f, const Value& v, const Deck& deck);

// Bounded diagnostic list: stops collecting after a limit so that a garbage deck of a
// million lines cannot produce a million messages.
class DiagSink {
 public:
  explicit DiagSink(std::vector<Diagnostic>& out) : out_(out) {}
  void error(SourceLoc loc, int col, std::string msg);
  void warning(SourceLoc loc, int col, std::string msg);
  bool full() const { return full_; }
  std::size_t errors() const { return errors_; }

 private:
  std::vector<Diagnostic>& out_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
  bool full_ = false;
};

inline constexpr std::size_t kMaxErrors = 1000;

// All checks that need the whole deck (ids, references, counts, shapes, functions,
// cross-field rules). `with_ranges` adds the per-field range checks (the reader does
// them itself while parsing).
void check_model(const Deck& deck, DiagSink& sink, bool with_ranges);

}  // namespace hbm::deck::detail
