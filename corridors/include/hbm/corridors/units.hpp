// SPDX-License-Identifier: GPL-3.0-or-later
// Unit conversion for time-history channels and corridors. The solver works in mm, ms, kg
// (so kN, GPa, J, mm/ms = m/s, mm/ms2 = 1000 m/s2) while published corridors are often in
// N, s, m/s or g. Each unit name maps to a dimension and a factor to SI; a conversion is
// allowed only between units of the same dimension.
#pragma once

#include <string>
#include <string_view>

namespace hbm::corridors {

/// Factor f such that value_in_to = f * value_in_from. Throws std::invalid_argument naming
/// the unit when a unit is unknown or the two units have different dimensions.
double unit_conversion_factor(std::string_view from, std::string_view to);

/// True when the unit name is known to the converter.
bool is_known_unit(std::string_view unit);

/// The dimension name of a known unit ("length", "force", ...); throws when unknown.
std::string unit_dimension(std::string_view unit);

/// Standard gravity used for g [m/s2] (ISO 80000-3 / SAE J211 conversion).
inline constexpr double standard_gravity = 9.80665;

}  // namespace hbm::corridors
