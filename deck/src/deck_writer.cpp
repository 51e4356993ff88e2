// SPDX-License-Identifier: GPL-3.0-or-later
// Canonical output of cards: starter cards in fixed columns (numbers right-aligned in
// their field, reals in the shortest text that reads back exactly), engine cards in free
// format. write_deck_file writes to a temporary name and renames it when complete.
#include "hbm/deck/io.hpp"

#include "field_checks.hpp"
#include "text_fields.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <ostream>
#include <random>
#include <stdexcept>
#include <system_error>

namespace hbm::deck {

namespace {

[[noreturn]] void unwritable(const Card& c, const FieldSpec& f, const std::string& why) {
  throw std::invalid_argument("write_card: " + detail::card_label(c) + " field " + std::string(f.name) + ": " + why);
}

std::string field_text(const Card& c, const FieldSpec& f, const Value& v, const Deck& deck) {
  switch (f.type) {
    case FieldType::Int: {
      char buf[24];
      auto r = std::to_chars(buf, buf + sizeof buf, v.integer);
      return std::string(buf, static_cast<std::size_t>(r.ptr - buf));
    }
    case FieldType::Real:
      if (!std::isfinite(v.real)) unwritable(c, f, "value is not finite");
      return text::format_real(v.real, f.width);
    case FieldType::Text:
      return v.text < deck.texts.size() ? deck.texts[v.text] : std::string();
  }
  return {};
}

// One fixed-format line; trailing blanks trimmed.
void write_fixed_line(std::ostream& os, const Card& c, const Row& r, const Deck& deck) {
  std::string line(100, ' ');
  std::size_t used = 0;
  for (std::size_t i = 0; i < r.layout->fields.size(); ++i) {
    const FieldSpec& f = r.layout->fields[i];
    const Value& v = c.values[r.first + i];
    if (v.blank) continue;
    std::string t = field_text(c, f, v, deck);
    if (static_cast<int>(t.size()) > f.width)
      unwritable(c, f, "'" + t + "' does not fit in " + std::to_string(f.width) + " columns");
    if (t.find_first_of("\n\r\t") != std::string::npos) unwritable(c, f, "text contains a line break or tab");
    const std::size_t w = static_cast<std::size_t>(f.width);
    const std::size_t col = static_cast<std::size_t>(f.column);
    // Long text (names) left-aligned, everything else right-aligned.
    const std::size_t start = (f.type == FieldType::Text && w >= 40) ? col : col + w - t.size();
    line.replace(start, t.size(), t);
    used = std::max(used, start + t.size());
  }
  line.resize(used);
  if (!line.empty() && (line[0] == '/' || line[0] == '#'))
    throw std::invalid_argument("write_card: " + detail::card_label(c) + " data line would start with '" +
                                line.substr(0, 1) + "' and read back as a keyword or comment");
  os << line << '\n';
}

void write_free_line(std::ostream& os, const Card& c, const Row& r, const Deck& deck) {
  // Values up to the last non-blank one; blanks before it are written as their defaults.
  std::size_t last = 0;
  for (std::size_t i = 0; i < r.layout->fields.size(); ++i)
    if (!c.values[r.first + i].blank) last = i + 1;
  for (std::size_t i = 0; i < last; ++i) {
    const FieldSpec& f = r.layout->fields[i];
    if (i) os << ' ';
    if (f.type == FieldType::Real) {
      os << text::format_number(c.values[r.first + i].real);
    } else {
      os << field_text(c, f, c.values[r.first + i], deck);
    }
  }
  os << '\n';
}

bool all_blank(const Card& c, const Row& r) {
  for (std::size_t i = 0; i < r.layout->fields.size(); ++i)
    if (!c.values[r.first + i].blank) return false;
  return true;
}

}  // namespace

void write_card(std::ostream& os, const Card& card, const Deck& deck) {
  if (!card.spec) throw std::invalid_argument("write_card: card without keyword");
  os << detail::card_label(card) << '\n';
  if (card.spec->has_title) {
    if (card.title.size() > 100 || card.title.find_first_of("\n\r") != std::string::npos ||
        (!card.title.empty() && (card.title[0] == '/' || card.title[0] == '#')))
      throw std::invalid_argument("write_card: " + detail::card_label(card) +
                                  " title longer than 100 columns, with a line break, or starting with / or #");
    os << card.title << '\n';
  }
  const bool starter = card.spec->section == Section::Starter;
  // Trailing optional fixed lines that are all blank are left out.
  std::size_t n_fixed = card.n_fixed_lines();
  while (n_fixed > 0 && card.spec->lines[n_fixed - 1].optional && all_blank(card, card.lines[n_fixed - 1])) --n_fixed;
  for (std::size_t k = 0; k < card.lines.size(); ++k) {
    if (k >= n_fixed && k < card.n_fixed_lines()) continue;
    const Row& r = card.lines[k];
    if (k >= card.n_fixed_lines() && all_blank(card, r)) continue;  // empty rows carry nothing
    if (starter) write_fixed_line(os, card, r, deck);
    else write_free_line(os, card, r, deck);
  }
}

void write_deck(std::ostream& os, const Deck& deck) {
  os << (deck.section == Section::Starter ? "#RADIOSS STARTER\n" : "#RADIOSS ENGINE\n");
  for (const Card& c : deck.cards) write_card(os, c, deck);
}

void write_deck_file(const std::filesystem::path& path, const Deck& deck) {
  std::random_device rd;
  const std::filesystem::path tmp = path.string() + ".tmp" + std::to_string(rd() % 1000000u);
  try {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) throw std::runtime_error("cannot create " + tmp.string());
      write_deck(out, deck);
      out.flush();
      if (!out) throw std::runtime_error("cannot write " + tmp.string());
    }
    std::filesystem::rename(tmp, path);
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw;
  }
}

}  // namespace hbm::deck
