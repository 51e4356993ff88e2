// SPDX-License-Identifier: GPL-3.0-or-later
// Shell section: thickness, through-thickness integration rule and hourglass
// coefficients of one /PROP/TYPE1.
//
// Through-thickness integration is Gauss-Legendre with N points (1..10) on zeta in
// [-1, 1], z = zeta t / 2 (points computed by Newton iteration on the Legendre
// polynomial, not tabulated). N = 1 is a membrane (no bending stiffness). Gauss rather
// than Lobatto: with 3 points elastic bending is exact, and the fully plastic moment is
// reached to 86% (N=3), 94% (N=5), 98.6% (N=9) of sigma_y t^2/4.
#pragma once

#include <array>
#include <cstdint>

namespace hbm::solver::shells {

inline constexpr int kMaxThicknessPoints = 10;

struct ShellSection {
  std::int64_t prop_id = 0;
  double thickness = 0;  // default thickness [length] (per-element values override)
  int n_points = 3;
  std::array<double, kMaxThicknessPoints> zeta{}, weight{};  // weights sum to 2
  double shear_factor = 5.0 / 6.0;  // transverse shear correction (Ashear)
  // Hourglass coefficients (Hm membrane, Hf out-of-plane, Hr rotation), Radioss
  // /PROP/TYPE1 line 2; Radioss defaults 0.01 when blank.
  double hm = 0.01, hf = 0.01, hr = 0.01;
  bool thickness_change = false;  // Ithick = 1: t follows the membrane strain
  // Deletion rule: the element is deleted when this many of its through-thickness points
  // have failed (from /PROP/TYPE1 P_thick_fail: ceil(P_thick_fail N); 0 = all N points).
  int fail_points = 0;
  int points_to_delete() const { return fail_points > 0 ? fail_points : n_points; }

  // Fills zeta/weight for n points; returns false when n is outside 1..10.
  bool set_points(int n);
};

}  // namespace hbm::solver::shells
