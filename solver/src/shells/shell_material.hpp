// SPDX-License-Identifier: GPL-3.0-or-later
// Materials on shells: the stress update of one through-thickness integration point in
// plane stress (sigma_zz = 0), in the element's corotational frame.
//
//  - LAW1  isotropic hypoelastic (plane-stress Hooke).
//  - LAW2  Johnson-Cook J2 plasticity, yield sigma_y = a + b eps_p^n (capped by SIG_max0),
//          strain-rate term c ln(epsdot/epsdot0) when c > 0.
//  - LAW36 J2 plasticity with tabulated yield curves sigma_y(eps_p) per strain rate.
//    The hardening laws are the engine's (hbm/solver/material/hardening.hpp, shared with
//    the solids). The rate: where the law filters it (LAW36 with two or more curves, LAW2
//    with c > 0 and F_cut > 0) the element's rate (element_strain_rate) filtered at F_cut,
//    as OpenRadioss does; else (LAW2 with F_cut 0) the point's own rate over the step. Both use the plane-stress return mapping of Simo & Taylor (1986), "A return mapping
//    algorithm for plane stress elastoplasticity", IJNME 22: 649-670 (Simo & Hughes,
//    Computational Inelasticity, section 3.4): the trial stress is relaxed along the
//    plane-stress projected flow direction and a scalar Newton iteration (safeguarded by
//    bisection) solves for the consistency parameter. EPS_p_max failure: a point whose
//    equivalent plastic strain reaches EPS_p_max carries no stress afterwards.
//  - LAW34 Boltzmann viscoelasticity G(t) = Ginf + (G0 - Ginf) exp(-beta t) with bulk K,
//    recursive update of the hereditary integral (Herrmann & Peterson 1968 /
//    Radioss LAW34); the thickness strain increment is solved so that sigma_zz = 0.
//  - LAW42 Ogden hyperelasticity, incompressible, in total form (Ogden 1972, Proc R Soc
//    Lond A 326:565-584; Radioss LAW42 on shells): W = sum_p mu_p / alpha_p (l1^a_p +
//    l2^a_p + l3^a_p - 3). The point keeps its total in-plane strain in the corotational
//    frame (the sum of the rate-of-deformation increments: the logarithmic strain when the
//    principal axes do not turn); principal stretches l_i = exp(e_i), l3 = 1 / (l1 l2)
//    (plane stress, incompressible), Cauchy stresses s_i = sum_p mu_p (l_i^a_p - l3^a_p),
//    each capped at sigma_cut in tension.
#pragma once

#include "hbm/deck/ogden_law.hpp"
#include "hbm/solver/material/hardening.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

namespace hbm::solver::shells {

enum class ShellLaw : std::uint8_t { Elastic = 1, JohnsonCook = 2, Viscoelastic = 34, Tabulated = 36, Ogden = 42 };

struct ShellMaterial {
  ShellLaw law = ShellLaw::Elastic;
  std::int64_t id = 0;
  double rho = 0, E = 0, nu = 0;  // [density], [stress], [-]
  PlasticityLaw plasticity;  // LAW2 / LAW36 hardening and EPS_p_max (engine's)
  // LAW34
  double K = 0, G0 = 0, Ginf = 0, beta = 0;
  // LAW42: Ogden pairs (mu_p [stress], alpha_p [-]; pairs with mu_p = 0 are unused) and the
  // tension cut-off of the principal stresses [stress].
  static constexpr int kOgdenPairs = hbm::deck::kOgdenPairs;
  double mu[kOgdenPairs] = {0, 0, 0, 0, 0}, alpha[kOgdenPairs] = {0, 0, 0, 0, 0};
  double sigma_cut = 1e30;
  // LAW42: the stretch up to which the stable step holds (plate_wave_speed() takes the
  // stiffest uniaxial tangent up to it; hbm/deck/ogden_law.hpp).
  static constexpr double kOgdenStepStretch = hbm::deck::kOgdenStepStretch;

  bool plastic() const { return law == ShellLaw::JohnsonCook || law == ShellLaw::Tabulated; }
  // History values per integration point (LAW34: hereditary deviatoric stresses; LAW42:
  // the total in-plane strain exx, eyy, gamma_xy in the corotational frame).
  int n_history() const {
    return law == ShellLaw::Viscoelastic ? 4 : law == ShellLaw::Ogden ? 3 : 0;
  }
  // LAW42: Cauchy stress of uniaxial tension at stretch l (plane stress, incompressible:
  // l2 = l3 = l^-1/2): sum_p mu_p (l^a_p - l^(-a_p/2)).
  double ogden_uniaxial_stress(double l) const;
  // Instantaneous Young's modulus and Poisson ratio (LAW34 from K and G0; LAW42 the
  // small-strain values 3 G and 0.5, G = sum_p mu_p alpha_p / 2).
  double young() const;
  double poisson() const;
  double shear_modulus() const { return young() / (2.0 * (1.0 + poisson())); }
  // Plate wave speed c = sqrt(E / (rho (1 - nu^2))) [length/time].
  double plate_wave_speed() const;
  // Equivalent plastic strain at failure (infinity: none).
  double eps_p_max() const { return plastic() ? plasticity.eps_p_max : std::numeric_limits<double>::infinity(); }
  // Yield stress and hardening slope d sigma_y / d eps_p at plastic strain eps_p,
  // for an equivalent total strain rate epsdot. Johnson-Cook is evaluated here with one
  // power per call (the same formula as JohnsonCookHardening, which calls pow twice);
  // tabulated curves go through the engine's TabulatedHardening.
  double yield(double eps_p, double epsdot, double& slope) const {
    if (plasticity.kind == PlasticityLaw::Kind::JohnsonCook) {
      const auto& jc = plasticity.jc;
      const double ep = eps_p > 1e-12 ? eps_p : 1e-12;
      const double pw = jc.n == 1.0 ? ep : (jc.n == 0.5 ? std::sqrt(ep) : std::pow(ep, jc.n));
      double f = 1.0;
      if (jc.c > 0.0 && epsdot > jc.eps_dot0) f = 1.0 + jc.c * std::log(epsdot / jc.eps_dot0);
      const double sy = (jc.a + (eps_p > 0.0 ? jc.b * pw : 0.0)) * f;
      const double cap = jc.rate_scales_sig_max ? jc.sig_max * f : jc.sig_max;
      if (sy >= cap) {
        slope = 0.0;
        return cap;
      }
      slope = jc.b * jc.n * pw / ep * f;
      return sy;
    }
    slope = plasticity.slope(eps_p, epsdot);
    return plasticity.yield_stress(eps_p, epsdot);
  }
  // True when the yield stress depends on the strain rate (then the rate is computed).
  bool rate_dependent() const;

  // Checks the parameters; returns an empty string when valid, else what is wrong.
  std::string_view check() const;
};

// State of one integration point, in the element's corotational frame.
struct PointStress {
  double sxx, syy, sxy;  // [stress]
};

// Result of one point update.
struct PointResult {
  double dezz = 0;      // thickness strain increment (for Ithick) [-]
  double depsp = 0;     // equivalent plastic strain increment [-]
  bool failed_now = false;  // eps_p reached EPS_p_max in this update
};

// Updates the stress of one point for the in-plane strain increment
// de = (dexx, deyy, gamma_xy) (engineering shear) over a step dt.
// `epsp` is the point's equivalent plastic strain (updated), `hist` its n_history()
// values. A point already failed (epsp >= eps_p_max) must not be passed in.
// element_rate >= 0: the strain rate of the yield stress, one for all points of the element
// (the filtered rate of element_strain_rate); < 0: the point's own rate over the step.
// dspin: the in-plane rotation of the material relative to the element frame over the step
// [rad]; LAW42 turns its total strain by it before adding de (the frame of a triangle
// follows its edge 1-2, which turns against the material when the triangle is stretched
// obliquely to it). The hypoelastic laws take their stress as corotational with the frame.
PointResult update_point(const ShellMaterial& m, const double de[3], double dt,
                         PointStress& s, double& epsp, double* hist, double element_rate = -1.0,
                         double dspin = 0.0);

// Equivalent strain rate of a shell element over a step (OpenRadioss mulawc.F, ISRATE 1, the
// energy equivalent of membrane plus bending): eps^2 = 4/3 (exx^2 + eyy^2 + exx eyy + gxy^2/4)
// + t^2/9 (kxx^2 + kyy^2 + kxx kyy + kxy^2/4), from the membrane increments dem (engineering
// shear) and curvature increments dk; rate = eps / dt.
inline double element_strain_rate(const double dem[3], const double dk[3], double t, double dt) {
  const double m2 = 4.0 / 3.0 * (dem[0] * dem[0] + dem[1] * dem[1] + dem[0] * dem[1] + 0.25 * dem[2] * dem[2]);
  const double k2 = (dk[0] * dk[0] + dk[1] * dk[1] + dk[0] * dk[1] + 0.25 * dk[2] * dk[2]) * t * t / 9.0;
  return std::sqrt(m2 + k2) / dt;
}

}  // namespace hbm::solver::shells
