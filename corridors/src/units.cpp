// SPDX-License-Identifier: GPL-3.0-or-later
// Table of units known to hbm-corridors: name, dimension, factor to SI.
#include "hbm/corridors/units.hpp"

#include <array>
#include <stdexcept>

namespace hbm::corridors {
namespace {

struct UnitEntry {
  std::string_view name;
  std::string_view dimension;
  double to_si;
};

constexpr std::array<UnitEntry, 41> unit_table{{
    {"s", "time", 1.0},
    {"ms", "time", 1e-3},
    {"us", "time", 1e-6},
    {"m", "length", 1.0},
    {"cm", "length", 1e-2},
    {"mm", "length", 1e-3},
    {"in", "length", 0.0254},
    {"N", "force", 1.0},
    {"kN", "force", 1e3},
    {"daN", "force", 10.0},
    {"lbf", "force", 4.4482216152605},
    {"m/s", "velocity", 1.0},
    {"mm/ms", "velocity", 1.0},
    {"mm/s", "velocity", 1e-3},
    {"km/h", "velocity", 1.0 / 3.6},
    {"m/s2", "acceleration", 1.0},
    {"m/s^2", "acceleration", 1.0},
    {"mm/ms2", "acceleration", 1e3},
    {"mm/ms^2", "acceleration", 1e3},
    {"mm/s2", "acceleration", 1e-3},
    {"mm/s^2", "acceleration", 1e-3},
    {"g", "acceleration", standard_gravity},
    {"N*m", "moment", 1.0},
    {"Nm", "moment", 1.0},
    {"N m", "moment", 1.0},
    {"N*mm", "moment", 1e-3},
    {"kN*mm", "moment", 1.0},
    {"J", "energy", 1.0},
    {"kJ", "energy", 1e3},
    {"mJ", "energy", 1e-3},
    {"kg", "mass", 1.0},
    {"t", "mass", 1e3},
    {"Mg", "mass", 1e3},
    {"g_mass", "mass", 1e-3},
    {"rad", "angle", 1.0},
    {"deg", "angle", 3.14159265358979323846 / 180.0},
    {"-", "dimensionless", 1.0},
    {"1", "dimensionless", 1.0},
    {"%", "dimensionless", 1e-2},
    {"GPa", "stress", 1e9},
    {"MPa", "stress", 1e6},
}};

const UnitEntry& find_unit(std::string_view unit) {
  for (const auto& e : unit_table)
    if (e.name == unit) return e;
  std::string known;
  for (const auto& e : unit_table) {
    if (!known.empty()) known += ", ";
    known += e.name;
  }
  throw std::invalid_argument("unknown unit '" + std::string(unit) + "' (known: " + known + ")");
}

}  // namespace

bool is_known_unit(std::string_view unit) {
  for (const auto& e : unit_table)
    if (e.name == unit) return true;
  return false;
}

std::string unit_dimension(std::string_view unit) { return std::string(find_unit(unit).dimension); }

double unit_conversion_factor(std::string_view from, std::string_view to) {
  const UnitEntry& a = find_unit(from);
  const UnitEntry& b = find_unit(to);
  if (a.dimension != b.dimension)
    throw std::invalid_argument("cannot convert '" + std::string(from) + "' (" +
                                std::string(a.dimension) + ") to '" + std::string(to) + "' (" +
                                std::string(b.dimension) + ")");
  return a.to_si / b.to_si;
}

}  // namespace hbm::corridors
