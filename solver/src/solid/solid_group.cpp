// SPDX-License-Identifier: GPL-3.0-or-later
// Solid element kernel: gather, uniform-gradient kinematics, stress update, bulk
// viscosity, internal forces, hourglass forces, element time step and nodal stiffness,
// scatter into slots. Formulas in solid_group.hpp and brick_geometry.hpp.
#include "solid/solid_group.hpp"

#include "solid/brick_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hbm::solver {

namespace {

// Tetra volume gradient: b_I = dV/dx_I, V = (x1-x0).((x2-x0)x(x3-x0))/6.
inline void tetra_volume_gradient(const double* x, const double* y, const double* z, double* bx,
                                  double* by, double* bz, double& volume, double& max_face_area) {
  const double ax = x[1] - x[0], ay = y[1] - y[0], az = z[1] - z[0];
  const double cx = x[2] - x[0], cy = y[2] - y[0], cz = z[2] - z[0];
  const double dx = x[3] - x[0], dy = y[3] - y[0], dz = z[3] - z[0];
  bx[1] = (cy * dz - cz * dy) / 6.0; by[1] = (cz * dx - cx * dz) / 6.0; bz[1] = (cx * dy - cy * dx) / 6.0;
  bx[2] = (dy * az - dz * ay) / 6.0; by[2] = (dz * ax - dx * az) / 6.0; bz[2] = (dx * ay - dy * ax) / 6.0;
  bx[3] = (ay * cz - az * cy) / 6.0; by[3] = (az * cx - ax * cz) / 6.0; bz[3] = (ax * cy - ay * cx) / 6.0;
  bx[0] = -(bx[1] + bx[2] + bx[3]);
  by[0] = -(by[1] + by[2] + by[3]);
  bz[0] = -(bz[1] + bz[2] + bz[3]);
  volume = ax * bx[1] + ay * by[1] + az * bz[1];
  double m2 = 0.0;
  for (int i = 0; i < 4; ++i) m2 = std::max(m2, bx[i] * bx[i] + by[i] * by[i] + bz[i] * bz[i]);
  max_face_area = 3.0 * std::sqrt(m2);  // |b_I| = area of the face opposite I / 3
}

// Physical hourglass stiffness in the corotational frame (engine-design.md §12):
// dQ = dW/du for the energy of the linear (modes 0-2) and bilinear (mode 3) hourglass
// strains of a box with half-lengths a, shear modulus G, volume V.
// u[i][k]: component i of hourglass mode k (local frame). Adds into dQ.
// The normal-strain pairs of modes 0-2 carry c1/2 (A^2 + B^2) + c2 A B and the normal
// warping strain of mode 3 the factor c3 (HourglassCoefficients): deviatoric energy only
// (Icpre 1, Belytschko & Bindeman 1993 ADS) or plane-stress bending (Icpre 0, ASQBI).
inline void physical_hourglass(const double u[3][4], const double a[3], double G, double V,
                               double c1, double c2, double c3, double dQ[3][4]) {
  const double s = G * V / (3.0 * 64.0);
  for (int m = 0; m < 3; ++m) {
    const int p = (m + 1) % 3, r = (m + 2) % 3;
    const double A = u[p][r] / a[p], B = u[r][p] / a[r];
    const double C = u[p][p] / a[r], D = u[r][r] / a[p];
    const double dA = s * (c1 * A + c2 * B);
    const double dB = s * (c1 * B + c2 * A);
    const double dCD = s * (C + D);
    dQ[p][r] += dA / a[p];
    dQ[r][p] += dB / a[r];
    dQ[p][p] += dCD / a[r];
    dQ[r][r] += dCD / a[p];
  }
  const double s4 = G * V / (9.0 * 64.0);
  const double i0 = 1.0 / (a[0] * a[0]), i1 = 1.0 / (a[1] * a[1]), i2 = 1.0 / (a[2] * a[2]);
  const double sum = i0 + i1 + i2;
  const double inv[3] = {i0, i1, i2};
  for (int i = 0; i < 3; ++i) dQ[i][3] += s4 * (sum + (c3 - 1.0) * inv[i]) * u[i][3];
}

}  // namespace

Index SolidGroup::initialize(const NodalState& nodes) {
  const std::size_t n = n_elements;
  volume0.assign(n, 0.0);
  mass.assign(n, 0.0);
  for (auto& a : sig) a.assign(n, 0.0);
  if (material.viscoelastic())
    for (auto& a : hist) a.assign(n, 0.0);
  eps_p.assign(material.plastic() ? n : 0, 0.0);
  e_int.assign(n, 0.0);
  if (nodes_per_element == 8)
    for (auto& a : hg) a.assign(n, 0.0);
  if (nodes_per_element == 8 && hourglass == HourglassForm::Physical)
    for (auto& a : hg_visc) a.assign(n, 0.0);
  q_bulk.assign(n, 0.0);
  alive.assign(n, 1);
  allocate_slots(false);
  Index bad = kNoIndex;
  const std::size_t npe = nodes_per_element;
  for (std::size_t e = 0; e < n; ++e) {
    double x[8], y[8], z[8], bx[8], by[8], bz[8], v = 0.0, amax = 0.0;
    for (std::size_t i = 0; i < npe; ++i) {
      const auto k = static_cast<std::size_t>(connectivity[e * npe + i]);
      x[i] = nodes.x.x[k];
      y[i] = nodes.x.y[k];
      z[i] = nodes.x.z[k];
    }
    if (npe == 8)
      brick::volume_gradient(x, y, z, bx, by, bz, v, amax);
    else
      tetra_volume_gradient(x, y, z, bx, by, bz, v, amax);
    if (!(v > 0.0) && bad == kNoIndex) bad = static_cast<Index>(e);
    volume0[e] = v;
    mass[e] = material.rho * v;
  }
  return bad;
}

SolidGroup::HourglassCoefficients SolidGroup::physical_coefficients() const {
  HourglassCoefficients h;
  if (icpre == 1) {
    // Deviatoric hourglass strain energy only (reduced pressure).
    h.c1 = 4.0 / 3.0;
    h.c2 = -2.0 / 3.0;
    h.c3 = 4.0 / 3.0;
  } else {
    // Bending modes with the plane-stress modulus E/(1 - nu^2) = 2G/(1 - nu) and coupling
    // nu, warping mode with the uniaxial modulus E = 2G(1 + nu): bounded as nu -> 1/2
    // (ASQBI, Belytschko & Bindeman 1993), so no volumetric locking.
    const double nu = std::clamp(material.nu, 0.0, 0.5);
    h.c1 = 2.0 / (1.0 - nu);
    h.c2 = nu * h.c1;
    h.c3 = 2.0 * (1.0 + nu);
  }
  return h;
}

std::string_view SolidGroup::formulation() const {
  if (nodes_per_element == 4) return "tetra4 constant strain";
  switch (hourglass) {
    case HourglassForm::Viscous: return "brick8 1-point FB viscous hourglass";
    case HourglassForm::Stiffness: return "brick8 1-point FB stiffness hourglass";
    case HourglassForm::Physical: return "brick8 1-point physical corotational hourglass";
  }
  return "brick8";
}

void SolidGroup::stress(std::size_t e, double s[6]) const {
  for (int k = 0; k < 6; ++k) s[k] = sig[k][e] + (material.viscoelastic() ? hist[k][e] : 0.0);
}

void SolidGroup::cell_field(CellField field, std::span<double> out) const {
  for (std::size_t e = 0; e < out.size(); ++e) {
    switch (field) {
      case CellField::VonMises: {
        double s[6];
        stress(e, s);
        out[e] = alive[e] ? von_mises(s) : 0.0;
        break;
      }
      case CellField::PlasticStrain: out[e] = eps_p.empty() ? 0.0 : eps_p[e]; break;
      case CellField::Eroded: out[e] = alive[e] ? 0.0 : 1.0; break;
    }
  }
}

template <int NPE>
void SolidGroup::compute_chunk(std::size_t chunk, const StepContext& step, const NodalState& nodes,
                               double& e_int_inc, double& e_hg_inc, double& dt_min, Index& dt_elem,
                               Index& inverted) {
  const std::size_t e_begin = chunk * kChunk;
  const std::size_t e_end = std::min(n_elements, e_begin + kChunk);
  const double dt = step.dt_prev;
  const SolidMaterial& mat = material;
  const bool visco = mat.viscoelastic(), plastic = mat.plastic();
  for (std::size_t e = e_begin; e < e_end; ++e) {
    const std::size_t s0 = e * NPE;
    if (!alive[e]) {
      for (int i = 0; i < NPE; ++i) {
        slot_force.x[s0 + i] = slot_force.y[s0 + i] = slot_force.z[s0 + i] = 0.0;
        slot_stiffness[s0 + i] = 0.0;
      }
      continue;
    }
    double x[8], y[8], z[8], vx[8], vy[8], vz[8];
    for (int i = 0; i < NPE; ++i) {
      const auto k = static_cast<std::size_t>(connectivity[s0 + i]);
      x[i] = nodes.x.x[k]; y[i] = nodes.x.y[k]; z[i] = nodes.x.z[k];
      vx[i] = nodes.v.x[k]; vy[i] = nodes.v.y[k]; vz[i] = nodes.v.z[k];
    }
    double bx[8], by[8], bz[8], V = 0.0, amax = 0.0, l = 0.0;
    if constexpr (NPE == 8) {
      brick::volume_gradient(x, y, z, bx, by, bz, V, amax);
      l = V / amax;
    } else {
      tetra_volume_gradient(x, y, z, bx, by, bz, V, amax);
      l = 3.0 * V / amax;
    }
    if (!(V > 0.0)) {
      if (inverted == kNoIndex) inverted = static_cast<Index>(e);
      for (int i = 0; i < NPE; ++i) {
        slot_force.x[s0 + i] = slot_force.y[s0 + i] = slot_force.z[s0 + i] = 0.0;
        slot_stiffness[s0 + i] = 0.0;
      }
      continue;
    }
    const double inv_v = 1.0 / V;
    // Velocity gradient L_ij = sum_I v_iI B_jI on the mid-step configuration
    // x^{n-1/2} = x^n - dt/2 v^{n-1/2} (second-order accurate strain increment; the
    // stress work then matches the trapezoidal work of the nodal forces).
    double L[3][3] = {};
    double v_mid = V;
    {
      double xm[8], ym[8], zm[8], mx[8], my[8], mz[8], vm = V, am = 0.0;
      const double* gx = bx;
      const double* gy = by;
      const double* gz = bz;
      if (dt > 0.0) {
        for (int i = 0; i < NPE; ++i) {
          xm[i] = x[i] - 0.5 * dt * vx[i];
          ym[i] = y[i] - 0.5 * dt * vy[i];
          zm[i] = z[i] - 0.5 * dt * vz[i];
        }
        if constexpr (NPE == 8)
          brick::volume_gradient(xm, ym, zm, mx, my, mz, vm, am);
        else
          tetra_volume_gradient(xm, ym, zm, mx, my, mz, vm, am);
        if (vm > 0.0) {
          gx = mx;
          gy = my;
          gz = mz;
        } else {
          vm = V;
        }
      }
      for (int i = 0; i < NPE; ++i) {
        L[0][0] += vx[i] * gx[i]; L[0][1] += vx[i] * gy[i]; L[0][2] += vx[i] * gz[i];
        L[1][0] += vy[i] * gx[i]; L[1][1] += vy[i] * gy[i]; L[1][2] += vy[i] * gz[i];
        L[2][0] += vz[i] * gx[i]; L[2][1] += vz[i] * gy[i]; L[2][2] += vz[i] * gz[i];
      }
      v_mid = vm;
      const double inv_vm = 1.0 / vm;
      for (auto& row : L)
        for (double& v : row) v *= inv_vm;
    }
    const double d[6] = {L[0][0], L[1][1], L[2][2], 0.5 * (L[0][1] + L[1][0]),
                         0.5 * (L[1][2] + L[2][1]), 0.5 * (L[2][0] + L[0][2])};
    const double wxy = 0.5 * (L[0][1] - L[1][0]), wyz = 0.5 * (L[1][2] - L[2][1]),
                 wzx = 0.5 * (L[2][0] - L[0][2]);
    // Stress update over dt^{n-1/2}.
    double s_el[6], h[6] = {0, 0, 0, 0, 0, 0}, ep = plastic ? eps_p[e] : 0.0;
    for (int k = 0; k < 6; ++k) s_el[k] = sig[k][e];
    if (visco)
      for (int k = 0; k < 6; ++k) h[k] = hist[k][e];
    double s_old[6], s_new[6];
    for (int k = 0; k < 6; ++k) s_old[k] = s_el[k] + h[k];
    if (dt > 0.0) {
      const SolidPointState st{s_el, visco ? h : nullptr, plastic ? &ep : nullptr};
      update_solid_stress(mat, st, d, wxy, wyz, wzx, dt, s_new);
      for (int k = 0; k < 6; ++k) sig[k][e] = s_el[k];
      if (visco)
        for (int k = 0; k < 6; ++k) hist[k][e] = h[k];
      if (plastic) eps_p[e] = ep;
    } else {
      for (int k = 0; k < 6; ++k) s_new[k] = s_old[k];
    }
    // Bulk viscosity (compression only).
    const double rho = mass[e] * inv_v;
    const double c = std::sqrt(mat.wave_modulus() / rho);
    const double dv = d[0] + d[1] + d[2];
    double q = 0.0, qv = 0.0;
    if (dv < 0.0) {
      q = rho * l * (qa * qa * l * dv * dv - qb * c * dv);
      qv = qb * c + qa * qa * l * (-dv);
    }
    // Internal energy: trapezoidal stress power 0.5 ((s - q I)^{n-1} + (s - q I)^n):D V dt
    // (all energies use this trapezoidal form so that they telescope with the kinetic
    // energy of the central difference scheme, see account_energies).
    auto power = [&](const double* s) {
      return s[0] * d[0] + s[1] * d[1] + s[2] * d[2] + 2.0 * (s[3] * d[3] + s[4] * d[4] + s[5] * d[5]);
    };
    const double de = (0.5 * (power(s_old) + power(s_new)) - 0.5 * (q_bulk[e] + q) * dv) * v_mid * dt;
    q_bulk[e] = q;
    e_int[e] += de;
    e_int_inc += de;
    // Internal forces: f_iI = -(sigma_ij - q delta_ij) b_jI  (b = V B).
    const double sxx = s_new[0] - q, syy = s_new[1] - q, szz = s_new[2] - q;
    const double sxy = s_new[3], syz = s_new[4], szx = s_new[5];
    double fx[8], fy[8], fz[8];
    for (int i = 0; i < NPE; ++i) {
      fx[i] = -(sxx * bx[i] + sxy * by[i] + szx * bz[i]);
      fy[i] = -(sxy * bx[i] + syy * by[i] + syz * bz[i]);
      fz[i] = -(szx * bx[i] + syz * by[i] + szz * bz[i]);
    }
    if constexpr (NPE == 8) {
      // FB hourglass projection gamma_alpha,I and hourglass velocities q_alpha.
      double gam[4][8], qx[4], qy[4], qz[4];
      for (int a = 0; a < 4; ++a) {
        double hx = 0.0, hy = 0.0, hz = 0.0;
        for (int i = 0; i < 8; ++i) {
          hx += brick::kHourglass[a][i] * x[i];
          hy += brick::kHourglass[a][i] * y[i];
          hz += brick::kHourglass[a][i] * z[i];
        }
        qx[a] = qy[a] = qz[a] = 0.0;
        for (int i = 0; i < 8; ++i) {
          gam[a][i] = brick::kHourglass[a][i] - (hx * bx[i] + hy * by[i] + hz * bz[i]) * inv_v;
          qx[a] += vx[i] * gam[a][i];
          qy[a] += vy[i] * gam[a][i];
          qz[a] += vz[i] * gam[a][i];
        }
      }
      double Qx[4], Qy[4], Qz[4];
      if (hourglass == HourglassForm::Viscous) {
        const double cv = hourglass_coef * rho * c * std::cbrt(V * V) * 0.25;
        double p = 0.0;
        for (int a = 0; a < 4; ++a) {
          Qx[a] = cv * qx[a]; Qy[a] = cv * qy[a]; Qz[a] = cv * qz[a];
          p += 0.5 * ((hg[a][e] + Qx[a]) * qx[a] + (hg[4 + a][e] + Qy[a]) * qy[a] + (hg[8 + a][e] + Qz[a]) * qz[a]);
          hg[a][e] = Qx[a]; hg[4 + a][e] = Qy[a]; hg[8 + a][e] = Qz[a];
        }
        e_hg_inc += p * dt;
      } else if (hourglass == HourglassForm::Stiffness) {
        double bb = 0.0;
        for (int i = 0; i < 8; ++i) bb += bx[i] * bx[i] + by[i] * by[i] + bz[i] * bz[i];
        const double k = hourglass_coef * (mat.lambda + 2.0 * mat.G) * bb * inv_v / 8.0;
        double p = 0.0;
        for (int a = 0; a < 4; ++a) {
          const double ox = hg[a][e], oy = hg[4 + a][e], oz = hg[8 + a][e];
          Qx[a] = ox + k * qx[a] * dt; Qy[a] = oy + k * qy[a] * dt; Qz[a] = oz + k * qz[a] * dt;
          hg[a][e] = Qx[a]; hg[4 + a][e] = Qy[a]; hg[8 + a][e] = Qz[a];
          p += 0.5 * ((ox + Qx[a]) * qx[a] + (oy + Qy[a]) * qy[a] + (oz + Qz[a]) * qz[a]);
        }
        e_hg_inc += p * dt;
      } else {
        // Corotational frame from the centre Jacobian columns g_j = sum_I xi_jI x_I / 8.
        double g[3][3] = {};
        for (int i = 0; i < 8; ++i) {
          g[0][0] += brick::kXi[i] * x[i]; g[0][1] += brick::kXi[i] * y[i]; g[0][2] += brick::kXi[i] * z[i];
          g[1][0] += brick::kEta[i] * x[i]; g[1][1] += brick::kEta[i] * y[i]; g[1][2] += brick::kEta[i] * z[i];
          g[2][0] += brick::kZeta[i] * x[i]; g[2][1] += brick::kZeta[i] * y[i]; g[2][2] += brick::kZeta[i] * z[i];
        }
        double half[3], R[3][3];
        for (int j = 0; j < 3; ++j) half[j] = 0.125 * std::sqrt(g[j][0] * g[j][0] + g[j][1] * g[j][1] + g[j][2] * g[j][2]);
        for (int k = 0; k < 3; ++k) R[0][k] = g[0][k] / (8.0 * half[0]);
        const double proj = R[0][0] * g[1][0] + R[0][1] * g[1][1] + R[0][2] * g[1][2];
        double e2[3] = {g[1][0] - proj * R[0][0], g[1][1] - proj * R[0][1], g[1][2] - proj * R[0][2]};
        const double n2 = std::sqrt(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]);
        for (int k = 0; k < 3; ++k) R[1][k] = e2[k] / n2;
        R[2][0] = R[0][1] * R[1][2] - R[0][2] * R[1][1];
        R[2][1] = R[0][2] * R[1][0] - R[0][0] * R[1][2];
        R[2][2] = R[0][0] * R[1][1] - R[0][1] * R[1][0];
        double u[3][4], dQ[3][4] = {};
        for (int i = 0; i < 3; ++i)
          for (int a = 0; a < 4; ++a) u[i][a] = (R[i][0] * qx[a] + R[i][1] * qy[a] + R[i][2] * qz[a]) * dt;
        const HourglassCoefficients hc = physical_coefficients();
        physical_hourglass(u, half, mat.G, V, hc.c1, hc.c2, hc.c3, dQ);
        // Q is kept in the global frame and turned with the element spin W (Jaumann, like
        // the stress): Q += dt W Q + R^T dQ. The frame R only orients the increment, so a
        // badly distorted element whose Gram-Schmidt frame jumps cannot turn the stored
        // hourglass force (that created energy in the hub case).
        const double Wm[3][3] = {{0.0, wxy, -wzx}, {-wxy, 0.0, wyz}, {wzx, -wyz, 0.0}};
        double p = 0.0;
        double Qg[3][4];
        for (int a = 0; a < 4; ++a) {
          const double old[3] = {hg[a][e], hg[4 + a][e], hg[8 + a][e]};
          const double qv[3] = {qx[a], qy[a], qz[a]};
          for (int k = 0; k < 3; ++k) {
            Qg[k][a] = old[k] + dt * (Wm[k][0] * old[0] + Wm[k][1] * old[1] + Wm[k][2] * old[2]) +
                       R[0][k] * dQ[0][a] + R[1][k] * dQ[1][a] + R[2][k] * dQ[2][a];
            hg[k * 4 + a][e] = Qg[k][a];
            p += 0.5 * (old[k] + Qg[k][a]) * qv[k] * dt;
          }
        }
        // The elastic part is the strain energy of the element's assumed hourglass strain
        // field: internal energy, as in OpenRadioss Isolid 24. Only the viscous part below
        // (artificial dissipation) is hourglass energy.
        e_int[e] += p;
        e_int_inc += p;
        // Small viscous part (global frame), trapezoidal work like the viscous form.
        const double cv = hc.viscous * hourglass_coef * rho * c * std::cbrt(V * V) * 0.25;
        double pv = 0.0;
        for (int a = 0; a < 4; ++a) {
          const double vx_ = cv * qx[a], vy_ = cv * qy[a], vz_ = cv * qz[a];
          pv += 0.5 * ((hg_visc[a][e] + vx_) * qx[a] + (hg_visc[4 + a][e] + vy_) * qy[a] +
                       (hg_visc[8 + a][e] + vz_) * qz[a]);
          hg_visc[a][e] = vx_; hg_visc[4 + a][e] = vy_; hg_visc[8 + a][e] = vz_;
          Qx[a] = Qg[0][a] + vx_;
          Qy[a] = Qg[1][a] + vy_;
          Qz[a] = Qg[2][a] + vz_;
        }
        e_hg_inc += pv * dt;
      }
      for (int i = 0; i < 8; ++i)
        for (int a = 0; a < 4; ++a) {
          fx[i] -= Qx[a] * gam[a][i];
          fy[i] -= Qy[a] * gam[a][i];
          fz[i] -= Qz[a] * gam[a][i];
        }
    }
    // Critical step: highest element frequency estimated by the Rayleigh quotient of the
    // dilatational mode u_I = B_I (exact for a box): with T = sum_I B_I (x) B_I,
    // omega^2 = n (lambda tr(T)^2 + 2 G T:T) / (rho tr(T)); dt = 2 / omega, i.e. an
    // effective length l_eff = 2 c / omega, reduced by bulk viscosity:
    // dt = l_eff / (Q + sqrt(Q^2 + c^2)).
    double txx = 0, tyy = 0, tzz = 0, txy = 0, tyz = 0, tzx = 0;
    for (int i = 0; i < NPE; ++i) {
      txx += bx[i] * bx[i]; tyy += by[i] * by[i]; tzz += bz[i] * bz[i];
      txy += bx[i] * by[i]; tyz += by[i] * bz[i]; tzx += bz[i] * bx[i];
    }
    const double iv2 = inv_v * inv_v;
    const double trT = (txx + tyy + tzz) * iv2;
    const double TT = (txx * txx + tyy * tyy + tzz * tzz + 2.0 * (txy * txy + tyz * tyz + tzx * tzx)) * iv2 * iv2;
    const double omega2 = NPE * (mat.lambda * trT * trT + 2.0 * mat.G * TT) / (rho * trT);
    const double l_eff = 2.0 * c / std::sqrt(omega2);
    const double dte = l_eff / (qv + std::sqrt(qv * qv + c * c));
    if (dte < dt_min) {
      dt_min = dte;
      dt_elem = static_cast<Index>(e);
    }
    const double k_slot = 2.0 * (mass[e] / NPE) / (dte * dte);
    for (int i = 0; i < NPE; ++i) {
      slot_force.x[s0 + i] = fx[i];
      slot_force.y[s0 + i] = fy[i];
      slot_force.z[s0 + i] = fz[i];
      slot_stiffness[s0 + i] = k_slot;
    }
    if (plastic && ep >= mat.plasticity.eps_p_max) alive[e] = 2;  // deleted after this cycle
  }
}

void SolidGroup::compute_forces(const StepContext& step, const NodalState& nodes,
                                GroupStepResult& result) {
  const std::size_t nch = n_chunks(n_elements);
  std::vector<double> e_int_c(nch, 0.0), e_hg_c(nch, 0.0),
      dt_c(nch, std::numeric_limits<double>::infinity());
  std::vector<Index> dt_el(nch, kNoIndex), inv_el(nch, kNoIndex);
#pragma omp parallel for schedule(static) if (nch >= 8)
  for (std::size_t ch = 0; ch < nch; ++ch) {
    if (nodes_per_element == 8)
      compute_chunk<8>(ch, step, nodes, e_int_c[ch], e_hg_c[ch], dt_c[ch], dt_el[ch], inv_el[ch]);
    else
      compute_chunk<4>(ch, step, nodes, e_int_c[ch], e_hg_c[ch], dt_c[ch], dt_el[ch], inv_el[ch]);
  }
  for (std::size_t ch = 0; ch < nch; ++ch) {
    energy.internal += e_int_c[ch];
    energy.hourglass += e_hg_c[ch];
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
