// SPDX-License-Identifier: GPL-3.0-or-later
// One degree of freedom of a Radioss spring (/PROP/TYPE4, and each of the six DOFs of
// /PROP/TYPE8 and /PROP/TYPE13): the force (or moment) as a function of the deformation
// delta (elongation or relative rotation), its rate and the loading history.
//
// Force law (Radioss spring theory, /PROP/TYPE4 reference guide):
//   linear (no fct1):  F = K delta + C delta_dot
//   nonlinear:         F = f_H(delta) * [A + B ln(max(1, |delta_dot| / D)) + E g(F_v delta_dot)]
//                          + C delta_dot + Hscale h(F_v delta_dot)
// where f_H is the static force from curve fct1 (abscissa delta / Ascale) with the
// loading/unloading rule of the hardening flag H, g = fct2 and h = fct4 are optional
// velocity curves and F_v scales the velocity abscissa. The hardening flags:
//   H=0 nonlinear elastic: f_H = f1(delta), same path on loading and unloading;
//   H=1 elastoplastic, isotropic hardening: elastic slope K on unloading; the yield
//       curve is read at the equivalent displacement |plastic| + F/K, so yielding in
//       tension also raises the compressive yield force;
//   H=2 elastoplastic, tension and compression decoupled: each side keeps its own
//       permanent set, the force is zero between the two sets;
//   H=4 kinematic hardening: the force stays between the upper curve f1(delta) and the
//       lower curve f3(delta), elastic slope K inside;
//   H=7 elastic hysteresis: loading follows f1, unloading f3, slope K between them;
//   H=8 nonlinear elastic in total length: f_H = f1(l) with l the current length.
// Failure: when delta leaves [delta_min, delta_max] (each active if non-zero) the DOF
// breaks and carries no force from then on.
// Units: delta in length (or rad), F in force (or moment); K force/length; C force*time/length.
#pragma once

#include "springs/spring_curve.hpp"

#include <cstdint>

namespace hbm::solver::springs {

enum class Hardening : std::uint8_t {
  Elastic = 0, Isotropic = 1, Decoupled = 2, Kinematic = 4, Hysteresis = 7, TotalLength = 8
};
// Valid Radioss H values this law implements; others are a deck error in the build phase.
bool is_supported_hardening(int h);

// Parameters of one DOF (from one K/C/A/B/D + fct/H + F/E/Ascale/Hscale block).
struct SpringDofLaw {
  double K = 0;        // linear stiffness; unloading / elastic slope for H=1,2,4,7
  double C = 0;        // linear damping
  double A = 1;        // scale of the static curve
  double B = 0;        // logarithmic rate effect
  double D = 1;        // rate reference of the logarithmic term
  double E = 0;        // scale of g (fct2)
  double Fv = 1;       // scale of the velocity abscissa of g and h
  double Ascale = 1;   // abscissa scale of f1 and f3
  double Hscale = 1;   // scale of h (fct4)
  double delta_min = 0, delta_max = 0;  // failure limits (0 = none)
  Hardening H = Hardening::Elastic;
  CurveView f1, g2, f3, h4;  // fct1 (static), fct2 (rate multiplier), fct3 (unloading/lower), fct4 (rate additive)

  bool nonlinear() const { return !f1.empty(); }
  // Stiffness bound for the stable step: max(K, A * max|df1/d delta|).
  double stiffness_bound() const;
};

// History of one DOF of one spring.
struct SpringDofState {
  double delta = 0;     // deformation at the last evaluation
  double f_static = 0;  // static (rate-independent) force at the last evaluation
  double force = 0;     // total force at the last evaluation (static + rate + damping)
  double plastic_t = 0; // H=1: accumulated plastic displacement; H=2: permanent set in tension
  double plastic_c = 0; // H=2: permanent set in compression
  double energy = 0;    // work done on the DOF, trapezoidal: sum 0.5 (F_old + F_new) d_delta
  bool broken = false;
};

// Advance one DOF to deformation `delta` reached after step `dt` (> 0, or 0 at the first
// evaluation, then the rate is zero). `length` is the current length (used by H=8 only).
// Returns the total force and updates the state (force, energy, history).
double spring_dof_force(const SpringDofLaw& law, SpringDofState& s, double delta, double dt,
                        double length = 0.0);

}  // namespace hbm::solver::springs
