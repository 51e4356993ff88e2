// SPDX-License-Identifier: GPL-3.0-or-later
// Equivalent strip of a hollow elliptic rib section (semi-axes a = width/2 in the bending
// direction, b = height/2 along the strip, cortex t):
//   I = pi/4 (b a^3 - (b-t)(a-t)^3),   A = pi (ab - (a-t)(b-t)).
// A shell strip of thickness t_eq = sqrt(12 I / A) whose modulus and density are scaled by
// A / (h_band t_eq) has the rib's axial stiffness E A, bending stiffness E I (about the
// height axis) and mass, for any band height h_band. Plain arithmetic (no Eigen) so that the
// solver's shell verification can build the same strip.
#pragma once

#include <cmath>
#include <numbers>

namespace hbm::deckgen {

inline double hollow_ellipse_area(double height, double width, double cortical) {
  const double a = width / 2, b = height / 2, t = cortical;
  return std::numbers::pi * (a * b - (a - t) * (b - t));
}

inline double hollow_ellipse_inertia(double height, double width, double cortical) {
  const double a = width / 2, b = height / 2, t = cortical;
  return std::numbers::pi / 4 * (b * a * a * a - (b - t) * std::pow(a - t, 3));
}

inline double equivalent_rib_thickness(double height, double width, double cortical) {
  return std::sqrt(12 * hollow_ellipse_inertia(height, width, cortical) / hollow_ellipse_area(height, width, cortical));
}

}  // namespace hbm::deckgen
