// SPDX-License-Identifier: GPL-3.0-or-later
// Formatting of diagnostics: "file:line:col: error: message", then one
// "  included from file:line" line per level of #include.
#include "hbm/deck/io.hpp"

#include <ostream>

namespace hbm::deck {

std::string format(const Diagnostic& d, const Deck& deck) {
  std::string s = deck.where(d.loc);
  if (d.loc.line != 0) s.append(":").append(std::to_string(d.column > 0 ? d.column : 1));
  s += d.severity == Severity::Error ? ": error: " : ": warning: ";
  s += d.message;
  std::uint32_t f = d.loc.file;
  for (int guard = 0; guard < 64 && f != 0 && f < deck.included_from.size(); ++guard) {
    const SourceLoc from = deck.included_from[f];
    s += "\n  included from " + deck.where(from);
    f = from.file;
  }
  return s;
}

void print_diagnostics(std::ostream& os, const ReadResult& r) {
  std::size_t errors = 0, warnings = 0;
  for (const Diagnostic& d : r.diagnostics) {
    os << format(d, r.deck) << '\n';
    (d.severity == Severity::Error ? errors : warnings)++;
  }
  if (errors || warnings) {
    os << (r.deck.files.empty() ? std::string("deck") : r.deck.files[0].string()) << ": " << errors
       << (errors == 1 ? " error, " : " errors, ") << warnings << (warnings == 1 ? " warning" : " warnings") << '\n';
  }
}

}  // namespace hbm::deck
