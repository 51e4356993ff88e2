// SPDX-License-Identifier: GPL-3.0-or-later
// Johnson-Cook and tabulated isotropic hardening, and the 3D radial return
// (Simo & Hughes, Computational Inelasticity, box 3.2) used by the solid laws LAW2/LAW36.
#include "hbm/solver/material/hardening.hpp"

#include <algorithm>
#include <cmath>

namespace hbm::solver {

static double jc_rate_factor(double c, double eps_dot0, double rate) {
  if (c <= 0.0 || eps_dot0 <= 0.0 || rate <= eps_dot0) return 1.0;
  return 1.0 + c * std::log(rate / eps_dot0);
}

double JohnsonCookHardening::yield_stress(double eps_p, double rate) const {
  const double f = jc_rate_factor(c, eps_dot0, rate);
  const double s = (a + (eps_p > 0.0 ? b * std::pow(eps_p, n) : 0.0)) * f;
  return std::min(s, rate_scales_sig_max ? sig_max * f : sig_max);
}

double JohnsonCookHardening::slope(double eps_p, double rate) const {
  if (b == 0.0) return 0.0;
  const double ep = std::max(eps_p, 1e-12);
  const double f = jc_rate_factor(c, eps_dot0, rate);
  const double unscaled = a + b * std::pow(ep, n);
  if (unscaled * f >= (rate_scales_sig_max ? sig_max * f : sig_max)) return 0.0;
  return b * n * std::pow(ep, n - 1.0) * f;
}

// Index of the two curves bracketing `rate` and the weight of the upper one.
static void bracket(const std::vector<double>& rates, double rate, std::size_t& i, double& w) {
  i = 0;
  w = 0.0;
  if (rates.size() < 2 || rate <= rates.front()) return;
  if (rate >= rates.back()) {
    i = rates.size() - 2;
    w = 1.0;
    return;
  }
  while (i + 2 < rates.size() && rate > rates[i + 1]) ++i;
  w = (rate - rates[i]) / (rates[i + 1] - rates[i]);
}

double TabulatedHardening::yield_stress(double eps_p, double rate) const {
  if (curves.size() == 1) return scales[0] * (*curves[0])(eps_p);
  std::size_t i;
  double w;
  bracket(rates, rate, i, w);
  return (1.0 - w) * scales[i] * (*curves[i])(eps_p) + w * scales[i + 1] * (*curves[i + 1])(eps_p);
}

double TabulatedHardening::slope(double eps_p, double rate) const {
  if (curves.size() == 1) return scales[0] * curves[0]->slope(eps_p);
  std::size_t i;
  double w;
  bracket(rates, rate, i, w);
  return (1.0 - w) * scales[i] * curves[i]->slope(eps_p) + w * scales[i + 1] * curves[i + 1]->slope(eps_p);
}

double radial_return_3d(const PlasticityLaw& law, double G, double s[6], double& eps_p,
                        double eps_rate) {
  // Equivalent trial stress q = sqrt(3/2 s:s).
  const double ss = s[0] * s[0] + s[1] * s[1] + s[2] * s[2] +
                    2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
  const double q_trial = std::sqrt(1.5 * ss);
  double sy = law.yield_stress(eps_p, eps_rate);
  if (q_trial <= sy) return 0.0;
  // Consistency: q_trial - 3 G dl - sigma_y(eps_p + dl) = 0, Newton on dl.
  double dl = (q_trial - sy) / (3.0 * G + std::max(law.slope(eps_p, eps_rate), 0.0));
  for (int it = 0; it < 30; ++it) {
    dl = std::max(dl, 0.0);
    sy = law.yield_stress(eps_p + dl, eps_rate);
    const double r = q_trial - 3.0 * G * dl - sy;
    const double dr = 3.0 * G + std::max(law.slope(eps_p + dl, eps_rate), 0.0);
    const double step = r / dr;
    dl += step;
    if (std::abs(step) <= 1e-14 * (1.0 + dl)) break;
  }
  dl = std::max(dl, 0.0);
  const double scale = std::max(0.0, 1.0 - 3.0 * G * dl / q_trial);
  for (int k = 0; k < 6; ++k) s[k] *= scale;
  eps_p += dl;
  return dl;
}

}  // namespace hbm::solver
