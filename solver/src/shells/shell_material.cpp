// SPDX-License-Identifier: GPL-3.0-or-later
// Plane-stress point update of the shell materials (see shell_material.hpp for the
// laws and the papers followed).
#include "shells/shell_material.hpp"

#include <algorithm>
#include <cmath>

namespace hbm::solver::shells {

double ShellMaterial::ogden_uniaxial_stress(double l) const { return hbm::deck::ogden_uniaxial_stress(mu, alpha, l); }

double ShellMaterial::young() const {
  if (law == ShellLaw::Viscoelastic) return 9.0 * K * G0 / (3.0 * K + G0);
  if (law == ShellLaw::Ogden) return 3.0 * hbm::deck::ogden_shear_modulus(mu, alpha);
  return E;
}

double ShellMaterial::poisson() const {
  if (law == ShellLaw::Viscoelastic) return (3.0 * K - 2.0 * G0) / (2.0 * (3.0 * K + G0));
  if (law == ShellLaw::Ogden) return 0.5;
  return nu;
}

double ShellMaterial::plate_wave_speed() const {
  // LAW42 stiffens with the stretch: the step takes the stiffest uniaxial tangent up to
  // kOgdenStepStretch, so that it holds over the range the law is used in (skin fails near
  // 1.5; the deck summary takes the same modulus).
  const double e = law == ShellLaw::Ogden ? hbm::deck::ogden_step_modulus(mu, alpha) : young();
  const double v = poisson();
  return std::sqrt(e / (rho * (1.0 - v * v)));
}

std::string_view ShellMaterial::check() const {
  if (!(rho > 0)) return "density must be > 0";
  if (law == ShellLaw::Ogden) {
    // The initial shear modulus sum(mu_p alpha_p) / 2 must be > 0, the one condition
    // OpenRadioss's starter puts on the pairs (hm_read_mat42.F, message 828).
    if (!(hbm::deck::ogden_shear_modulus(mu, alpha) > 0)) return "LAW42 needs an initial shear modulus sum(mu_p alpha_p) / 2 > 0";
    if (!(sigma_cut > 0)) return "LAW42 needs sigma_cut > 0";
    return {};
  }
  if (law == ShellLaw::Viscoelastic) {
    if (!(K > 0) || !(G0 > 0)) return "LAW34 needs K > 0 and G0 > 0";
    if (Ginf < 0 || Ginf > G0) return "LAW34 needs 0 <= Ginf <= G0";
    if (beta < 0) return "LAW34 needs beta >= 0";
    return {};
  }
  if (!(E > 0)) return "Young's modulus must be > 0";
  if (!(nu > -1.0 && nu < 0.5)) return "Poisson's ratio must be in (-1, 0.5)";
  if (law == ShellLaw::JohnsonCook) {
    const auto& jc = plasticity.jc;
    if (!(jc.a > 0)) return "LAW2 yield stress a must be > 0";
    if (jc.b < 0 || jc.n < 0) return "LAW2 needs b >= 0 and n >= 0";
    if (jc.c < 0 || (jc.c > 0 && !(jc.eps_dot0 > 0))) return "LAW2 needs c >= 0 and EPS_DOT_0 > 0";
  }
  if (law == ShellLaw::Tabulated) {
    const auto& tab = plasticity.tab;
    if (tab.curves.empty() || tab.scales.size() != tab.curves.size() ||
        tab.rates.size() != tab.curves.size())
      return "LAW36 needs at least one yield curve";
    double h;
    if (!(yield(0.0, 0.0, h) > 0)) return "LAW36 initial yield stress must be > 0";
  }
  return {};
}

bool ShellMaterial::rate_dependent() const {
  if (law == ShellLaw::JohnsonCook) return plasticity.jc.c > 0;
  if (law == ShellLaw::Tabulated) return plasticity.tab.curves.size() > 1;
  return false;
}

namespace {

// Simo-Taylor plane-stress return: the trial stress in the invariant coordinates
// S = sxx + syy, D = sxx - syy, T = sxy relaxes as
//   S(g) = S_tr / (1 + E g / (3 (1 - nu))),  D(g) = D_tr / (1 + 2 G g),  T likewise,
// with von Mises stress q(g)^2 = S^2/4 + 3 D^2/4 + 3 T^2 and plastic strain increment
// deps_p = 2/3 g q(g). Solves q(g) - sigma_y(eps_p + 2/3 g q(g)) = 0 for g >= 0.
PointResult return_plane_stress(const ShellMaterial& m, double epsdot, PointStress& s,
                                double& epsp, double S_old) {
  PointResult r;
  const double E = m.E, nu = m.nu, G = E / (2.0 * (1.0 + nu));
  const double St = s.sxx + s.syy, Dt = s.sxx - s.syy, Tt = s.sxy;
  const double q_tr = std::sqrt(0.25 * St * St + 0.75 * Dt * Dt + 3.0 * Tt * Tt);
  double h;
  const double sy0 = m.yield(epsp, epsdot, h);
  if (q_tr <= sy0) {
    r.dezz = -nu / E * (St - S_old);
    return r;
  }
  const double c1 = E / (3.0 * (1.0 - nu)), c2 = 2.0 * G;
  auto eval = [&](double g, double& q, double& dq, double& fval, double& dfval) {
    const double a1 = 1.0 / (1.0 + c1 * g), a2 = 1.0 / (1.0 + c2 * g);
    const double S = St * a1, D = Dt * a2, T = Tt * a2;
    q = std::sqrt(0.25 * S * S + 0.75 * D * D + 3.0 * T * T);
    const double Sp = -c1 * S * a1, Dp = -c2 * D * a2, Tp = -c2 * T * a2;
    dq = q > 0 ? (0.25 * S * Sp + 0.75 * D * Dp + 3.0 * T * Tp) / q : 0.0;
    double hh;
    const double sy = m.yield(epsp + 2.0 / 3.0 * g * q, epsdot, hh);
    // Residual scaled by (1 + 2 G g): (1 + 2 G g) q(g) is nearly constant for the
    // deviatoric part, so the scaled residual is close to linear in g and Newton
    // converges in one or two steps.
    const double sc = 1.0 + c2 * g;
    fval = sc * (q - sy);
    dfval = c2 * (q - sy) + sc * (dq - hh * 2.0 / 3.0 * (q + g * dq));
  };
  // First guess from the 3D radial return: deps_p = f / (3G + H), with the von Mises
  // stress at the end of the step (q = sigma_y(eps_p + deps_p)) in g = 3/2 deps_p / q.
  const double dep0 = (q_tr - sy0) / (3.0 * G + std::max(h, 0.0));
  double g = 1.5 * dep0 / std::max(sy0 + std::max(h, 0.0) * dep0, q_tr - 3.0 * G * dep0);
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  double q, dq, f, df;
  // Newton, safeguarded by bisection once the root is bracketed. When |f| is below
  // 1e-4 sigma_y the last Newton step is taken without re-evaluating: quadratic
  // convergence leaves a consistency error of order 1e-7 sigma_y or less (checked in
  // ctest/solver/shells_kernel_test.cpp); in steady plastic flow this is two evaluations.
  for (int it = 0; it < 60; ++it) {
    eval(g, q, dq, f, df);
    if (f > 0) lo = g; else hi = g;
    double gn = (df < 0) ? g - f / df : -1.0;
    const bool in_bracket = gn > lo && gn < hi;
    if (!in_bracket) gn = std::isfinite(hi) ? 0.5 * (lo + hi) : 2.0 * g + 1e-300;
    g = gn;
    if (in_bracket && std::abs(f) <= 1e-4 * sy0 * (1.0 + c2 * g)) break;
  }
  const double a1 = 1.0 / (1.0 + c1 * g), a2 = 1.0 / (1.0 + c2 * g);
  const double S = St * a1, D = Dt * a2;
  s.sxx = 0.5 * (S + D);
  s.syy = 0.5 * (S - D);
  s.sxy = Tt * a2;
  q = std::sqrt(0.25 * S * S + 0.75 * D * D + 3.0 * s.sxy * s.sxy);
  r.depsp = 2.0 / 3.0 * g * q;
  epsp += r.depsp;
  // Elastic thickness strain plus plastic incompressibility: deps_p_zz = -g S / 3.
  r.dezz = -nu / E * (S - S_old) - g * S / 3.0;
  if (epsp >= m.eps_p_max()) r.failed_now = true;
  return r;
}

}  // namespace

PointResult update_point(const ShellMaterial& m, const double de[3], double dt, PointStress& s,
                         double& epsp, double* hist, double element_rate, double dspin) {
  if (m.law == ShellLaw::Ogden) {
    // Total in-plane strain and its principal values e1 >= e2; l_i^a = exp(a e_i) and
    // l3 = exp(-(e1 + e2)). The stress is coaxial with the strain: sigma = (s1 + s2)/2 I +
    // (s1 - s2)/2 N with N = (e - mid I) / rad the unit deviatoric direction of the strain.
    if (dspin != 0.0) {
      // The material turned by dspin in the frame: E <- R E R^T (tensor shear exy = g / 2).
      const double c = std::cos(dspin), sn = std::sin(dspin);
      const double xx = hist[0], yy = hist[1], xy = 0.5 * hist[2];
      hist[0] = c * c * xx - 2.0 * c * sn * xy + sn * sn * yy;
      hist[1] = sn * sn * xx + 2.0 * c * sn * xy + c * c * yy;
      hist[2] = 2.0 * (c * sn * (xx - yy) + (c * c - sn * sn) * xy);
    }
    hist[0] += de[0];
    hist[1] += de[1];
    hist[2] += de[2];
    const double exx = hist[0], eyy = hist[1], exy = 0.5 * hist[2];
    const double mid = 0.5 * (exx + eyy), hdiff = 0.5 * (exx - eyy);
    const double rad = std::sqrt(hdiff * hdiff + exy * exy);
    const double e1 = mid + rad, e2 = mid - rad, e3 = -(e1 + e2);
    double s1 = 0, s2 = 0;
    for (int p = 0; p < ShellMaterial::kOgdenPairs; ++p) {
      if (m.mu[p] == 0.0) continue;
      const double a = m.alpha[p], l3a = std::exp(a * e3);
      s1 += m.mu[p] * (std::exp(a * e1) - l3a);
      s2 += m.mu[p] * (std::exp(a * e2) - l3a);
    }
    s1 = std::min(s1, m.sigma_cut);
    s2 = std::min(s2, m.sigma_cut);
    const double avg = 0.5 * (s1 + s2), half = 0.5 * (s1 - s2);
    const double nxx = rad > 1e-300 ? hdiff / rad : 0.0, nxy = rad > 1e-300 ? exy / rad : 0.0;
    s.sxx = avg + half * nxx;
    s.syy = avg - half * nxx;
    s.sxy = half * nxy;
    PointResult res;
    res.dezz = -(de[0] + de[1]);  // ln l3 = -(e1 + e2): incompressible
    (void)dt;
    (void)epsp;
    (void)element_rate;
    return res;
  }
  if (m.law == ShellLaw::Viscoelastic) {
    // sigma = 2 Ginf e + h + K eps_v 1, h_{n+1} = E1 h_n + 2 (G0 - Ginf) phi de,
    // E1 = exp(-beta dt), phi = (1 - E1) / (beta dt); dezz from sigma_zz = 0.
    const double x = m.beta * dt;
    const double E1 = std::exp(-x);
    const double phi = x > 1e-8 ? (1.0 - E1) / x : 1.0 - 0.5 * x;
    const double Gv = (m.G0 - m.Ginf) * phi, Ge = m.Ginf + Gv;
    const double mm = de[0] + de[1];
    const double r = (E1 - 1.0) * hist[2];
    const double dezz = (-(m.K - 2.0 / 3.0 * Ge) * mm - r) / (4.0 / 3.0 * Ge + m.K);
    const double dv = mm + dezz;
    const double dexx = de[0] - dv / 3.0, deyy = de[1] - dv / 3.0, dezz_d = dezz - dv / 3.0;
    s.sxx += 2.0 * Ge * dexx + (E1 - 1.0) * hist[0] + m.K * dv;
    s.syy += 2.0 * Ge * deyy + (E1 - 1.0) * hist[1] + m.K * dv;
    s.sxy += Ge * de[2] + (E1 - 1.0) * hist[3];
    hist[0] = E1 * hist[0] + 2.0 * Gv * dexx;
    hist[1] = E1 * hist[1] + 2.0 * Gv * deyy;
    hist[2] = E1 * hist[2] + 2.0 * Gv * dezz_d;
    hist[3] = E1 * hist[3] + Gv * de[2];
    PointResult res;
    res.dezz = dezz;
    return res;
  }
  // Plane-stress Hooke predictor.
  const double E = m.E, nu = m.nu;
  const double c = E / (1.0 - nu * nu);
  const double S_old = s.sxx + s.syy;
  s.sxx += c * (de[0] + nu * de[1]);
  s.syy += c * (nu * de[0] + de[1]);
  s.sxy += c * 0.5 * (1.0 - nu) * de[2];
  if (m.law == ShellLaw::Elastic) {
    PointResult res;
    res.dezz = -nu / E * (s.sxx + s.syy - S_old);
    return res;
  }
  double epsdot = 0;
  if (element_rate >= 0.0) {
    epsdot = element_rate;
  } else if (dt > 0 && m.rate_dependent()) {
    const double eq2 = 4.0 / 3.0 * (de[0] * de[0] + de[1] * de[1] + de[0] * de[1]) +
                       de[2] * de[2] / 3.0;
    epsdot = std::sqrt(eq2) / dt;
  }
  return return_plane_stress(m, epsdot, s, epsp, S_old);
}

}  // namespace hbm::solver::shells
