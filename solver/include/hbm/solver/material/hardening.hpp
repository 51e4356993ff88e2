// SPDX-License-Identifier: GPL-3.0-or-later
// Isotropic hardening laws shared by solids (3D radial return, here) and shells (plane
// stress return, in shells/): yield stress sigma_y(eps_p, eps_p_dot) and its slope
// d sigma_y / d eps_p. LAW2 Johnson-Cook (without temperature):
//   sigma_y = min( (a + b eps_p^n) (1 + c ln(max(eps_dot / eps_dot0, 1))), sig_max )
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
  double yield_stress(double eps_p, double rate) const {
    return kind == Kind::JohnsonCook ? jc.yield_stress(eps_p, rate) : tab.yield_stress(eps_p, rate);
  }
  double slope(double eps_p, double rate) const {
    return kind == Kind::JohnsonCook ? jc.slope(eps_p, rate) : tab.slope(eps_p, rate);
  }
};

// 3D radial return (Simo & Hughes 1998, box 3.2) for J2 plasticity with isotropic
// hardening. In: trial deviatoric stress s[6] (xx yy zz xy yz zx) [stress], shear
// modulus G, current eps_p, strain rate for the rate term, dt. Out: s scaled back onto
// the yield surface, eps_p updated. Returns the plastic strain increment (0 if elastic).
// The consistency equation is solved by Newton on d eps_p (nonlinear hardening).
double radial_return_3d(const PlasticityLaw& law, double G, double s[6], double& eps_p,
                        double eps_rate);

}  // namespace hbm::solver
