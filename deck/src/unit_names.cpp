// SPDX-License-Identifier: GPL-3.0-or-later
// Radioss unit names of /BEGIN: an SI prefix and the base letter (g, m, s).
#include "hbm/deck/deck.hpp"

#include <array>
#include <utility>

namespace hbm::deck {

std::optional<double> unit_factor(std::string_view name, char base) {
  if (name.empty() || name.back() != base) return std::nullopt;
  const std::string_view prefix = name.substr(0, name.size() - 1);
  static constexpr std::array<std::pair<std::string_view, double>, 21> kPrefixes{{
      {"", 1.0},     {"y", 1e-24}, {"z", 1e-21}, {"a", 1e-18}, {"f", 1e-15}, {"p", 1e-12}, {"n", 1e-9},
      {"mu", 1e-6},  {"m", 1e-3},  {"c", 1e-2},  {"d", 1e-1},  {"da", 1e1},  {"h", 1e2},   {"k", 1e3},
      {"M", 1e6},    {"G", 1e9},   {"T", 1e12},  {"P", 1e15},  {"E", 1e18},  {"Z", 1e21},  {"Y", 1e24},
  }};
  for (const auto& [p, f] : kPrefixes)
    if (prefix == p) return f;
  return std::nullopt;
}

}  // namespace hbm::deck
