// SPDX-License-Identifier: GPL-3.0-or-later
// Injury risk functions with their coefficients and sources. Coefficients marked [check]
// were recalled from the literature (shared/notes/ratings-and-criteria.md and the NHTSA
// NCAP 2008 risk curves) and not re-read in the primary source; docs/corridors.md says so.
#pragma once

namespace hbm::corridors {

/// Standard normal cumulative distribution.
double standard_normal_cdf(double z);

/// AIS3+ thoracic injury risk from peak chest deflection d [mm] and age [years]
/// (Laituri et al. 2005, SAE 2005-01-0297) [check]:
///   p = 1 / (1 + exp(12.597 - 0.05861 age - 1.568 d^0.4612)).
/// At age 35 the constant is 10.5456, the NHTSA NCAP (2008) Hybrid III chest curve.
double chest_deflection_ais3_risk_laituri2005(double deflection_mm, double age_years);

/// AIS3+ head injury risk from HIC15 (NHTSA NCAP 2008, after Eppinger et al. 1999 / Prasad &
/// Mertz 1985 data) [check]: p = Phi((ln HIC15 - 7.45231) / 0.73998).
double hic15_ais3_risk_nhtsa(double hic15);

/// AIS3+ neck injury risk from Nij (NHTSA NCAP 2008) [check]:
///   p = 1 / (1 + exp(3.2269 - 1.9688 Nij)).
double nij_ais3_risk_nhtsa(double nij);

/// Shoulder-belt force of 50 % AIS3+ thoracic risk (Foret-Bruno et al. 1998, Stapp 42):
/// 6.9 kN. Only this point is used (as a reference level, no curve).
inline constexpr double foret_bruno_belt_force_50pct_kN = 6.9;

}  // namespace hbm::corridors
