// SPDX-License-Identifier: GPL-3.0-or-later
// Radioss spring force law of one DOF: static curve with the hardening rule H, rate terms
// and damping (see spring_dof_law.hpp for the formulas).
#include "springs/spring_dof_law.hpp"

#include <algorithm>
#include <cmath>

namespace hbm::solver::springs {

bool is_supported_hardening(int h) {
  return h == 0 || h == 1 || h == 2 || h == 4 || h == 7 || h == 8;
}

double SpringDofLaw::stiffness_bound() const {
  double k = K;
  if (nonlinear()) {
    double s = f1.max_abs_slope();
    if (!f3.empty()) s = std::max(s, f3.max_abs_slope());
    k = std::max(k, std::abs(A) * s / Ascale);
  }
  return k;
}

namespace {

// Static force of a nonlinear DOF for the new deformation `d` (old deformation `d_old`),
// following hardening rule H. Curves take the scaled abscissa d / Ascale.
double static_force(const SpringDofLaw& p, SpringDofState& s, double d, double d_old,
                    double length) {
  const double inv = 1.0 / p.Ascale;
  const double dd = d - d_old;
  switch (p.H) {
    case Hardening::Elastic:
      return p.f1(d * inv);
    case Hardening::TotalLength:
      return p.f1(length * inv);
    case Hardening::Isotropic: {
      // Elastic predictor with slope K, then return to the yield curve read at the
      // equivalent displacement (accumulated plastic displacement + elastic part).
      double f = s.f_static + p.K * dd;
      const double x = (f >= 0 ? s.plastic_t : -s.plastic_t) + f / p.K;
      const double y = p.f1(x * inv);
      if (f >= 0 && f > y) { s.plastic_t += (f - y) / p.K; f = y; }
      else if (f < 0 && f < y) { s.plastic_t += (y - f) / p.K; f = y; }
      return f;
    }
    case Hardening::Decoupled: {
      // Tension side beyond its permanent set, compression side beyond its own, zero force
      // in the gap between them.
      if (d > s.plastic_t) {
        const double f = std::min(p.K * (d - s.plastic_t), p.f1(d * inv));
        s.plastic_t = d - f / p.K;
        return f;
      }
      if (d < s.plastic_c) {
        const double f = std::max(p.K * (d - s.plastic_c), p.f1(d * inv));
        s.plastic_c = d - f / p.K;
        return f;
      }
      return 0.0;
    }
    case Hardening::Kinematic: {
      double f = s.f_static + p.K * dd;
      f = std::min(f, p.f1(d * inv));
      f = std::max(f, p.f3(d * inv));
      return f;
    }
    case Hardening::Hysteresis: {
      // Loading (|d| growing) is bounded by the loading curve, unloading by the
      // unloading curve, slope K in between.
      double f = s.f_static + p.K * dd;
      const bool growing = (d >= 0) ? (dd >= 0) : (dd < 0);
      const double load = p.f1(d * inv), unload = p.f3(d * inv);
      if (d >= 0) f = growing ? std::min(f, load) : std::max(f, unload);
      else        f = growing ? std::max(f, load) : std::min(f, unload);
      return f;
    }
  }
  return 0.0;
}

}  // namespace

double spring_dof_force(const SpringDofLaw& p, SpringDofState& s, double delta, double dt,
                        double length) {
  const double d_old = s.delta;
  const double f_old = s.force;
  if (s.broken) { s.delta = delta; return 0.0; }
  if ((p.delta_max != 0 && delta > p.delta_max) || (p.delta_min != 0 && delta < p.delta_min)) {
    s.broken = true;
    s.delta = delta; s.force = 0; s.f_static = 0;
    return 0.0;
  }
  const double rate = dt > 0 ? (delta - d_old) / dt : 0.0;
  double f;
  if (!p.nonlinear()) {
    s.f_static = p.K * delta;
    f = s.f_static + p.C * rate;
  } else {
    s.f_static = static_force(p, s, delta, d_old, length);
    double factor = p.A;
    if (p.B != 0) factor += p.B * std::log(std::max(1.0, std::abs(rate / p.D)));
    if (!p.g2.empty()) factor += p.E * p.g2(p.Fv * rate);
    f = factor * s.f_static + p.C * rate;
    if (!p.h4.empty()) f += p.Hscale * p.h4(p.Fv * rate);
  }
  s.energy += 0.5 * (f_old + f) * (delta - d_old);
  s.delta = delta;
  s.force = f;
  return f;
}

}  // namespace hbm::solver::springs
