// SPDX-License-Identifier: GPL-3.0-or-later
// Rib fracture model (hbm-deckgen --rib-fracture AGE): the rib strips become elastoplastic
// with element deletion at the bone's failure strain, the seed paper's injury model.
//
// A rib strip is a shell of thickness t_eq = sqrt(12 I / A) with its modulus scaled by
// s = A / (h t_eq), so that it has the real hollow section's E A, E I and mass
// (rib_strip.hpp). At a curvature kappa the real section's outer fibre, at w / 2
// of its width w, is strained kappa w / 2; the strip's outer through-thickness Gauss point,
// at zeta t_eq / 2, is strained kappa zeta t_eq / 2, i.e. k = zeta t_eq / w times as much.
// Giving the strip the bone's yield strain and failure strain times k makes it yield and
// break at the real section's curvatures (and its stresses, times s, its moments):
//   sigma_y,strip = s k sigma_y,     H_strip = s H (plastic modulus, same ratio H / E),
//   eps_p,max,strip = k (eps_u - eps_y) / (1 + H / E),
// the last from the uniaxial linear-hardening law eps = sigma / E + eps_p at eps = k eps_u.
// What it does not match: the moment between first yield and failure (a hollow section
// and three Gauss points through a rectangle spread plasticity differently) and the axial
// yield force (k times the real one; ribs in a hub impact fail in bending).
// This header is plain arithmetic (no Eigen) so that the solver's shell verification can
// check the strip in the solver's own through-thickness integration.
#pragma once

#include "rib_strip.hpp"  // same folder: also found by the solver test, which has no deckgen include path

#include <cmath>

namespace hbm::deckgen {

// Rib cortical bone beyond yield (geometry/rib_fracture.csv, E from materials.csv).
struct RibBoneFailure {
  double E = 0;                 // Young's modulus [MPa]
  double yield_stress = 0;      // [MPa]
  double plastic_modulus = 0;   // d sigma / d eps_p [MPa]
  double log_median_intercept = 0, log_median_age_slope = 0;  // median eps_u = exp(b + c age)
  double age_min = 0, age_max = 0;                            // donor ages the fit covers [y]

  double yield_strain() const { return yield_stress / E; }
  // Median ultimate (failure) strain of rib cortical bone at `age` years (Larsson 2021).
  double ultimate_strain(double age) const { return std::exp(log_median_intercept + log_median_age_slope * age); }
};

// LAW2 parameters of an equivalent strip (stresses in the unit of bone.E).
struct StripPlasticity {
  double yield_stress = 0, plastic_modulus = 0, eps_p_max = 0;
};

// modulus_scale s = E_strip / E; fibre_ratio = t_eq / w; zeta_outer = outer Gauss point of
// the strip's through-thickness rule (sqrt(3/5) for three points).
inline StripPlasticity strip_plasticity(const RibBoneFailure& bone, double age, double modulus_scale, double fibre_ratio,
                                        double zeta_outer) {
  const double k = zeta_outer * fibre_ratio;
  StripPlasticity p;
  p.yield_stress = modulus_scale * k * bone.yield_stress;
  p.plastic_modulus = modulus_scale * bone.plastic_modulus;
  p.eps_p_max = k * (bone.ultimate_strain(age) - bone.yield_strain()) / (1.0 + bone.plastic_modulus / bone.E);
  return p;
}

// Outer Gauss-Legendre point of the three-point through-thickness rule the model's shells use.
inline double three_point_outer_zeta() { return std::sqrt(3.0 / 5.0); }

}  // namespace hbm::deckgen
