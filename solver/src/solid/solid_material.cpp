// SPDX-License-Identifier: GPL-3.0-or-later
// Stress update of solid laws LAW1, LAW2, LAW34, LAW36 (formulas in solid_material.hpp).
#include "solid/solid_material.hpp"

#include <cmath>

namespace hbm::solver {

double update_solid_stress(const SolidMaterial& m, const SolidPointState& st, const double d[6],
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
      // Equivalent total deviatoric strain rate sqrt(2/3 D':D') for the rate term.
      const double rate = (dt > 0.0)
          ? std::sqrt(2.0 / 3.0 * (de[0] * de[0] + de[1] * de[1] + de[2] * de[2] +
                                   2.0 * (de[3] * de[3] + de[4] * de[4] + de[5] * de[5]))) / dt
          : 0.0;
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

}  // namespace hbm::solver
