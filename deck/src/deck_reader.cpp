// SPDX-License-Identifier: GPL-3.0-or-later
// The deck reader: turns source lines into cards laid out by the keyword tables.
// Starter decks are fixed format (fields at their columns, 100 significant columns);
// engine decks are free format. Every problem becomes a Diagnostic and reading goes on,
// so that one run reports all errors; the model checks run afterwards.
#include "hbm/deck/io.hpp"

#include "field_checks.hpp"
#include "source_lines.hpp"
#include "text_fields.hpp"

#include <algorithm>
#include <cctype>

namespace hbm::deck {

namespace {

using detail::DiagSink;
using detail::SourceLine;
using text::NumberStatus;

constexpr std::size_t kColumns = 100;

bool is_blank(std::string_view s) {
  for (char c : s)
    if (c != ' ' && c != '\t' && c != '\r') return false;
  return true;
}

Value default_value(const FieldSpec& f) {
  Value v;
  v.blank = true;
  v.real = f.default_value;
  v.integer = static_cast<std::int64_t>(f.default_value);
  return v;
}

class Parser {
 public:
  Parser(Deck& deck, DiagSink& sink) : deck_(deck), sink_(sink) {}

  void run(const std::vector<SourceLine>& lines) {
    // Data lines following each keyword line, to size the card's arrays once.
    following_.assign(lines.size(), 0);
    std::uint32_t run_length = 0;
    for (std::size_t i = lines.size(); i-- > 0;) {
      following_[i] = run_length;
      const std::string_view t = lines[i].text;
      run_length = (!t.empty() && t[0] == '/') ? 0 : run_length + 1;
    }
    for (std::size_t li = 0; li < lines.size(); ++li) {
      const SourceLine& l = lines[li];
      line_index_ = li;
      if (sink_.full()) return;
      if (after_end_) {
        if (!is_blank(l.text) && !warned_after_end_) {
          sink_.warning(l.loc, 1, "content after /END is ignored");
          warned_after_end_ = true;
        }
        continue;
      }
      if (!l.text.empty() && l.text[0] == '/') {
        finish_card();
        keyword_line(l);
      } else {
        data_line(l);
      }
    }
    finish_card();
  }

 private:
  Deck& deck_;
  DiagSink& sink_;
  bool starter() const { return deck_.section == Section::Starter; }

  std::vector<std::uint32_t> following_;  // per keyword line: data lines until the next keyword

  // Default values of a row layout, built once per layout (rows are copied from it).
  std::vector<std::pair<const LineSpec*, std::vector<Value>>> defaults_cache_;
  const std::vector<Value>& defaults_of(const LineSpec& ls) {
    for (const auto& [spec, values] : defaults_cache_)
      if (spec == &ls) return values;
    std::vector<Value> v;
    for (const FieldSpec& f : ls.fields) v.push_back(default_value(f));
    return defaults_cache_.emplace_back(&ls, std::move(v)).second;
  }
  std::size_t line_index_ = 0;

  // Current card state.
  Card* cur_ = nullptr;
  bool skipping_ = false;        // data lines of an unsupported keyword
  bool title_pending_ = false;
  std::size_t fixed_read_ = 0;   // fixed lines read so far
  bool rows_started_ = false;
  bool warned_extra_ = false;
  bool after_end_ = false;
  bool warned_after_end_ = false;
  bool warned_orphan_ = false;

  // Diagnostics for characters past column 100, tabs and control characters; returns
  // the part of the line to parse.
  std::string_view check_line_chars(const SourceLine& l, bool allow_tabs) {
    std::string_view t = l.text;
    for (std::size_t i = 0; i < t.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(t[i]);
      if (c == '\t' && !allow_tabs && starter()) {
        sink_.error(l.loc, static_cast<int>(i + 1),
                    "tab character in a fixed-format line (fields are counted in columns; use spaces)");
        return {};
      }
      if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
        sink_.error(l.loc, static_cast<int>(i + 1), "control character (byte " + std::to_string(c) + ") in deck line");
        return {};
      }
    }
    if (starter() && t.size() > kColumns) {
      std::string_view rest = t.substr(kColumns);
      if (!is_blank(rest)) {
        const std::size_t off = rest.find_first_not_of(" \t\r");
        sink_.error(l.loc, static_cast<int>(kColumns + off + 1),
                    "content past column 100 (the starter reads 100 columns)");
      }
      t = t.substr(0, kColumns);
    }
    return t;
  }

  void keyword_line(const SourceLine& l) {
    skipping_ = true;  // until the keyword is known to be good
    cur_ = nullptr;
    std::string_view t = check_line_chars(l, true);
    t = text::trim(t);
    if (t.empty()) return;
    // Split "/A/B/12" into components.
    std::vector<std::string_view> comps;
    std::size_t pos = 1;
    while (pos <= t.size()) {
      std::size_t slash = t.find('/', pos);
      if (slash == std::string_view::npos) slash = t.size();
      comps.push_back(t.substr(pos, slash - pos));
      pos = slash + 1;
    }
    for (std::size_t i = 0; i < comps.size(); ++i) {
      if (comps[i].empty() || comps[i].find_first_of(" \t") != std::string_view::npos) {
        sink_.error(l.loc, 1, "malformed keyword line '" + std::string(t) + "'");
        return;
      }
    }
    auto join = [&](std::size_t n) {
      std::string s;
      for (std::size_t i = 0; i < n; ++i) {
        s += '/';
        s += comps[i];
      }
      return s;
    };
    auto is_int = [](std::string_view s) {
      std::int64_t v;
      return text::parse_int(s, v) == NumberStatus::Ok;
    };
    const KeywordSpec* spec = nullptr;
    std::size_t n_kw = comps.size();
    std::string name;
    std::int64_t id = 0;
    bool has_id = false;
    std::string run_title;

    if (comps[0] == "RUN" && !starter()) {
      spec = find_keyword("/RUN", Section::Engine);
      if (comps.size() != 3 || !is_int(comps[2])) {
        sink_.error(l.loc, 1, "/RUN must read /RUN/run_name/restart_number, e.g. /RUN/pendulum/1");
        return;
      }
      run_title = std::string(comps[1]);
      text::parse_int(comps[2], id);
      has_id = true;
    } else {
      for (std::size_t strip = 0; strip <= 2 && strip < comps.size(); ++strip) {
        n_kw = comps.size() - strip;
        bool ids_ok = true;
        for (std::size_t i = n_kw; i < comps.size(); ++i) ids_ok = ids_ok && is_int(comps[i]);
        if (!ids_ok) break;
        name = join(n_kw);
        spec = find_keyword_any(name);
        if (spec) {
          if (strip == 2) {
            sink_.error(l.loc, 1, "unit_ID in '" + std::string(t) +
                                      "' is not supported: all values are in the units of /BEGIN");
            return;
          }
          if (strip == 1) {
            text::parse_int(comps.back(), id);
            has_id = true;
          }
          break;
        }
      }
      if (!spec) {
        std::string kw = join(comps.size());
        if (comps.size() > 1 && is_int(comps.back())) kw = join(comps.size() - 1);
        const Section sec = deck_.section;
        sink_.error(l.loc, 1, "keyword " + kw + " is not supported; nearest supported keyword: " +
                                  std::string(nearest_keyword(kw, sec)));
        return;
      }
    }
    if (spec->section != deck_.section) {
      sink_.error(l.loc, 1, "keyword " + std::string(spec->keyword) + " belongs to the " +
                                (spec->section == Section::Starter ? "starter deck (NAME_0000.rad)"
                                                                   : "engine deck (NAME_0001.rad)") +
                                ", not this one");
      return;
    }
    switch (spec->id) {
      case IdKind::None:
        if (has_id) {
          sink_.error(l.loc, 1, std::string(spec->keyword) + " takes no id");
          return;
        }
        break;
      case IdKind::Object:
      case IdKind::Part:
        if (!has_id) {
          sink_.error(l.loc, 1, std::string(spec->keyword) + " needs an id: " + std::string(spec->keyword) +
                                    (spec->id == IdKind::Part ? "/part_id" : "/id"));
          return;
        }
        if (id < 1) {
          sink_.error(l.loc, 1, std::string(spec->keyword) + " id " + std::to_string(id) + " must be >= 1");
          return;
        }
        break;
      case IdKind::Optional:
        break;
    }
    if (spec->keyword == "/BEGIN") {
      if (!deck_.cards.empty()) sink_.error(l.loc, 1, "/BEGIN must be the first card of the starter deck");
    }
    // Open the card.
    Card& c = deck_.cards.emplace_back();
    if (spec->rows) {
      const std::size_t n = following_[line_index_];
      c.lines.reserve(spec->lines.size() + n);
      c.values.reserve(n * spec->rows->fields.size() + 64);
    }
    c.spec = spec;
    c.id = id;
    c.loc = l.loc;
    c.title = std::move(run_title);
    for (const LineSpec& ls : spec->lines) {
      Row r;
      r.layout = &ls;
      r.first = static_cast<std::uint32_t>(c.values.size());
      c.lines.push_back(r);
      for (const FieldSpec& f : ls.fields) c.values.push_back(default_value(f));
    }
    cur_ = &c;
    skipping_ = false;
    title_pending_ = spec->has_title;
    fixed_read_ = 0;
    rows_started_ = false;
    warned_extra_ = false;
    if (spec->keyword == "/END") after_end_ = true;
  }

  void finish_card() {
    if (!cur_) return;
    Card& c = *cur_;
    const std::string label = detail::card_label(c);
    if (title_pending_) {
      sink_.error(c.loc, 1, label + ": missing title line (one line of text after the keyword)");
    } else {
      for (std::size_t k = fixed_read_; k < c.spec->lines.size(); ++k) {
        const LineSpec& ls = c.spec->lines[k];
        if (!ls.optional) {
          sink_.error(c.loc, 1, label + ": missing data line " + std::to_string(k + 1) + " (" +
                                    std::string(ls.name) + ")");
          break;
        }
      }
    }
    if (c.spec->keyword == "/BEGIN") {
      deck_.run_name = c.title;
      deck_.invers = static_cast<int>(c.integer(0, "Invers"));
      auto unit = [&](std::size_t line, std::string_view f, std::string& dst) {
        const Row& r = c.lines[line];
        const Value& v = c.value(r, f);
        if (!v.blank) dst = std::string(deck_.text(v));
      };
      unit(1, "mass", deck_.input_units.mass);
      unit(1, "length", deck_.input_units.length);
      unit(1, "time", deck_.input_units.time);
      deck_.work_units = deck_.input_units;
      unit(2, "mass", deck_.work_units.mass);
      unit(2, "length", deck_.work_units.length);
      unit(2, "time", deck_.work_units.time);
    }
    if (c.spec->keyword == "/RUN") deck_.run_name = c.title;
    cur_ = nullptr;
  }

  void data_line(const SourceLine& l) {
    if (skipping_) return;
    if (!cur_) {
      if (!is_blank(l.text) && !warned_orphan_) {
        sink_.error(l.loc, 1, "data line before the first keyword");
        warned_orphan_ = true;
      }
      return;
    }
    Card& c = *cur_;
    const KeywordSpec& spec = *c.spec;
    if (title_pending_) {
      std::string_view t = check_line_chars(l, true);
      std::size_t e = t.size();
      while (e > 0 && (t[e - 1] == ' ' || t[e - 1] == '\t')) --e;
      c.title.assign(t.data(), e);
      title_pending_ = false;
      return;
    }
    const bool blank = is_blank(l.text);
    if (!starter() && blank) return;  // free format: blank lines carry nothing
    if (fixed_read_ < spec.lines.size() && !rows_started_) {
      Row& r = c.lines[fixed_read_];
      r.loc = l.loc;
      ++fixed_read_;
      if (!blank) {
        const std::size_t before = sink_.errors();
        parse_into(c, r, l);
        r.has_error = sink_.errors() != before;
      }
      return;
    }
    if (blank) return;
    if (spec.name_rows && !rows_started_) {
      const std::size_t p = l.text.find_first_not_of(' ');
      if (p != std::string_view::npos && std::isalpha(static_cast<unsigned char>(l.text[p]))) {
        append_row(c, *spec.name_rows, l);
        return;
      }
    }
    if (spec.rows) {
      rows_started_ = true;
      append_row(c, *spec.rows, l);
      return;
    }
    if (!warned_extra_) {
      sink_.error(l.loc, 1, detail::card_label(c) + ": unexpected data line (the card has " +
                                std::to_string(spec.lines.size()) + " data line(s)" +
                                (spec.has_title ? " after its title" : "") + ")");
      warned_extra_ = true;
    }
  }

  void append_row(Card& c, const LineSpec& ls, const SourceLine& l) {
    Row r;
    r.layout = &ls;
    r.loc = l.loc;
    r.first = static_cast<std::uint32_t>(c.values.size());
    const std::vector<Value>& defaults = defaults_of(ls);
    c.values.insert(c.values.end(), defaults.begin(), defaults.end());
    c.lines.push_back(r);
    const std::size_t before = sink_.errors();
    parse_into(c, c.lines.back(), l);
    c.lines.back().has_error = sink_.errors() != before;
  }

  void field_error(const Card& c, const FieldSpec& f, SourceLoc loc, int col, std::string_view raw,
                   std::string_view problem) {
    sink_.error(loc, col, detail::card_label(c) + " field " + std::string(f.name) + " = '" +
                              std::string(raw.substr(0, 40)) + "': " + std::string(problem));
  }

  // Parses one field's text into v; reports bad text and out-of-range values.
  void parse_field(const Card& c, const FieldSpec& f, Value& v, std::string_view raw, SourceLoc loc, int col) {
    switch (f.type) {
      case FieldType::Int: {
        std::int64_t x = 0;
        const NumberStatus st = text::parse_int(raw, x);
        if (st != NumberStatus::Ok) {
          field_error(c, f, loc, col, raw, st == NumberStatus::NotNumber ? "integer expected, found text"
                                                                        : text::describe(st));
          return;
        }
        v.integer = x;
        v.real = static_cast<double>(x);
        v.blank = false;
        break;
      }
      case FieldType::Real: {
        double x = 0;
        const NumberStatus st = text::parse_real(raw, x);
        if (st != NumberStatus::Ok) {
          field_error(c, f, loc, col, raw, st == NumberStatus::NotNumber ? "number expected, found text"
                                                                        : text::describe(st));
          return;
        }
        v.real = x;
        v.integer = 0;
        v.blank = false;
        break;
      }
      case FieldType::Text:
        v.text = static_cast<std::uint32_t>(deck_.texts.size());
        deck_.texts.emplace_back(raw);
        v.blank = false;
        return;
    }
    if (f.zero_is_default && v.real == 0.0) {
      v = default_value(f);  // OpenRadioss reads 0 as the default, as it reads a blank
      return;
    }
    if (v.real == f.replace_value) {
      sink_.warning(loc, col, detail::field_prefix(c, f, v, deck_) + "read as " + text::format_number(f.replaced_by) +
                                  " (as OpenRadioss reads it)");
      v.real = f.replaced_by;
    }
    if (auto p = detail::range_problem(f, v))
      sink_.error(loc, col, detail::field_prefix(c, f, v, deck_) + *p);
  }

  void parse_into(Card& c, Row& r, const SourceLine& l) {
    const LineSpec& ls = *r.layout;
    if (starter()) {
      const bool allow_tabs = false;
      std::string_view t = check_line_chars(l, allow_tabs);
      if (t.empty()) return;
      std::size_t covered = 0;  // columns [0, covered) checked for stray content
      for (std::size_t i = 0; i < ls.fields.size(); ++i) {
        const FieldSpec& f = ls.fields[i];
        const std::size_t col = static_cast<std::size_t>(f.column);
        if (col > covered) stray(c, l, t, covered, col);
        covered = std::max(covered, col + static_cast<std::size_t>(f.width));
        if (col >= t.size()) continue;
        std::string_view raw = t.substr(col, static_cast<std::size_t>(f.width));
        const std::size_t b = raw.find_first_not_of(' ');
        if (b == std::string_view::npos) continue;
        const std::size_t e = raw.find_last_not_of(' ');
        Value& v = c.values[r.first + i];
        parse_field(c, f, v, raw.substr(b, e - b + 1), l.loc, static_cast<int>(col + b + 1));
      }
      if (covered < t.size()) stray(c, l, t, covered, kColumns);
    } else {
      std::string_view t = check_line_chars(l, true);
      std::size_t pos = 0, i = 0;
      while (true) {
        while (pos < t.size() && (t[pos] == ' ' || t[pos] == '\t' || t[pos] == ',')) ++pos;
        if (pos >= t.size()) break;
        std::size_t e = pos;
        while (e < t.size() && t[e] != ' ' && t[e] != '\t' && t[e] != ',') ++e;
        if (i >= ls.fields.size()) {
          sink_.error(l.loc, static_cast<int>(pos + 1),
                      detail::card_label(c) + ": too many values on the line (expected " +
                          std::to_string(ls.fields.size()) + ")");
          return;
        }
        parse_field(c, ls.fields[i], c.values[r.first + i], t.substr(pos, e - pos), l.loc,
                    static_cast<int>(pos + 1));
        ++i;
        pos = e;
      }
    }
  }

  void stray(const Card& c, const SourceLine& l, std::string_view t, std::size_t from, std::size_t gap_end) {
    const std::size_t to = std::min(gap_end, t.size());
    for (std::size_t k = from; k < to; ++k) {
      if (t[k] != ' ') {
        sink_.error(l.loc, static_cast<int>(k + 1),
                    detail::card_label(c) + ": text in column " + std::to_string(k + 1) +
                        ", where this card has no field (columns " + std::to_string(from + 1) + "-" +
                        std::to_string(gap_end) + " are unused)");
        return;
      }
    }
  }
};

}  // namespace

bool ReadResult::ok() const {
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::Error) return false;
  return true;
}

namespace {

ReadResult read_impl(std::string_view text, std::filesystem::path name, Section section) {
  ReadResult r;
  r.deck.section = section;
  r.deck.files.push_back(std::move(name));
  r.deck.included_from.push_back(SourceLoc{});
  detail::Sources src;
  detail::load_sources(text, r.deck, src, r.diagnostics);
  DiagSink sink(r.diagnostics);
  Parser p(r.deck, sink);
  p.run(src.lines);
  if (!sink.full()) {
    detail::check_model(r.deck, sink, false);
  }
  std::stable_sort(r.diagnostics.begin(), r.diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
    if (a.loc.file != b.loc.file) return a.loc.file < b.loc.file;
    if (a.loc.line != b.loc.line) return a.loc.line < b.loc.line;
    return a.column < b.column;
  });
  return r;
}

}  // namespace

ReadResult read_deck_text(std::string_view text, std::string name, Section section) {
  return read_impl(text, std::filesystem::path(std::move(name)), section);
}

ReadResult read_deck(const std::filesystem::path& path, Section section) {
  std::string buf;
  if (!detail::read_file(path, buf)) {
    ReadResult r;
    r.deck.section = section;
    r.deck.files.push_back(path);
    r.deck.included_from.push_back(SourceLoc{});
    r.diagnostics.push_back(Diagnostic{Severity::Error, SourceLoc{0, 0}, 0, "cannot read deck file"});
    return r;
  }
  return read_impl(buf, path, section);
}

}  // namespace hbm::deck
