// SPDX-License-Identifier: GPL-3.0-or-later
// Constitutive laws of solid elements and their stress update at one integration point.
// Stresses are Cauchy, Voigt order xx yy zz xy yz zx, in the global frame, advanced with
// the Jaumann rate (objective): sigma' = sigma + dt (C:D + W sigma - sigma W).
//  - LAW1  hypoelastic isotropic: C:D = lambda tr(D) I + 2 G D.
//  - LAW2  Johnson-Cook / LAW36 tabulated: elastic predictor, 3D radial return on the
//          deviator (hardening.hpp), pressure elastic; EPS_p_max deletes the element.
//  - LAW34 Boltzmann viscoelastic: p from K (hypoelastic), deviator
//          s = 2 Ginf e + h,  h^{n+1} = exp(-beta dt) h^n + 2 (G0 - Ginf) (1 - exp(-beta dt))
//          / (beta dt) de   (exact recursive hereditary integral for a strain rate
//          constant over the step; Herrmann & Peterson 1968, Radioss LAW34).
#pragma once

#include "hbm/solver/material/hardening.hpp"

#include <cmath>
#include <cstdint>

namespace hbm::solver {

enum class SolidLaw : std::uint8_t { Elastic = 1, JohnsonCook = 2, Viscoelastic = 34, Tabulated = 36 };

struct SolidMaterial {
  SolidLaw law = SolidLaw::Elastic;
  std::int64_t id = 0;
  double rho = 0;                  // initial density [mass/length^3]
  double E = 0, nu = 0;            // LAW1/2/36 [stress], [-]
  double K = 0, G = 0, lambda = 0; // bulk, shear (instantaneous: G0 for LAW34), Lame [stress]
  double G0 = 0, Ginf = 0, beta = 0;  // LAW34 [stress], [stress], [1/time]
  PlasticityLaw plasticity;        // LAW2 / LAW36

  bool plastic() const { return law == SolidLaw::JohnsonCook || law == SolidLaw::Tabulated; }
  bool viscoelastic() const { return law == SolidLaw::Viscoelastic; }
  // Dilatational modulus for the wave speed: K + 4/3 G [stress].
  double wave_modulus() const { return K + 4.0 / 3.0 * G; }
  void set_elastic(double E_, double nu_) {
    E = E_;
    nu = nu_;
    G = E / (2.0 * (1.0 + nu));
    K = E / (3.0 * (1.0 - 2.0 * nu));
    lambda = K - 2.0 / 3.0 * G;
  }
  void set_viscoelastic(double K_, double G0_, double Ginf_, double beta_) {
    K = K_;
    G0 = G0_;
    Ginf = Ginf_;
    beta = beta_;
    G = G0;
    lambda = K - 2.0 / 3.0 * G;
    E = 9.0 * K * G / (3.0 * K + G);
    nu = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
  }
};

// Jaumann rotation increment dt (W sigma - sigma W) for symmetric sigma (Voigt) and the
// spin W_ij = (L_ij - L_ji)/2 given by wxy = W_xy, wyz = W_yz, wzx = W_zx:
// W = [[0, wxy, -wzx], [-wxy, 0, wyz], [wzx, -wyz, 0]].
inline void jaumann_increment(const double s[6], double wxy, double wyz, double wzx,
                              double dt, double ds[6]) {
  // (W S - S W) with S = [[s0 s3 s5],[s3 s1 s4],[s5 s4 s2]], expanded.
  ds[0] = dt * 2.0 * (wxy * s[3] - wzx * s[5]);
  ds[1] = dt * 2.0 * (wyz * s[4] - wxy * s[3]);
  ds[2] = dt * 2.0 * (wzx * s[5] - wyz * s[4]);
  ds[3] = dt * (wxy * (s[1] - s[0]) - wzx * s[4] + wyz * s[5]);
  ds[4] = dt * (wyz * (s[2] - s[1]) - wxy * s[5] + wzx * s[3]);
  ds[5] = dt * (wzx * (s[0] - s[2]) - wyz * s[3] + wxy * s[4]);
}

// Per-point state the update reads and writes (pointers into the group's arrays).
struct SolidPointState {
  double* sig;       // 6 Cauchy stress (LAW34: elastic part 2 Ginf e - p I)
  double* hist;      // 6 hereditary deviatoric stress h (LAW34 only), else nullptr
  double* eps_p;     // equivalent plastic strain (LAW2/36), else nullptr
  double* eps_rate = nullptr;  // filtered strain rate (plasticity.rate_filter > 0), else nullptr
};

// One step of the LAW1 / LAW34 hypoelastic update at a point as the lane kernels do it, the
// step's constants hoisted out of the element loop: sigma gets its Jaumann rotation,
// 2 G' dev(D) dt and, times `vol`, the volumetric K tr(D) dt, plus `shift` on the diagonal
// (vol 0, shift K ln J - p: the tetras' nodal pressure); the LAW34 hereditary deviator
// h^{n+1} = exp(-beta dt)(h + dt(Wh - hW)) + 2 (G0 - Ginf) (1 - exp(-beta dt))/(beta dt) dev(D) dt.
// G' = Ginf for LAW34, G for LAW1 (h stays 0).
struct HypoelasticStep {
  double dt = 0, decay = 0, two_g = 0, two_gh = 0, K = 0;

  HypoelasticStep(const SolidMaterial& m, double dt_) : dt(dt_), K(m.K) {
    const bool visco = m.viscoelastic();
    const double x = m.beta * dt;
    decay = visco ? std::exp(-x) : 0.0;
    const double gain = visco ? ((x > 1e-8) ? (1.0 - decay) / x : 1.0 - 0.5 * x) : 0.0;
    two_g = 2.0 * (visco ? m.Ginf : m.G);
    two_gh = visco ? 2.0 * (m.G0 - m.Ginf) * gain : 0.0;
  }

  void apply(const double s[6], const double h[6], const double d[6], double wxy, double wyz, double wzx, double vol,
             double shift, double s_out[6], double h_out[6]) const {
    double rot[6], hrot[6];
    jaumann_increment(s, wxy, wyz, wzx, dt, rot);
    jaumann_increment(h, wxy, wyz, wzx, dt, hrot);
    const double dv = (d[0] + d[1] + d[2]) * dt;
    const double dev[6] = {d[0] * dt - dv / 3.0, d[1] * dt - dv / 3.0, d[2] * dt - dv / 3.0,
                           d[3] * dt, d[4] * dt, d[5] * dt};
    const double dvol = dv * vol;
    for (int k = 0; k < 6; ++k) {
      s_out[k] = s[k] + rot[k] + two_g * dev[k] + (k < 3 ? K * dvol : 0.0) + (k < 3 ? shift : 0.0);
      h_out[k] = decay * (h[k] + hrot[k]) + two_gh * dev[k];
    }
  }
};

// Advance the stress over dt with rate of deformation d (Voigt, engineering-free:
// d[3] = D_xy etc.) and spin (wxy, wyz, wzx). Writes the total stress to `out`.
// Returns the plastic strain increment.
inline double update_solid_stress(const SolidMaterial& m, const SolidPointState& st, const double d[6],
                           double wxy, double wyz, double wzx, double dt, double out[6]) {
  double* s = st.sig;
  double rot[6];
  jaumann_increment(s, wxy, wyz, wzx, dt, rot);
  const double dv = (d[0] + d[1] + d[2]) * dt;      // volumetric strain increment
  const double de[6] = {d[0] * dt - dv / 3.0, d[1] * dt - dv / 3.0, d[2] * dt - dv / 3.0,
                        d[3] * dt, d[4] * dt, d[5] * dt};  // deviatoric (tensor) increments
  double dl = 0.0;
  switch (m.law) {
    case SolidLaw::Elastic: {
      for (int k = 0; k < 6; ++k) s[k] += rot[k] + 2.0 * m.G * de[k];
      for (int k = 0; k < 3; ++k) s[k] += m.K * dv;
      for (int k = 0; k < 6; ++k) out[k] = s[k];
      break;
    }
    case SolidLaw::JohnsonCook:
    case SolidLaw::Tabulated: {
      for (int k = 0; k < 6; ++k) s[k] += rot[k] + 2.0 * m.G * de[k];
      for (int k = 0; k < 3; ++k) s[k] += m.K * dv;
      const double p = (s[0] + s[1] + s[2]) / 3.0;
      double dev[6] = {s[0] - p, s[1] - p, s[2] - p, s[3], s[4], s[5]};
      // Equivalent deviatoric strain rate sqrt(2/3 D':D') for the rate term (OpenRadioss
      // mstrain_rate.F, IDEV 1, as its LAW36 solids use), filtered when the law says so.
      double rate = (dt > 0.0)
          ? std::sqrt(2.0 / 3.0 * (de[0] * de[0] + de[1] * de[1] + de[2] * de[2] +
                                   2.0 * (de[3] * de[3] + de[4] * de[4] + de[5] * de[5]))) / dt
          : 0.0;
      if (st.eps_rate && dt > 0.0) rate = filtered_strain_rate(m.plasticity.rate_filter, dt, rate, *st.eps_rate);
      dl = radial_return_3d(m.plasticity, m.G, dev, *st.eps_p, rate);
      for (int k = 0; k < 3; ++k) s[k] = dev[k] + p;
      for (int k = 3; k < 6; ++k) s[k] = dev[k];
      for (int k = 0; k < 6; ++k) out[k] = s[k];
      break;
    }
    case SolidLaw::Viscoelastic: {
      double* h = st.hist;
      double hrot[6];
      jaumann_increment(h, wxy, wyz, wzx, dt, hrot);
      const double x = m.beta * dt;
      const double decay = std::exp(-x);
      const double gain = (x > 1e-8) ? (1.0 - decay) / x : 1.0 - 0.5 * x;
      for (int k = 0; k < 6; ++k) {
        s[k] += rot[k] + 2.0 * m.Ginf * de[k];
        h[k] = decay * (h[k] + hrot[k]) + 2.0 * (m.G0 - m.Ginf) * gain * de[k];
      }
      for (int k = 0; k < 3; ++k) s[k] += m.K * dv;
      for (int k = 0; k < 6; ++k) out[k] = s[k] + h[k];
      break;
    }
  }
  return dl;
}


inline double von_mises(const double s[6]) {
  const double p = (s[0] + s[1] + s[2]) / 3.0;
  const double a = s[0] - p, b = s[1] - p, c = s[2] - p;
  return std::sqrt(1.5 * (a * a + b * b + c * c + 2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
}

}  // namespace hbm::solver
