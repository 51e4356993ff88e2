// SPDX-License-Identifier: GPL-3.0-or-later
// The table of all supported keywords (assembled once from the per-area tables), lookup
// by keyword, nearest-keyword suggestion (Levenshtein distance) and dimension names.
#include "field_builders.hpp"

#include <algorithm>
#include <cctype>
#include <unordered_map>
#include <string>

namespace hbm::deck {

namespace {

struct Index {
  std::vector<KeywordSpec> table;
  std::unordered_map<std::string_view, const KeywordSpec*> by_name;
  Index() {
    tables::add_starter_geometry(table);
    tables::add_starter_model(table);
    tables::add_starter_loads(table);
    tables::add_starter_contact(table);
    tables::add_engine(table);
    for (const KeywordSpec& k : table) by_name.emplace(k.keyword, &k);
  }
};

const Index& index() {
  static const Index idx;
  return idx;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::toupper(static_cast<unsigned char>(a[i - 1])) ==
                        std::toupper(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

}  // namespace

const std::vector<KeywordSpec>& keyword_table() { return index().table; }

const KeywordSpec* find_keyword_any(std::string_view keyword) {
  const auto& m = index().by_name;
  auto it = m.find(keyword);
  return it == m.end() ? nullptr : it->second;
}

const KeywordSpec* find_keyword(std::string_view keyword, Section section) {
  const KeywordSpec* k = find_keyword_any(keyword);
  return (k && k->section == section) ? k : nullptr;
}

std::string_view nearest_keyword(std::string_view keyword, Section section) {
  std::string_view best;
  std::size_t best_d = static_cast<std::size_t>(-1);
  for (const KeywordSpec& k : keyword_table()) {
    if (k.section != section) continue;
    const std::size_t d = edit_distance(keyword, k.keyword);
    if (d < best_d) {
      best_d = d;
      best = k.keyword;
    }
  }
  return best;
}

int field_index(const LineSpec& line, std::string_view field) {
  for (std::size_t i = 0; i < line.fields.size(); ++i) {
    const std::string_view n = line.fields[i].name;
    if (n.size() != field.size()) continue;
    bool eq = true;
    for (std::size_t c = 0; c < n.size() && eq; ++c)
      eq = std::tolower(static_cast<unsigned char>(n[c])) ==
           std::tolower(static_cast<unsigned char>(field[c]));
    if (eq) return static_cast<int>(i);
  }
  return -1;
}

std::string_view to_string(Dimension d) {
  switch (d) {
    case Dimension::None: return "-";
    case Dimension::Id: return "id";
    case Dimension::Count: return "count";
    case Dimension::Flag: return "flag";
    case Dimension::Length: return "length";
    case Dimension::Area: return "area";
    case Dimension::Time: return "time";
    case Dimension::Mass: return "mass";
    case Dimension::Density: return "mass/length^3";
    case Dimension::Velocity: return "length/time";
    case Dimension::Acceleration: return "length/time^2";
    case Dimension::Force: return "force";
    case Dimension::Moment: return "force*length";
    case Dimension::Stress: return "force/length^2";
    case Dimension::Stiffness: return "force/length";
    case Dimension::RotStiffness: return "force*length/rad";
    case Dimension::Damping: return "force*time/length";
    case Dimension::RotDamping: return "force*length*time/rad";
    case Dimension::Energy: return "energy";
    case Dimension::Inertia: return "mass*length^2";
    case Dimension::Momentum: return "mass*length/time";
    case Dimension::Angle: return "degree";
    case Dimension::Frequency: return "1/time";
    case Dimension::Strain: return "strain";
    case Dimension::StrainRate: return "1/time";
    case Dimension::Temperature: return "temperature";
  }
  return "?";
}

}  // namespace hbm::deck
