// SPDX-License-Identifier: GPL-3.0-or-later
// The Ogden law of /MAT/LAW42 where the deck summary and the engine's shells both need it:
// its uniaxial stress and the modulus the stable step of a shell takes from it. One
// definition, so that the summary's time step is the engine's.
#pragma once

#include <algorithm>
#include <cmath>

namespace hbm::deck {

inline constexpr int kOgdenPairs = 5;
// The stretch (uniaxial) up to which a LAW42 shell's stable step holds: beyond skin's
// failure strain (about 1.5).
inline constexpr double kOgdenStepStretch = 1.6;

// Initial (small-strain) shear modulus G = sum_p mu_p alpha_p / 2 (Ogden 1972); OpenRadioss
// asks it to be > 0 (hm_read_mat42.F) and stores 2 G as its GS.
inline double ogden_shear_modulus(const double mu[kOgdenPairs], const double alpha[kOgdenPairs]) {
  double g = 0;
  for (int p = 0; p < kOgdenPairs; ++p) g += 0.5 * mu[p] * alpha[p];
  return g;
}

// Cauchy stress of incompressible uniaxial tension at stretch l (l2 = l3 = l^-1/2):
// sum_p mu_p (l^a_p - l^(-a_p/2)) (Ogden 1972).
inline double ogden_uniaxial_stress(const double mu[kOgdenPairs], const double alpha[kOgdenPairs], double l) {
  double s = 0;
  for (int p = 0; p < kOgdenPairs; ++p)
    if (mu[p] != 0.0) s += mu[p] * (std::pow(l, alpha[p]) - std::pow(l, -0.5 * alpha[p]));
  return s;
}

// Young's modulus for the shell's stable step: the small-strain 3 G (G = sum mu_p alpha_p /
// 2) or the stiffest uniaxial tangent d sigma / d ln(l) up to kOgdenStepStretch, sampled every
// 1 %, whichever is larger (the law stiffens with the stretch).
inline double ogden_step_modulus(const double mu[kOgdenPairs], const double alpha[kOgdenPairs]) {
  double e = 3.0 * ogden_shear_modulus(mu, alpha);
  const double h = 1e-4;
  for (int i = 1; i <= 100; ++i) {
    const double l = 1.0 + (kOgdenStepStretch - 1.0) * i / 100.0;
    e = std::max(e, (ogden_uniaxial_stress(mu, alpha, l * (1 + h)) - ogden_uniaxial_stress(mu, alpha, l * (1 - h))) /
                        (std::log1p(h) - std::log1p(-h)));
  }
  return e;
}

}  // namespace hbm::deck
