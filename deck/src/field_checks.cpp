// SPDX-License-Identifier: GPL-3.0-or-later
// Field ranges and message prefixes (see field_checks.hpp).
#include "field_checks.hpp"

#include "text_fields.hpp"

#include <cmath>

namespace hbm::deck::detail {

std::string card_label(const Card& card) {
  std::string s(card.keyword());
  if (!card.spec) return s;
  if (card.spec->keyword == "/RUN") {
    s += '/';
    s += card.title;
    s += '/';
    s += std::to_string(card.id);
    return s;
  }
  if (card.spec->id != IdKind::None && (card.id != 0 || card.spec->id != IdKind::Optional)) {
    s += '/';
    s += std::to_string(card.id);
  }
  return s;
}

std::string value_text(const FieldSpec& f, const Value& v, const Deck& deck) {
  if (f.type == FieldType::Text) {
    if (v.blank) return "blank";
    std::string q(1, '\'');
    q.append(deck.text(v)).push_back('\'');
    return q;
  }
  std::string n = f.type == FieldType::Int ? std::to_string(v.integer) : text::format_number(v.real);
  if (v.blank) return "blank (default " + n + ")";
  return n;
}

std::optional<std::string> range_problem(const FieldSpec& f, const Value& v) {
  if (f.type == FieldType::Text) return std::nullopt;
  const double x = f.type == FieldType::Int ? static_cast<double>(v.integer) : v.real;
  // An optional reference may be 0 (none) whatever its minimum.
  if (f.type == FieldType::Int && f.ref != RefKind::None && f.ref_optional && v.integer == 0)
    return std::nullopt;
  const bool lo_ok = f.min_exclusive ? x > f.min : x >= f.min;
  const bool hi_ok = f.max_exclusive ? x < f.max : x <= f.max;
  if (lo_ok && hi_ok) return std::nullopt;
  const bool has_lo = std::isfinite(f.min), has_hi = std::isfinite(f.max);
  if (f.dim == Dimension::Id && f.min >= 1 && x == 0) return std::string("required (must be >= 1)");
  if (has_lo && has_hi) {
    if (f.min == f.max) return "must be " + text::format_number(f.min);
    return std::string("must be in ") + (f.min_exclusive ? "(" : "[") + text::format_number(f.min) +
           ", " + text::format_number(f.max) + (f.max_exclusive ? ")" : "]");
  }
  if (has_lo) return std::string("must be ") + (f.min_exclusive ? "> " : ">= ") + text::format_number(f.min);
  return std::string("must be ") + (f.max_exclusive ? "< " : "<= ") + text::format_number(f.max);
}

std::string field_prefix(const Card& card, const FieldSpec& f, const Value& v, const Deck& deck) {
  return card_label(card) + " field " + std::string(f.name) + " = " + value_text(f, v, deck) + ": ";
}

void DiagSink::error(SourceLoc loc, int col, std::string msg) {
  if (full_) return;
  if (errors_ >= kMaxErrors) {
    out_.push_back(Diagnostic{Severity::Error, loc, col, "too many errors; stopped after " +
                                                             std::to_string(kMaxErrors)});
    full_ = true;
    return;
  }
  ++errors_;
  out_.push_back(Diagnostic{Severity::Error, loc, col, std::move(msg)});
}

void DiagSink::warning(SourceLoc loc, int col, std::string msg) {
  if (full_ || warnings_ >= kMaxErrors) return;  // warnings are bounded too
  ++warnings_;
  out_.push_back(Diagnostic{Severity::Warning, loc, col, std::move(msg)});
}

}  // namespace hbm::deck::detail
