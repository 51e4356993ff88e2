// SPDX-License-Identifier: GPL-3.0-or-later
// Through-thickness integration shared by the shell kernels: the strain increment at
// point z is de_m + z dk (membrane plus curvature, Kirchhoff/Mindlin kinematics), each
// point's stress is updated in plane stress, and the resultants are
//   N = int sigma dz = t/2 sum w_p sigma_p,   M = int z sigma dz = (t/2)^2 sum w_p zeta_p sigma_p.
// A point whose plastic strain reaches EPS_p_max keeps the work done up to failure in the
// internal energy and carries no stress afterwards. element_rate >= 0 is the strain rate of
// every point's yield stress (filtered: LAW36 with rate curves, LAW2 with F_cut), < 0 each point's own.
#pragma once

#include "shells/shell_material.hpp"
#include "shells/shell_section.hpp"

namespace hbm::solver::shells {

struct ThicknessResult {
  double N[3] = {0, 0, 0};  // membrane resultants Nxx Nyy Nxy [force/length]
  double M[3] = {0, 0, 0};  // moment resultants Mxx Myy Mxy [force]
  double dE = 0;            // internal energy increment per unit area [energy/length^2]
  double dezz = 0;          // mean thickness strain increment [-]
  int newly_failed = 0;
};

inline void integrate_thickness(const ShellMaterial& m, const ShellSection& s, double t,
                                const double dem[3], const double dk[3], double dt,
                                double* stress, double* epsp, double* hist, ThicknessResult& r,
                                double element_rate = -1.0, double dspin = 0.0) {
  const double ht = 0.5 * t;
  const int nh = m.n_history();
  const double eps_fail = m.eps_p_max();
  // Elastic law (the body model's shells): the plane-stress Hooke update of
  // update_point, inlined here with the same expressions (bitwise the same stresses).
  const bool elastic = m.law == ShellLaw::Elastic;
  const double E = m.E, nu = m.nu;
  const double c = E / (1.0 - nu * nu);
  for (int p = 0; p < s.n_points; ++p) {
    double* sp = stress + 3 * p;
    if (epsp[p] >= eps_fail) continue;  // failed point
    const double z = s.zeta[p] * ht;
    const double de[3] = {dem[0] + z * dk[0], dem[1] + z * dk[1], dem[2] + z * dk[2]};
    PointStress st{sp[0], sp[1], sp[2]};
    PointResult pr;
    if (elastic) {
      const double S_old = st.sxx + st.syy;
      st.sxx += c * (de[0] + nu * de[1]);
      st.syy += c * (nu * de[0] + de[1]);
      st.sxy += c * 0.5 * (1.0 - nu) * de[2];
      pr.dezz = -nu / E * (st.sxx + st.syy - S_old);
    } else {
      pr = update_point(m, de, dt, st, epsp[p], hist + nh * p, element_rate, dspin);
    }
    const double w = s.weight[p] * ht;
    r.dE += 0.5 * w * ((sp[0] + st.sxx) * de[0] + (sp[1] + st.syy) * de[1] + (sp[2] + st.sxy) * de[2]);
    r.dezz += 0.5 * s.weight[p] * pr.dezz;
    if (pr.failed_now) {
      ++r.newly_failed;
      sp[0] = sp[1] = sp[2] = 0.0;
      continue;
    }
    sp[0] = st.sxx;
    sp[1] = st.syy;
    sp[2] = st.sxy;
    const double wz = w * z;
    r.N[0] += w * st.sxx;
    r.N[1] += w * st.syy;
    r.N[2] += w * st.sxy;
    r.M[0] += wz * st.sxx;
    r.M[1] += wz * st.syy;
    r.M[2] += wz * st.sxy;
  }
}

}  // namespace hbm::solver::shells
