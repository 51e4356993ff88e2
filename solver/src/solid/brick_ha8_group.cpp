// SPDX-License-Identifier: GPL-3.0-or-later
// HA8 brick kernel (formulas in brick_ha8_group.hpp): gather, point gradients on the
// current and the mid-step configuration, mean dilatation, per-point stress update,
// bulk viscosity, internal forces, element time step, scatter into slots.
#include "solid/brick_ha8_group.hpp"

#include "core/parallel_loop.hpp"
#include "solid/brick_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hbm::solver {

namespace {

// Shape function derivatives dN_I/dxi_a at the 2x2x2 Gauss points (xi = +-1/sqrt 3),
// point g at the sign pattern of node g: N_I = (1 + xi_I xi)(1 + eta_I eta)(1 + zeta_I zeta)/8.
struct GaussTable {
  double dn[8][3][8];
  GaussTable() {
    const double r = 1.0 / std::sqrt(3.0);
    for (int g = 0; g < 8; ++g) {
      const double xi = r * brick::kXi[g], eta = r * brick::kEta[g], ze = r * brick::kZeta[g];
      for (int i = 0; i < 8; ++i) {
        const double a = 1.0 + brick::kXi[i] * xi, b = 1.0 + brick::kEta[i] * eta, c = 1.0 + brick::kZeta[i] * ze;
        dn[g][0][i] = 0.125 * brick::kXi[i] * b * c;
        dn[g][1][i] = 0.125 * brick::kEta[i] * a * c;
        dn[g][2][i] = 0.125 * brick::kZeta[i] * a * b;
      }
    }
  }
};
const GaussTable kGauss;

// Point volume gradient at Gauss point g: bg_iI = det(J) dN_I/dx_i = adj(J)_ia dN_I/dxi_a,
// J_ai = dx_i/dxi_a; returns det(J) (the point's volume, Gauss weight 1).
inline double point_gradient(const double* x, const double* y, const double* z, int g,
                             double* bgx, double* bgy, double* bgz) {
  const auto& dn = kGauss.dn[g];
  double M[3][3];
  for (int a = 0; a < 3; ++a) {
    double sx = 0.0, sy = 0.0, sz = 0.0;
    for (int i = 0; i < 8; ++i) {
      sx += dn[a][i] * x[i];
      sy += dn[a][i] * y[i];
      sz += dn[a][i] * z[i];
    }
    M[a][0] = sx; M[a][1] = sy; M[a][2] = sz;
  }
  double adj[3][3];
  adj[0][0] = M[1][1] * M[2][2] - M[1][2] * M[2][1];
  adj[0][1] = M[0][2] * M[2][1] - M[0][1] * M[2][2];
  adj[0][2] = M[0][1] * M[1][2] - M[0][2] * M[1][1];
  adj[1][0] = M[1][2] * M[2][0] - M[1][0] * M[2][2];
  adj[1][1] = M[0][0] * M[2][2] - M[0][2] * M[2][0];
  adj[1][2] = M[0][2] * M[1][0] - M[0][0] * M[1][2];
  adj[2][0] = M[1][0] * M[2][1] - M[1][1] * M[2][0];
  adj[2][1] = M[0][1] * M[2][0] - M[0][0] * M[2][1];
  adj[2][2] = M[0][0] * M[1][1] - M[0][1] * M[1][0];
  const double det = M[0][0] * adj[0][0] + M[0][1] * adj[1][0] + M[0][2] * adj[2][0];
  for (int i = 0; i < 8; ++i) {
    bgx[i] = adj[0][0] * dn[0][i] + adj[0][1] * dn[1][i] + adj[0][2] * dn[2][i];
    bgy[i] = adj[1][0] * dn[0][i] + adj[1][1] * dn[1][i] + adj[1][2] * dn[2][i];
    bgz[i] = adj[2][0] * dn[0][i] + adj[2][1] * dn[1][i] + adj[2][2] * dn[2][i];
  }
  return det;
}

inline double stress_power(const double* s, const double* d) {
  return s[0] * d[0] + s[1] * d[1] + s[2] * d[2] + 2.0 * (s[3] * d[3] + s[4] * d[4] + s[5] * d[5]);
}

}  // namespace

Index BrickHa8Group::initialize(const NodalState& nodes) {
  const std::size_t n = n_elements;
  const std::size_t np = n * kPoints;
  volume0.assign(n, 0.0);
  mass.assign(n, 0.0);
  sig.assign(6 * np, 0.0);
  hist.assign(material.viscoelastic() ? 6 * np : 0, 0.0);
  eps_p.assign(material.plastic() ? np : 0, 0.0);
  eps_rate.assign(material.plasticity.rate_filter > 0.0 ? np : 0, 0.0);
  e_int.assign(n, 0.0);
  q_bulk.assign(n, 0.0);
  alive.assign(n, 1);
  if (small_strain.enabled) frozen_geometry.allocate(n);
  allocate_slots(false);
  Index bad = kNoIndex;
  for (std::size_t e = 0; e < n; ++e) {
    double x[8], y[8], z[8], gx[8], gy[8], gz[8], v = 0.0;
    for (std::size_t i = 0; i < 8; ++i) {
      const auto k = static_cast<std::size_t>(connectivity[e * 8 + i]);
      x[i] = nodes.x.x[k];
      y[i] = nodes.x.y[k];
      z[i] = nodes.x.z[k];
    }
    bool ok = true;
    for (int g = 0; g < kPoints; ++g) {
      const double dv = point_gradient(x, y, z, g, gx, gy, gz);
      ok = ok && dv > 0.0;
      v += dv;
    }
    if (!ok && bad == kNoIndex) bad = static_cast<Index>(e);
    volume0[e] = v;
    mass[e] = material.rho * v;
  }
  return bad;
}

void BrickHa8Group::point_stress(std::size_t e, int g, double s[6]) const {
  const bool visco = material.viscoelastic();
  for (int k = 0; k < 6; ++k) s[k] = sig[at(k, g, e)] + (visco ? hist[at(k, g, e)] : 0.0);
}

void BrickHa8Group::stress(std::size_t e, double s[6]) const {
  for (int k = 0; k < 6; ++k) s[k] = 0.0;
  for (int g = 0; g < kPoints; ++g) {
    double p[6];
    point_stress(e, g, p);
    for (int k = 0; k < 6; ++k) s[k] += p[k] / kPoints;
  }
}

void BrickHa8Group::cell_field(CellField field, std::span<double> out) const {
  for (std::size_t e = 0; e < out.size(); ++e) {
    switch (field) {
      case CellField::VonMises: {
        double s[6];
        stress(e, s);
        out[e] = alive[e] ? von_mises(s) : 0.0;
        break;
      }
      case CellField::PlasticStrain: {
        double m = 0.0;
        if (!eps_p.empty())
          for (int g = 0; g < kPoints; ++g) m = std::max(m, eps_p[static_cast<std::size_t>(g) * n_elements + e]);
        out[e] = m;
        break;
      }
      case CellField::Eroded: out[e] = alive[e] ? 0.0 : 1.0; break;
      case CellField::SpecificEnergy: out[e] = mass[e] > 0.0 ? e_int[e] / mass[e] : 0.0; break;
      case CellField::HourglassEnergy: out[e] = 0.0; break;  // fully integrated: no hourglass modes
    }
  }
}

void BrickHa8Group::compute_chunk(std::size_t chunk, const StepContext& step, const NodalState& nodes,
                                  double& e_int_inc, double& dt_min, Index& dt_elem, Index& inverted) {
  const std::size_t e_begin = chunk * kChunk;
  const std::size_t e_end = std::min(n_elements, e_begin + kChunk);
  const double dt = step.dt_prev;
  const SolidMaterial& mat = material;
  const bool visco = mat.viscoelastic(), plastic = mat.plastic();
  for (std::size_t e = e_begin; e < e_end; ++e) {
    const std::size_t s0 = e * 8;
    auto zero_slots = [&] {
      for (int i = 0; i < 8; ++i) {
        slot_force.x[s0 + i] = slot_force.y[s0 + i] = slot_force.z[s0 + i] = 0.0;
        slot_stiffness[s0 + i] = 0.0;
      }
    };
    if (!alive[e]) {
      zero_slots();
      continue;
    }
    double x[8], y[8], z[8], vx[8], vy[8], vz[8];
    for (int i = 0; i < 8; ++i) {
      const auto k = static_cast<std::size_t>(connectivity[s0 + i]);
      x[i] = nodes.x.x[k]; y[i] = nodes.x.y[k]; z[i] = nodes.x.z[k];
      vx[i] = nodes.v.x[k]; vy[i] = nodes.v.y[k]; vz[i] = nodes.v.z[k];
    }
    // /DT/BRICK/CST: a switched element keeps the geometry it had at the switch.
    const bool frozen = frozen_geometry.active() && frozen_geometry.frozen[e] != 0;
    if (frozen)
      for (int i = 0; i < 8; ++i) {
        const double* xf = &frozen_geometry.x[e * 24 + 3 * static_cast<std::size_t>(i)];
        x[i] = xf[0]; y[i] = xf[1]; z[i] = xf[2];
      }
    // Exact volume gradient b_I at x^n (pressure force, time step) and point gradients.
    double bx[8], by[8], bz[8], V = 0.0, amax = 0.0;
    brick::volume_gradient(x, y, z, bx, by, bz, V, amax);
    double gnx[8][8], gny[8][8], gnz[8][8], dvn[8];
    bool ok = V > 0.0;
    for (int g = 0; g < kPoints; ++g) {
      dvn[g] = point_gradient(x, y, z, g, gnx[g], gny[g], gnz[g]);
      ok = ok && dvn[g] > 0.0;
    }
    if (!ok) {
      if (inverted == kNoIndex) inverted = static_cast<Index>(e);
      zero_slots();
      continue;
    }
    // Velocity gradients on the mid-step configuration x^{n-1/2} = x^n - dt/2 v^{n-1/2}
    // (as the one-point kernel: second-order strain increment, trapezoidal work).
    double gmx[8][8], gmy[8][8], gmz[8][8], dvm[8];
    bool mid = dt > 0.0 && !frozen;
    if (mid) {
      double xm[8], ym[8], zm[8];
      for (int i = 0; i < 8; ++i) {
        xm[i] = x[i] - 0.5 * dt * vx[i];
        ym[i] = y[i] - 0.5 * dt * vy[i];
        zm[i] = z[i] - 0.5 * dt * vz[i];
      }
      for (int g = 0; g < kPoints; ++g) {
        dvm[g] = point_gradient(xm, ym, zm, g, gmx[g], gmy[g], gmz[g]);
        mid = mid && dvm[g] > 0.0;
      }
    }
    if (!mid) {
      for (int g = 0; g < kPoints; ++g) {
        dvm[g] = dvn[g];
        std::copy(gnx[g], gnx[g] + 8, gmx[g]);
        std::copy(gny[g], gny[g] + 8, gmy[g]);
        std::copy(gnz[g], gnz[g] + 8, gmz[g]);
      }
    }
    // Mean dilatation tr D_bar = sum_I v_I . (sum_g bm_gI) / V_mid.
    double v_mid = 0.0, div = 0.0;
    for (int g = 0; g < kPoints; ++g) {
      v_mid += dvm[g];
      for (int i = 0; i < 8; ++i) div += vx[i] * gmx[g][i] + vy[i] * gmy[g][i] + vz[i] * gmz[g][i];
    }
    const double dv = div / v_mid;
    // Bulk viscosity on the mean dilatation (compression only).
    const double rho = mass[e] / V;
    const double c = std::sqrt(mat.wave_modulus() / rho);
    const double l = V / amax;
    double q = 0.0, qv = 0.0;
    if (dv < 0.0) {
      q = rho * l * (qa * qa * l * dv * dv - qb * c * dv);
      qv = qb * c + qa * qa * l * (-dv);
    }
    double fx[8] = {}, fy[8] = {}, fz[8] = {};
    double de_el = 0.0, mean_stress_v = 0.0, ep_max = 0.0;
    for (int g = 0; g < kPoints; ++g) {
      double L[3][3] = {};
      for (int i = 0; i < 8; ++i) {
        L[0][0] += vx[i] * gmx[g][i]; L[0][1] += vx[i] * gmy[g][i]; L[0][2] += vx[i] * gmz[g][i];
        L[1][0] += vy[i] * gmx[g][i]; L[1][1] += vy[i] * gmy[g][i]; L[1][2] += vy[i] * gmz[g][i];
        L[2][0] += vz[i] * gmx[g][i]; L[2][1] += vz[i] * gmy[g][i]; L[2][2] += vz[i] * gmz[g][i];
      }
      const double inv = 1.0 / dvm[g];
      for (auto& row : L)
        for (double& a : row) a *= inv;
      // B-bar: the point's deviatoric rate plus the element's mean volumetric rate
      // (Icpre 0: the point's own volumetric rate).
      const double vol = constant_pressure ? (dv - (L[0][0] + L[1][1] + L[2][2])) / 3.0 : 0.0;
      const double d[6] = {L[0][0] + vol, L[1][1] + vol, L[2][2] + vol, 0.5 * (L[0][1] + L[1][0]),
                           0.5 * (L[1][2] + L[2][1]), 0.5 * (L[2][0] + L[0][2])};
      const double wxy = 0.5 * (L[0][1] - L[1][0]), wyz = 0.5 * (L[1][2] - L[2][1]),
                   wzx = 0.5 * (L[2][0] - L[0][2]);
      double s_el[6], h[6] = {0, 0, 0, 0, 0, 0}, s_old[6], s_new[6] = {0, 0, 0, 0, 0, 0};
      double ep = plastic ? eps_p[static_cast<std::size_t>(g) * n_elements + e] : 0.0;
      for (int k = 0; k < 6; ++k) s_el[k] = sig[at(k, g, e)];
      if (visco)
        for (int k = 0; k < 6; ++k) h[k] = hist[at(k, g, e)];
      for (int k = 0; k < 6; ++k) s_old[k] = s_el[k] + h[k];
      if (dt > 0.0) {
        const SolidPointState st{s_el, visco ? h : nullptr, plastic ? &ep : nullptr,
                                 eps_rate.empty() ? nullptr : &eps_rate[static_cast<std::size_t>(g) * n_elements + e]};
        update_solid_stress(mat, st, d, wxy, wyz, wzx, dt, s_new);
        for (int k = 0; k < 6; ++k) sig[at(k, g, e)] = s_el[k];
        if (visco)
          for (int k = 0; k < 6; ++k) hist[at(k, g, e)] = h[k];
        if (plastic) eps_p[static_cast<std::size_t>(g) * n_elements + e] = ep;
      } else {
        for (int k = 0; k < 6; ++k) s_new[k] = s_old[k];
      }
      ep_max = std::max(ep_max, ep);
      // Trapezoidal stress power of the point (see SolidGroup: energies telescope with
      // the central-difference kinetic energy).
      de_el += 0.5 * (stress_power(s_old, d) + stress_power(s_new, d)) * dvm[g] * dt;
      // Deviatoric force of the point on x^n; mean stress collected for the element.
      const double sm = constant_pressure ? (s_new[0] + s_new[1] + s_new[2]) / 3.0 : 0.0;
      mean_stress_v += sm * dvn[g];
      const double sxx = s_new[0] - sm, syy = s_new[1] - sm, szz = s_new[2] - sm;
      const double sxy = s_new[3], syz = s_new[4], szx = s_new[5];
      for (int i = 0; i < 8; ++i) {
        fx[i] -= sxx * gnx[g][i] + sxy * gny[g][i] + szx * gnz[g][i];
        fy[i] -= sxy * gnx[g][i] + syy * gny[g][i] + syz * gnz[g][i];
        fz[i] -= szx * gnx[g][i] + syz * gny[g][i] + szz * gnz[g][i];
      }
    }
    // Constant pressure part: -(sigma_m_bar - q) b_I (Icpre 0: sigma_m_bar = 0 here, the
    // point forces above carry the whole point stress).
    double vsum = 0.0;
    for (int g = 0; g < kPoints; ++g) vsum += dvn[g];
    const double sp = mean_stress_v / vsum - q;
    for (int i = 0; i < 8; ++i) {
      fx[i] -= sp * bx[i];
      fy[i] -= sp * by[i];
      fz[i] -= sp * bz[i];
    }
    de_el -= 0.5 * (q_bulk[e] + q) * dv * v_mid * dt;
    q_bulk[e] = q;
    e_int[e] += de_el;
    e_int_inc += de_el;
    // Critical step: the one-point brick's Rayleigh estimate of the dilatational mode
    // (solid_group.cpp), which bounds the deviatoric modes of the full integration.
    double txx = 0, tyy = 0, tzz = 0, txy = 0, tyz = 0, tzx = 0;
    for (int i = 0; i < 8; ++i) {
      txx += bx[i] * bx[i]; tyy += by[i] * by[i]; tzz += bz[i] * bz[i];
      txy += bx[i] * by[i]; tyz += by[i] * bz[i]; tzx += bz[i] * bx[i];
    }
    const double iv2 = 1.0 / (V * V);
    const double trT = (txx + tyy + tzz) * iv2;
    const double TT = (txx * txx + tyy * tyy + tzz * tzz + 2.0 * (txy * txy + tyz * tyz + tzx * tzx)) * iv2 * iv2;
    const double omega2 = 8.0 * (mat.lambda * trT * trT + 2.0 * mat.G * TT) / (rho * trT);
    const double l_eff = 2.0 * c / std::sqrt(omega2);
    const double dte = l_eff / (qv + std::sqrt(qv * qv + c * c));
    if (dte < dt_min) {
      dt_min = dte;
      dt_elem = static_cast<Index>(e);
    }
    if (frozen_geometry.active() && !frozen && small_strain.triggers(dte, V / volume0[e])) {
      double* xf = &frozen_geometry.x[e * 24];
      for (int i = 0; i < 8; ++i) {
        xf[3 * i] = x[i]; xf[3 * i + 1] = y[i]; xf[3 * i + 2] = z[i];
      }
      frozen_geometry.frozen[e] = 1;
    }
    const double k_slot = 2.0 * (mass[e] / 8.0) / (dte * dte);
    for (int i = 0; i < 8; ++i) {
      slot_force.x[s0 + i] = fx[i];
      slot_force.y[s0 + i] = fy[i];
      slot_force.z[s0 + i] = fz[i];
      slot_stiffness[s0 + i] = k_slot;
    }
    // LAW2/36: the element is deleted when a Gauss point reaches EPS_p_max.
    if (plastic && ep_max >= mat.plasticity.eps_p_max) alive[e] = 2;
  }
}

void BrickHa8Group::compute_forces(const StepContext& step, const NodalState& nodes,
                                   GroupStepResult& result) {
  const std::size_t nch = n_chunks(n_elements);
  std::vector<double> e_int_c(nch, 0.0), dt_c(nch, std::numeric_limits<double>::infinity());
  std::vector<Index> dt_el(nch, kNoIndex), inv_el(nch, kNoIndex);
  parallel_loop(nch, nch >= 8, [&](std::size_t ch) {  // 8 = kSmallGroupChunks (cycle.cpp)
    compute_chunk(ch, step, nodes, e_int_c[ch], dt_c[ch], dt_el[ch], inv_el[ch]);
  }, chunk_thread);
  for (std::size_t ch = 0; ch < nch; ++ch) {
    energy.internal += e_int_c[ch];
    if (dt_c[ch] < result.dt_min) {
      result.dt_min = dt_c[ch];
      result.dt_element = dt_el[ch];
    }
    if (result.inverted_element == kNoIndex && inv_el[ch] != kNoIndex)
      result.inverted_element = inv_el[ch];
  }
  if (material.plastic()) {
    for (std::size_t e = 0; e < n_elements; ++e)
      if (alive[e] == 2) {
        alive[e] = 0;
        ++n_eroded;
        newly_eroded.push_back(static_cast<Index>(e));
        energy.eroded += e_int[e];
      }
  }
}

}  // namespace hbm::solver
