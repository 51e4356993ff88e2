// SPDX-License-Identifier: GPL-3.0-or-later
// Isotropic hardening laws shared by solids (3D radial return, here) and shells (plane
// stress return, in shells/): yield stress sigma_y(eps_p, eps_p_dot) and its slope
// d sigma_y / d eps_p. LAW2 Johnson-Cook (without temperature), rate term
// f = 1 + c ln(max(eps_dot / eps_dot0, 1)):
//   sigma_y = min( (a + b eps_p^n) f, sig_max f )   (ICC 0, 1: OpenRadioss m2law.F)
//   sigma_y = min( (a + b eps_p^n) f, sig_max )     (ICC 2)
// LAW36 tabulated: sigma_y = Fscale * f_i(eps_p), interpolated linearly in strain rate
// between the curves given for increasing rates (one curve = rate independent).
#pragma once

#include "hbm/solver/function_curve.hpp"

#include <limits>
#include <vector>

namespace hbm::solver {

struct JohnsonCookHardening {
  double a = 0, b = 0, n = 1;       // a [stress], b [stress], n [-]
  double c = 0, eps_dot0 = 1;       // rate term; eps_dot0 [1/time]
  double sig_max = std::numeric_limits<double>::infinity();  // [stress]
  bool rate_scales_sig_max = true;  // ICC 0/1: the cap is sig_max times the rate term; ICC 2: sig_max
  double yield_stress(double eps_p, double eps_p_rate) const;
  double slope(double eps_p, double eps_p_rate) const;
};

struct TabulatedHardening {
  std::vector<const FunctionCurve*> curves;  // sigma_y(eps_p), one per rate
  std::vector<double> rates;                 // increasing strain rates [1/time]
  std::vector<double> scales;                // ordinate scale per curve [stress]
  double yield_stress(double eps_p, double eps_p_rate) const;
  double slope(double eps_p, double eps_p_rate) const;
};

// Parameters of one elastoplastic solid/shell material point law (LAW2 or LAW36).
struct PlasticityLaw {
  enum class Kind : unsigned char { JohnsonCook, Tabulated } kind = Kind::JohnsonCook;
  JohnsonCookHardening jc;
  TabulatedHardening tab;
  double eps_p_max = std::numeric_limits<double>::infinity();  // failure: element deleted
  // Strain-rate filter 2 pi F_cut [1/time] (OpenRadioss PM(9)); 0: the rate of the step is
  // used as it is. Set for LAW36 with two or more yield curves (law36_card.hpp) and for LAW2
  // with c > 0 and F_cut > 0 (law2_card.hpp).
  double rate_filter = 0;
  double yield_stress(double eps_p, double rate) const {
    return kind == Kind::JohnsonCook ? jc.yield_stress(eps_p, rate) : tab.yield_stress(eps_p, rate);
  }
  double slope(double eps_p, double rate) const {
    return kind == Kind::JohnsonCook ? jc.slope(eps_p, rate) : tab.slope(eps_p, rate);
  }
};

// Exponential average of the equivalent strain rate (OpenRadioss mstrain_rate.F):
// r_n = a r + (1 - a) r_{n-1}, a = min(1, 2 pi F_cut dt): a first-order low-pass of cutoff
// F_cut on the step's rate r, which in an explicit run carries the element's vibration at
// every cycle. `state` holds r_{n-1} and receives r_n, which is returned.
inline double filtered_strain_rate(double rate_filter, double dt, double rate, double& state) {
  const double a = rate_filter * dt < 1.0 ? rate_filter * dt : 1.0;
  state = a * rate + (1.0 - a) * state;
  return state;
}

// 3D radial return (Simo & Hughes 1998, box 3.2) for J2 plasticity with isotropic
// hardening. In: trial deviatoric stress s[6] (xx yy zz xy yz zx) [stress], shear
// modulus G, current eps_p, strain rate for the rate term, dt. Out: s scaled back onto
// the yield surface, eps_p updated. Returns the plastic strain increment (0 if elastic).
// The consistency equation is solved by Newton on d eps_p (nonlinear hardening).
double radial_return_3d(const PlasticityLaw& law, double G, double s[6], double& eps_p,
                        double eps_rate);

}  // namespace hbm::solver
