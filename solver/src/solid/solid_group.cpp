// SPDX-License-Identifier: GPL-3.0-or-later
// Solid element kernel: gather, uniform-gradient kinematics, stress update, bulk
// viscosity, internal forces, hourglass forces, element time step and nodal stiffness,
// scatter into slots. Formulas in solid_group.hpp and brick_geometry.hpp.
#include "solid/solid_group.hpp"

#include "core/parallel_loop.hpp"
#include "solid/brick_geometry.hpp"
#include "core/lane_vector_ops.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

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
#pragma GCC unroll 3
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
#pragma GCC unroll 3
  for (int i = 0; i < 3; ++i) dQ[i][3] += s4 * (sum + (c3 - 1.0) * inv[i]) * u[i][3];
}


// Lanes of one chunk of bricks: every array is [component][lane] (or [lane]), so each stage
// of the kernel is a loop over the lanes that the compiler vectorises. One instance per
// thread (thread_local): about 60 KB with W = 32.
struct BrickLanes {
  static constexpr std::size_t W = 32;  // lanes per batch: the arrays stay in L1/L2
  alignas(64) double x[8][W], y[8][W], z[8][W], vx[8][W], vy[8][W], vz[8][W];
  alignas(64) double bx[8][W], by[8][W], bz[8][W];   // volume gradient, current configuration
  alignas(64) double mx[8][W], my[8][W], mz[8][W];   // volume gradient, mid-step configuration
  alignas(64) double fx[8][W], fy[8][W], fz[8][W];   // nodal forces (first: mid-step coordinates)
  alignas(64) double gam[4][8][W];                   // FB hourglass projection gamma_alpha,I
  alignas(64) double qx[4][W], qy[4][W], qz[4][W];   // hourglass velocities q_alpha
  alignas(64) double Qx[4][W], Qy[4][W], Qz[4][W];   // hourglass forces Q_alpha
  alignas(64) double hg[12][W], hgv[12][W];          // stored Q (and Physical: viscous part)
  alignas(64) double L[9][W], d[6][W], w[3][W];      // velocity gradient, D, spin (wxy wyz wzx)
  alignas(64) double sig[6][W], hist[6][W], s_new[6][W];
  alignas(64) double V[W], Vm[W], amax2[W], amid2[W], ok[W], mass[W], rho[W], c[W], v23[W];
  alignas(64) double q[W], qv[W], q_old[W], e_int[W], de[W], p_int[W], p_hg[W], dte[W], lc[W], tmp[W];
  alignas(64) double g[9][W], half[3][W], n2[W];     // Physical: centre Jacobian, frame
  alignas(64) double mv[W];  // 1: mid-step shift x - dt/2 v; 0: small strain (frozen geometry)
};


// Stages the brick and tetra lane kernels share (Lanes: BrickLanes or TetraLanes, NPE nodes).
// Deleted or inverted lanes: ok = 0 and finite stand-ins for V and amax2; the first alive
// element with a non-positive volume is reported in `inverted`.
template <class Lanes, class LaneCount>
inline void mask_lanes(Lanes& b, LaneCount lane_count, const std::vector<std::uint8_t>& alive, std::size_t e0,
                       Index& inverted) {
  const std::size_t n = lane_count;
  for (std::size_t l = 0; l < n; ++l) {
    const bool good = alive[e0 + l] != 0 && b.V[l] > 0.0;
    if (alive[e0 + l] != 0 && !(b.V[l] > 0.0) && inverted == kNoIndex) inverted = static_cast<Index>(e0 + l);
    b.ok[l] = good ? 1.0 : 0.0;
    b.V[l] = good ? b.V[l] : 1.0;  // masked lanes: finite values only
    b.amax2[l] = good ? b.amax2[l] : 1.0;
  }
}

// Mid-step coordinates x^{n-1/2} = x^n - dt/2 mv v^{n-1/2} into (fx, fy, fz) (mv = 0: a
// switched element's frozen shape).
template <int NPE, class Lanes, class LaneCount>
inline void mid_step_coordinates(Lanes& b, LaneCount lane_count, double hdt) {
  const std::size_t n = lane_count;
  for (int i = 0; i < NPE; ++i)
    for (std::size_t l = 0; l < n; ++l) {
      b.fx[i][l] = b.x[i][l] - hdt * b.mv[l] * b.vx[i][l];
      b.fy[i][l] = b.y[i][l] - hdt * b.mv[l] * b.vy[i][l];
      b.fz[i][l] = b.z[i][l] - hdt * b.mv[l] * b.vz[i][l];
    }
}

// The mid-step gradient (mx, my, mz) and volume Vm where that volume is positive, else the
// current ones; `have_mid` false: the current ones (first cycle).
template <int NPE, class Lanes, class LaneCount>
inline void settle_mid_step_gradient(Lanes& b, LaneCount lane_count, bool have_mid) {
  const std::size_t n = lane_count;
  if (have_mid) {
    for (int i = 0; i < NPE; ++i)
      for (std::size_t l = 0; l < n; ++l) {
        const bool mid = b.Vm[l] > 0.0;
        b.mx[i][l] = mid ? b.mx[i][l] : b.bx[i][l];
        b.my[i][l] = mid ? b.my[i][l] : b.by[i][l];
        b.mz[i][l] = mid ? b.mz[i][l] : b.bz[i][l];
      }
    for (std::size_t l = 0; l < n; ++l) b.Vm[l] = b.Vm[l] > 0.0 ? b.Vm[l] : b.V[l];
  } else {
    for (int i = 0; i < NPE; ++i) {
      lanes::copy_lanes(n, b.bx[i], b.mx[i]);
      lanes::copy_lanes(n, b.by[i], b.my[i]);
      lanes::copy_lanes(n, b.bz[i], b.mz[i]);
    }
    lanes::copy_lanes(n, b.V, b.Vm);
  }
}

// Physical hourglass (Isolid 24) over the lanes: corotational frame R from the centre
// Jacobian columns g_j = sum_I xi_jI x_I / 8 (Gram-Schmidt), increment dQ of the box
// closed form (physical_hourglass) in that frame, Q kept in the global frame and turned
// with the element spin W (Jaumann, like the stress): Q += dt W Q + R^T dQ. The frame only
// orients the increment, so a badly distorted element whose frame jumps cannot turn the
// stored hourglass force. Plus the small viscous part (global frame) with coefficient
// cvf rho c V^(2/3). Writes Q, the elastic work to p_int (strain energy of the assumed
// hourglass strain field: internal energy, as in OpenRadioss Isolid 24) and the viscous
// work (artificial dissipation) to p_hg.
void physical_hourglass_lanes(BrickLanes& b, std::size_t n, double dt, double G,
                              const SolidGroup::HourglassCoefficients& hc, double cvf) {
  for (std::size_t l = 0; l < n; ++l) {
    double g00 = 0, g01 = 0, g02 = 0, g10 = 0, g11 = 0, g12 = 0, g20 = 0, g21 = 0, g22 = 0;
    for (int i = 0; i < 8; ++i) {
      g00 += brick::kXi[i] * b.x[i][l]; g01 += brick::kXi[i] * b.y[i][l]; g02 += brick::kXi[i] * b.z[i][l];
      g10 += brick::kEta[i] * b.x[i][l]; g11 += brick::kEta[i] * b.y[i][l]; g12 += brick::kEta[i] * b.z[i][l];
      g20 += brick::kZeta[i] * b.x[i][l]; g21 += brick::kZeta[i] * b.y[i][l]; g22 += brick::kZeta[i] * b.z[i][l];
    }
    b.g[0][l] = g00; b.g[1][l] = g01; b.g[2][l] = g02;
    b.g[3][l] = g10; b.g[4][l] = g11; b.g[5][l] = g12;
    b.g[6][l] = g20; b.g[7][l] = g21; b.g[8][l] = g22;
  }
  for (int j = 0; j < 3; ++j) {  // half extents |g_j| / 8 (sqrt_lanes: vector loops, std::sqrt's bits)
    for (std::size_t l = 0; l < n; ++l)
      b.half[j][l] = b.g[3 * j][l] * b.g[3 * j][l] + b.g[3 * j + 1][l] * b.g[3 * j + 1][l] +
                     b.g[3 * j + 2][l] * b.g[3 * j + 2][l];
    lanes::sqrt_lanes(n, b.half[j]);
    for (std::size_t l = 0; l < n; ++l) b.half[j][l] *= 0.125;
  }
  for (std::size_t l = 0; l < n; ++l) {
    const double s = 8.0 * b.half[0][l];
    const double r0 = b.g[0][l] / s, r1 = b.g[1][l] / s, r2 = b.g[2][l] / s;
    const double proj = r0 * b.g[3][l] + r1 * b.g[4][l] + r2 * b.g[5][l];
    const double e0 = b.g[3][l] - proj * r0, e1 = b.g[4][l] - proj * r1, e2 = b.g[5][l] - proj * r2;
    b.g[0][l] = r0; b.g[1][l] = r1; b.g[2][l] = r2;   // first row of R
    b.g[3][l] = e0; b.g[4][l] = e1; b.g[5][l] = e2;   // second direction, not normed
    b.n2[l] = e0 * e0 + e1 * e1 + e2 * e2;
  }
  lanes::sqrt_lanes(n, b.n2);
  for (std::size_t l = 0; l < n; ++l) {
    double R[3][3];
    R[0][0] = b.g[0][l]; R[0][1] = b.g[1][l]; R[0][2] = b.g[2][l];
    R[1][0] = b.g[3][l] / b.n2[l]; R[1][1] = b.g[4][l] / b.n2[l]; R[1][2] = b.g[5][l] / b.n2[l];
    R[2][0] = R[0][1] * R[1][2] - R[0][2] * R[1][1];
    R[2][1] = R[0][2] * R[1][0] - R[0][0] * R[1][2];
    R[2][2] = R[0][0] * R[1][1] - R[0][1] * R[1][0];
    double u[3][4], dQ[3][4] = {};
#pragma GCC unroll 3
    for (int i = 0; i < 3; ++i)
#pragma GCC unroll 4
      for (int a = 0; a < 4; ++a)
        u[i][a] = (R[i][0] * b.qx[a][l] + R[i][1] * b.qy[a][l] + R[i][2] * b.qz[a][l]) * dt;
    const double half[3] = {b.half[0][l], b.half[1][l], b.half[2][l]};
    physical_hourglass(u, half, G, b.V[l], hc.c1, hc.c2, hc.c3, dQ);
    const double wxy = b.w[0][l], wyz = b.w[1][l], wzx = b.w[2][l];
    const double Wm[3][3] = {{0.0, wxy, -wzx}, {-wxy, 0.0, wyz}, {wzx, -wyz, 0.0}};
    const double cv = cvf * b.rho[l] * b.c[l] * b.v23[l];
    double p = 0.0, pv = 0.0;
#pragma GCC unroll 4
    for (int a = 0; a < 4; ++a) {
      const double old[3] = {b.hg[a][l], b.hg[4 + a][l], b.hg[8 + a][l]};
      const double qv[3] = {b.qx[a][l], b.qy[a][l], b.qz[a][l]};
      double Qg[3];
#pragma GCC unroll 3
      for (int k = 0; k < 3; ++k) {
        Qg[k] = old[k] + dt * (Wm[k][0] * old[0] + Wm[k][1] * old[1] + Wm[k][2] * old[2]) +
                R[0][k] * dQ[0][a] + R[1][k] * dQ[1][a] + R[2][k] * dQ[2][a];
        p += 0.5 * (old[k] + Qg[k]) * qv[k] * dt;
      }
      const double vx = cv * qv[0], vy = cv * qv[1], vz = cv * qv[2];
      pv += 0.5 * ((b.hgv[a][l] + vx) * qv[0] + (b.hgv[4 + a][l] + vy) * qv[1] + (b.hgv[8 + a][l] + vz) * qv[2]);
      b.hg[a][l] = Qg[0]; b.hg[4 + a][l] = Qg[1]; b.hg[8 + a][l] = Qg[2];
      b.hgv[a][l] = vx; b.hgv[4 + a][l] = vy; b.hgv[8 + a][l] = vz;
      b.Qx[a][l] = Qg[0] + vx; b.Qy[a][l] = Qg[1] + vy; b.Qz[a][l] = Qg[2] + vz;
    }
    b.p_int[l] = p;
    b.p_hg[l] = pv * dt;
  }
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
  eps_rate.assign(material.plasticity.rate_filter > 0.0 ? n : 0, 0.0);
  e_int.assign(n, 0.0);
  e_hg.assign(n, 0.0);
  if (nodes_per_element == 8)
    for (auto& a : hg) a.assign(n, 0.0);
  if (nodes_per_element == 8 && hourglass == HourglassForm::Physical)
    for (auto& a : hg_visc) a.assign(n, 0.0);
  if (small_strain.enabled) frozen_geometry.allocate(n, nodes_per_element);
  if (nodes_per_element != 4) nodal_pressure.enabled = false;
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
  if (nodal_pressure.enabled) nodal_pressure.setup(connectivity, volume0);
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
  if (nodes_per_element == 4) return nodal_pressure.enabled ? "tetra4 average nodal pressure" : "tetra4 constant strain";
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
      case CellField::SpecificEnergy: out[e] = mass[e] > 0.0 ? e_int[e] / mass[e] : 0.0; break;
      case CellField::HourglassEnergy: out[e] = e_hg[e]; break;
    }
  }
}

// Lanes of one batch of 4-node tetras ([component][lane], as BrickLanes): each stage of
// compute_tetra_lanes is a loop over the lanes that the compiler vectorises. One per thread.
struct TetraLanes {
  static constexpr std::size_t W = 32;
  alignas(64) double x[4][W], y[4][W], z[4][W], vx[4][W], vy[4][W], vz[4][W];
  alignas(64) double bx[4][W], by[4][W], bz[4][W];   // volume gradient, current configuration
  alignas(64) double mx[4][W], my[4][W], mz[4][W];   // volume gradient, mid-step configuration
  alignas(64) double fx[4][W], fy[4][W], fz[4][W];   // mid-step coordinates, then nodal forces
  alignas(64) double d[6][W], w[3][W], sig[6][W], hist[6][W], s_new[6][W];
  alignas(64) double V[W], Vm[W], amax2[W], am2[W], ok[W], mv[W], vol_free[W], shift_on[W], mlj[W];
  alignas(64) double mass[W], q_old[W], de[W], dte[W], ks[W];
  // Rows whose square root is taken a row at a time (sqrt_lanes): largest face, wave speed,
  // omega (Rayleigh quotient), sqrt(qv^2 + c^2); qv kept for the step after the roots.
  alignas(64) double face[W], c[W], omega[W], cq[W], qv[W];
};

namespace {

// Volume gradient b_I = dV/dx_I of the lanes' tetras (tetra_volume_gradient per lane),
// volume and the largest |b_I|^2 (= (face area / 3)^2).
template <class LaneCount>
inline void tetra_gradient_lanes(LaneCount lane_count, const double (*x)[TetraLanes::W], const double (*y)[TetraLanes::W],
                                 const double (*z)[TetraLanes::W], double (*bx)[TetraLanes::W], double (*by)[TetraLanes::W],
                                 double (*bz)[TetraLanes::W], double* V, double* amax2) {
  const std::size_t n = lane_count;
  for (std::size_t l = 0; l < n; ++l) {
    const double ax = x[1][l] - x[0][l], ay = y[1][l] - y[0][l], az = z[1][l] - z[0][l];
    const double cx = x[2][l] - x[0][l], cy = y[2][l] - y[0][l], cz = z[2][l] - z[0][l];
    const double dx = x[3][l] - x[0][l], dy = y[3][l] - y[0][l], dz = z[3][l] - z[0][l];
    const double b1x = (cy * dz - cz * dy) / 6.0, b1y = (cz * dx - cx * dz) / 6.0, b1z = (cx * dy - cy * dx) / 6.0;
    const double b2x = (dy * az - dz * ay) / 6.0, b2y = (dz * ax - dx * az) / 6.0, b2z = (dx * ay - dy * ax) / 6.0;
    const double b3x = (ay * cz - az * cy) / 6.0, b3y = (az * cx - ax * cz) / 6.0, b3z = (ax * cy - ay * cx) / 6.0;
    const double b0x = -(b1x + b2x + b3x), b0y = -(b1y + b2y + b3y), b0z = -(b1z + b2z + b3z);
    bx[0][l] = b0x; by[0][l] = b0y; bz[0][l] = b0z;
    bx[1][l] = b1x; by[1][l] = b1y; bz[1][l] = b1z;
    bx[2][l] = b2x; by[2][l] = b2y; bz[2][l] = b2z;
    bx[3][l] = b3x; by[3][l] = b3y; bz[3][l] = b3z;
    V[l] = ax * b1x + ay * b1y + az * b1z;
    const double m0 = b0x * b0x + b0y * b0y + b0z * b0z, m1 = b1x * b1x + b1y * b1y + b1z * b1z;
    const double m2 = b2x * b2x + b2y * b2y + b2z * b2z, m3 = b3x * b3x + b3y * b3y + b3z * b3z;
    amax2[l] = std::max(std::max(m0, m1), std::max(m2, m3));
  }
}

}  // namespace

// 4-node tetras of one chunk: LAW1 and LAW34 in batches of lanes, the plastic laws element
// by element (radial return).
void SolidGroup::compute_tetra_chunk(std::size_t chunk, const StepContext& step, const NodalState& nodes,
                                     double& e_int_inc, double& dt_min, Index& dt_elem, Index& inverted) {
  const std::size_t e_begin = chunk * kChunk, e_end = std::min(n_elements, e_begin + kChunk);
  if (material.plastic()) {
    compute_tetra_scalar(e_begin, e_end, step, nodes, e_int_inc, dt_min, dt_elem, inverted);
    return;
  }
  for (std::size_t e0 = e_begin; e0 < e_end; e0 += TetraLanes::W) {
    const std::size_t n = std::min(TetraLanes::W, e_end - e0);
    if (n == TetraLanes::W)
      compute_tetra_lanes(e0, std::integral_constant<std::size_t, TetraLanes::W>{}, step, nodes, e_int_inc, dt_min,
                          dt_elem, inverted);
    else
      compute_tetra_lanes(e0, n, step, nodes, e_int_inc, dt_min, dt_elem, inverted);
  }
}

// Tetras e0 .. e0+n-1 as lanes (LAW1, LAW34): the arithmetic of compute_tetra_scalar, stage
// by stage. Deleted or inverted lanes are computed on finite stand-in values and masked.
template <class LaneCount>
void SolidGroup::compute_tetra_lanes(std::size_t e0, LaneCount lane_count, const StepContext& step,
                                     const NodalState& nodes, double& e_int_inc, double& dt_min, Index& dt_elem,
                                     Index& inverted) {
  const std::size_t n = lane_count;
  static thread_local TetraLanes lanes;
  TetraLanes& b = lanes;
  const double dt = step.dt_prev;
  const SolidMaterial& mat = material;
  const bool visco = mat.viscoelastic();
  const bool frozen_any = frozen_geometry.active();
  for (std::size_t l = 0; l < n; ++l) {
    const Index* conn = &connectivity[(e0 + l) * 4];
    const bool fr = frozen_any && frozen_geometry.frozen[e0 + l];
    const double* xf = fr ? &frozen_geometry.x[(e0 + l) * 12] : nullptr;
    for (int i = 0; i < 4; ++i) {
      const auto k = static_cast<std::size_t>(conn[i]);
      b.x[i][l] = fr ? xf[3 * i] : nodes.x.x[k];
      b.y[i][l] = fr ? xf[3 * i + 1] : nodes.x.y[k];
      b.z[i][l] = fr ? xf[3 * i + 2] : nodes.x.z[k];
      b.vx[i][l] = nodes.v.x[k]; b.vy[i][l] = nodes.v.y[k]; b.vz[i][l] = nodes.v.z[k];
    }
    b.mv[l] = fr ? 0.0 : 1.0;
    // Nodal pressure: the material sees no volume change and the mean stress is set from
    // the nodes (not for a switched tetra: its own small strain pressure).
    const bool np = nodal_pressure.enabled && !fr;
    b.vol_free[l] = np ? 0.0 : 1.0;
    b.shift_on[l] = np ? 1.0 : 0.0;
    b.mlj[l] = np ? nodal_pressure.mean_log_j(e0 + l) : 0.0;
  }
  for (int k = 0; k < 6; ++k) lanes::copy_lanes(n, sig[k].data() + e0, b.sig[k]);
  if (visco)
    for (int k = 0; k < 6; ++k) lanes::copy_lanes(n, hist[k].data() + e0, b.hist[k]);
  else
    for (int k = 0; k < 6; ++k) std::fill_n(b.hist[k], n, 0.0);
  lanes::copy_lanes(n, mass.data() + e0, b.mass);
  lanes::copy_lanes(n, q_bulk.data() + e0, b.q_old);

  tetra_gradient_lanes(lane_count, b.x, b.y, b.z, b.bx, b.by, b.bz, b.V, b.amax2);
  mask_lanes(b, lane_count, alive, e0, inverted);
  // Velocity gradient on the mid-step configuration x - dt/2 v (current one if its volume
  // is not positive, and for a switched tetra, whose shape is frozen).
  if (dt > 0.0) {
    mid_step_coordinates<4>(b, lane_count, 0.5 * dt);
    tetra_gradient_lanes(lane_count, b.fx, b.fy, b.fz, b.mx, b.my, b.mz, b.Vm, b.am2);
  }
  settle_mid_step_gradient<4>(b, lane_count, dt > 0.0);
  for (std::size_t l = 0; l < n; ++l) {
    double L[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < 4; ++i) {
      L[0] += b.vx[i][l] * b.mx[i][l]; L[1] += b.vx[i][l] * b.my[i][l]; L[2] += b.vx[i][l] * b.mz[i][l];
      L[3] += b.vy[i][l] * b.mx[i][l]; L[4] += b.vy[i][l] * b.my[i][l]; L[5] += b.vy[i][l] * b.mz[i][l];
      L[6] += b.vz[i][l] * b.mx[i][l]; L[7] += b.vz[i][l] * b.my[i][l]; L[8] += b.vz[i][l] * b.mz[i][l];
    }
    const double iv = 1.0 / b.Vm[l];
    for (double& v : L) v *= iv;
    b.d[0][l] = L[0]; b.d[1][l] = L[4]; b.d[2][l] = L[8];
    b.d[3][l] = 0.5 * (L[1] + L[3]); b.d[4][l] = 0.5 * (L[5] + L[7]); b.d[5][l] = 0.5 * (L[6] + L[2]);
    b.w[0][l] = 0.5 * (L[1] - L[3]); b.w[1][l] = 0.5 * (L[5] - L[7]); b.w[2][l] = 0.5 * (L[6] - L[2]);
  }
  // Stress update (LAW1, LAW34: HypoelasticStep as the brick lanes), with the old total stress
  // power first for the trapezoidal internal energy.
  const HypoelasticStep law(mat, dt);
  const double K = mat.K;
  const bool update = dt > 0.0;
  for (std::size_t l = 0; l < n; ++l) {
    const double s[6] = {b.sig[0][l], b.sig[1][l], b.sig[2][l], b.sig[3][l], b.sig[4][l], b.sig[5][l]};
    const double h[6] = {b.hist[0][l], b.hist[1][l], b.hist[2][l], b.hist[3][l], b.hist[4][l], b.hist[5][l]};
    const double d[6] = {b.d[0][l], b.d[1][l], b.d[2][l], b.d[3][l], b.d[4][l], b.d[5][l]};
    b.de[l] = (s[0] + h[0]) * d[0] + (s[1] + h[1]) * d[1] + (s[2] + h[2]) * d[2] +
              2.0 * ((s[3] + h[3]) * d[3] + (s[4] + h[4]) * d[4] + (s[5] + h[5]) * d[5]);
    if (!update) {
      for (int k = 0; k < 6; ++k) b.s_new[k][l] = s[k] + h[k];
      continue;
    }
    const double shift = b.shift_on[l] * (K * b.mlj[l] - (s[0] + s[1] + s[2]) / 3.0);
    double sn[6], hn[6];
    law.apply(s, h, d, b.w[0][l], b.w[1][l], b.w[2][l], b.vol_free[l], shift, sn, hn);
    for (int k = 0; k < 6; ++k) {
      b.sig[k][l] = sn[k];
      b.hist[k][l] = hn[k];
      b.s_new[k][l] = sn[k] + hn[k];
    }
  }
  // Bulk viscosity, internal energy, forces, critical step (see compute_tetra_scalar). The
  // square roots are taken a row at a time (sqrt_lanes: the same bits as std::sqrt), so that
  // the stages around them are vector loops (a std::sqrt keeps its loop scalar, errno).
  const double qa2 = qa * qa, qb_ = qb, lambda = mat.lambda, G = mat.G, M = mat.wave_modulus();
  for (std::size_t l = 0; l < n; ++l) {
    b.face[l] = b.amax2[l];
    b.c[l] = M / (b.mass[l] * (1.0 / b.V[l]));  // M / rho
  }
  lanes::sqrt_lanes(n, b.face);
  lanes::sqrt_lanes(n, b.c);
  for (std::size_t l = 0; l < n; ++l) {
    const double V = b.V[l], inv_v = 1.0 / V;
    const double lc = 3.0 * V / (3.0 * b.face[l]);  // 3 V / largest face area
    const double rho = b.mass[l] * inv_v, c = b.c[l];
    const double d0 = b.d[0][l], d1 = b.d[1][l], d2 = b.d[2][l];
    const double dv = d0 + d1 + d2;
    const bool comp = dv < 0.0;
    const double q = comp ? rho * lc * (qa2 * lc * dv * dv - qb_ * c * dv) : 0.0;
    const double qv = comp ? qb_ * c + qa2 * lc * (-dv) : 0.0;
    const double s0 = b.s_new[0][l], s1 = b.s_new[1][l], s2 = b.s_new[2][l];
    const double s3 = b.s_new[3][l], s4 = b.s_new[4][l], s5 = b.s_new[5][l];
    const double p_new = s0 * d0 + s1 * d1 + s2 * d2 + 2.0 * (s3 * b.d[3][l] + s4 * b.d[4][l] + s5 * b.d[5][l]);
    b.de[l] = (0.5 * (b.de[l] + p_new) - 0.5 * (b.q_old[l] + q) * dv) * b.Vm[l] * dt;
    b.q_old[l] = q;
    const double sxx = s0 - q, syy = s1 - q, szz = s2 - q;
    double txx = 0, tyy = 0, tzz = 0, txy = 0, tyz = 0, tzx = 0;
    for (int i = 0; i < 4; ++i) {
      const double gx = b.bx[i][l], gy = b.by[i][l], gz = b.bz[i][l];
      b.fx[i][l] = -(sxx * gx + s3 * gy + s5 * gz) * b.ok[l];
      b.fy[i][l] = -(s3 * gx + syy * gy + s4 * gz) * b.ok[l];
      b.fz[i][l] = -(s5 * gx + s4 * gy + szz * gz) * b.ok[l];
      txx += gx * gx; tyy += gy * gy; tzz += gz * gz;
      txy += gx * gy; tyz += gy * gz; tzx += gz * gx;
    }
    // Rayleigh quotient of the dilatational mode (compute_tetra_scalar).
    const double iv2 = inv_v * inv_v;
    const double trT = (txx + tyy + tzz) * iv2;
    const double TT = (txx * txx + tyy * tyy + tzz * tzz + 2.0 * (txy * txy + tyz * tyz + tzx * tzx)) * iv2 * iv2;
    b.omega[l] = 4.0 * (lambda * trT * trT + 2.0 * G * TT) / (rho * trT);  // omega^2
    b.qv[l] = qv;
    b.cq[l] = qv * qv + c * c;
  }
  lanes::sqrt_lanes(n, b.omega);
  lanes::sqrt_lanes(n, b.cq);
  for (std::size_t l = 0; l < n; ++l) {
    const double l_eff = 2.0 * b.c[l] / b.omega[l];
    const double dte = l_eff / (b.qv[l] + b.cq[l]);
    b.dte[l] = dte;
    b.ks[l] = b.ok[l] * 2.0 * (b.mass[l] / 4.0) / (dte * dte);
  }
  // Write back (masked lanes keep their state), switch, slots, reductions in element order.
  double sum_int = e_int_inc, step_min = dt_min;
  Index step_elem = dt_elem;
  for (std::size_t l = 0; l < n; ++l) {
    const std::size_t e = e0 + l, s0 = e * 4;
    for (int i = 0; i < 4; ++i) {
      slot_force.x[s0 + i] = b.fx[i][l];
      slot_force.y[s0 + i] = b.fy[i][l];
      slot_force.z[s0 + i] = b.fz[i][l];
      slot_stiffness[s0 + i] = b.ks[l];
    }
    if (b.ok[l] == 0.0) continue;
    for (int k = 0; k < 6; ++k) sig[k][e] = b.sig[k][l];
    if (visco)
      for (int k = 0; k < 6; ++k) hist[k][e] = b.hist[k][l];
    q_bulk[e] = b.q_old[l];
    e_int[e] += b.de[l];
    sum_int += b.de[l];
    if (b.dte[l] < step_min) {
      step_min = b.dte[l];
      step_elem = static_cast<Index>(e);
    }
    if (b.mv[l] != 0.0 && small_strain.enabled && small_strain.triggers(b.dte[l], b.V[l] / volume0[e])) {
      double* xf = &frozen_geometry.x[e * 12];
      for (int i = 0; i < 4; ++i) {
        xf[3 * i] = b.x[i][l]; xf[3 * i + 1] = b.y[i][l]; xf[3 * i + 2] = b.z[i][l];
      }
      frozen_geometry.frozen[e] = 1;
    }
  }
  e_int_inc = sum_int;
  dt_min = step_min;
  dt_elem = step_elem;
}

// Tetras e_begin .. e_end-1 element by element (all laws; the plastic ones use it).
void SolidGroup::compute_tetra_scalar(std::size_t e_begin, std::size_t e_end, const StepContext& step,
                                      const NodalState& nodes, double& e_int_inc, double& dt_min, Index& dt_elem,
                                      Index& inverted) {
  constexpr int NPE = 4;
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
    double x[4], y[4], z[4], vx[4], vy[4], vz[4];
    for (int i = 0; i < NPE; ++i) {
      const auto k = static_cast<std::size_t>(connectivity[s0 + i]);
      x[i] = nodes.x.x[k]; y[i] = nodes.x.y[k]; z[i] = nodes.x.z[k];
      vx[i] = nodes.v.x[k]; vy[i] = nodes.v.y[k]; vz[i] = nodes.v.z[k];
    }
    const bool frozen = frozen_geometry.active() && frozen_geometry.frozen[e];
    if (frozen) {  // small strain: the shape at the switch (small_strain_switch.hpp)
      const double* xf = &frozen_geometry.x[e * 12];
      for (int i = 0; i < NPE; ++i) {
        x[i] = xf[3 * i]; y[i] = xf[3 * i + 1]; z[i] = xf[3 * i + 2];
      }
    }
    double bx[4], by[4], bz[4], V = 0.0, amax = 0.0;
    tetra_volume_gradient(x, y, z, bx, by, bz, V, amax);
    const double l = 3.0 * V / amax;
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
      double xm[4], ym[4], zm[4], mx[4], my[4], mz[4], vm = V, am = 0.0;
      const double* gx = bx;
      const double* gy = by;
      const double* gz = bz;
      if (dt > 0.0 && !frozen) {
        for (int i = 0; i < NPE; ++i) {
          xm[i] = x[i] - 0.5 * dt * vx[i];
          ym[i] = y[i] - 0.5 * dt * vy[i];
          zm[i] = z[i] - 0.5 * dt * vz[i];
        }
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
      const SolidPointState st{s_el, visco ? h : nullptr, plastic ? &ep : nullptr,
                               eps_rate.empty() ? nullptr : &eps_rate[e]};
      if (nodal_pressure.enabled && !frozen) {
        // Deviator from the element, mean stress K ln J from the nodes (nodal_pressure_average.hpp).
        // A switched tetra goes on from its stress at the switch with its own strain rate
        // (small strain: tr D of the frozen shape), its nodal volume share kept at the switch.
        const double third = (d[0] + d[1] + d[2]) / 3.0;
        const double d_dev[6] = {d[0] - third, d[1] - third, d[2] - third, d[3], d[4], d[5]};
        update_solid_stress(mat, st, d_dev, wxy, wyz, wzx, dt, s_new);
        const double shift = mat.K * nodal_pressure.mean_log_j(e) - (s_el[0] + s_el[1] + s_el[2]) / 3.0;
        for (int k = 0; k < 3; ++k) {
          s_el[k] += shift;
          s_new[k] += shift;
        }
      } else {
        update_solid_stress(mat, st, d, wxy, wyz, wzx, dt, s_new);
      }
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
    double fx[4], fy[4], fz[4];
    for (int i = 0; i < NPE; ++i) {
      fx[i] = -(sxx * bx[i] + sxy * by[i] + szx * bz[i]);
      fy[i] = -(sxy * bx[i] + syy * by[i] + syz * bz[i]);
      fz[i] = -(szx * bx[i] + syz * by[i] + szz * bz[i]);
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
    if (!frozen && small_strain.enabled && small_strain.triggers(dte, V / volume0[e])) {
      double* xf = &frozen_geometry.x[e * 12];
      for (int i = 0; i < NPE; ++i) {
        xf[3 * i] = x[i]; xf[3 * i + 1] = y[i]; xf[3 * i + 2] = z[i];
      }
      frozen_geometry.frozen[e] = 1;
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

// One chunk of 8-node bricks, in batches of BrickLanes::W elements (lanes).
void SolidGroup::compute_brick_chunk(std::size_t chunk, const StepContext& step, const NodalState& nodes,
                                     double& e_int_inc, double& e_hg_inc, double& dt_min, Index& dt_elem,
                                     Index& inverted) {
  const std::size_t e_begin = chunk * kChunk, e_end = std::min(n_elements, e_begin + kChunk);
  for (std::size_t e0 = e_begin; e0 < e_end; e0 += BrickLanes::W) {
    const std::size_t n = std::min(BrickLanes::W, e_end - e0);
    if (n == BrickLanes::W)
      compute_brick_lanes(e0, std::integral_constant<std::size_t, BrickLanes::W>{}, step, nodes, e_int_inc,
                          e_hg_inc, dt_min, dt_elem, inverted);
    else
      compute_brick_lanes(e0, n, step, nodes, e_int_inc, e_hg_inc, dt_min, dt_elem, inverted);
  }
}

// Elements e0 .. e0+n-1 (n <= BrickLanes::W) as lanes: element e0 + l is lane l. Lanes of
// deleted or inverted elements are computed like the others and masked on output (ok = 0:
// state kept, zero slot force and stiffness), so no stage branches on the lane.
// A full batch passes its lane count as a compile-time constant (the same arithmetic per
// lane either way).
template <class LaneCount>
void SolidGroup::compute_brick_lanes(std::size_t e0, LaneCount lane_count, const StepContext& step,
                                     const NodalState& nodes, double& e_int_inc, double& e_hg_inc,
                                     double& dt_min, Index& dt_elem, Index& inverted) {
  const std::size_t n = lane_count;
  static thread_local BrickLanes lanes;
  BrickLanes& b = lanes;
  const double dt = step.dt_prev;
  const SolidMaterial& mat = material;
  const bool visco = mat.viscoelastic(), plastic = mat.plastic();
  const double M = mat.wave_modulus();

  // Gather nodal x, v and the element state.
  for (std::size_t l = 0; l < n; ++l) {
    const Index* conn = &connectivity[(e0 + l) * 8];
    for (int i = 0; i < 8; ++i) {
      const auto k = static_cast<std::size_t>(conn[i]);
      b.x[i][l] = nodes.x.x[k]; b.y[i][l] = nodes.x.y[k]; b.z[i][l] = nodes.x.z[k];
      b.vx[i][l] = nodes.v.x[k]; b.vy[i][l] = nodes.v.y[k]; b.vz[i][l] = nodes.v.z[k];
    }
  }
  std::fill_n(b.mv, n, 1.0);
  if (frozen_geometry.active())
    for (std::size_t l = 0; l < n; ++l) {
      if (!frozen_geometry.frozen[e0 + l]) continue;
      const double* xf = &frozen_geometry.x[(e0 + l) * 24];
      for (int i = 0; i < 8; ++i) {
        b.x[i][l] = xf[3 * i]; b.y[i][l] = xf[3 * i + 1]; b.z[i][l] = xf[3 * i + 2];
      }
      b.mv[l] = 0.0;
    }
  for (int k = 0; k < 6; ++k) lanes::copy_lanes(n, sig[k].data() + e0, b.sig[k]);
  if (visco)
    for (int k = 0; k < 6; ++k) lanes::copy_lanes(n, hist[k].data() + e0, b.hist[k]);
  else
    for (int k = 0; k < 6; ++k) std::fill_n(b.hist[k], n, 0.0);
  for (int k = 0; k < 12; ++k) lanes::copy_lanes(n, hg[k].data() + e0, b.hg[k]);
  if (hourglass == HourglassForm::Physical)
    for (int k = 0; k < 12; ++k) lanes::copy_lanes(n, hg_visc[k].data() + e0, b.hgv[k]);
  lanes::copy_lanes(n, mass.data() + e0, b.mass);
  lanes::copy_lanes(n, q_bulk.data() + e0, b.q_old);
  lanes::copy_lanes(n, e_int.data() + e0, b.e_int);

  brick::volume_gradient_lanes(lane_count, b.x, b.y, b.z, b.bx, b.by, b.bz, b.V, b.amax2);
  mask_lanes(b, lane_count, alive, e0, inverted);

  // Velocity gradient L_ij = sum_I v_iI B_jI on the mid-step configuration
  // x^{n-1/2} = x^n - dt/2 v^{n-1/2} (second-order accurate strain increment; the stress
  // work then matches the trapezoidal work of the nodal forces). A lane whose mid-step
  // volume is not positive uses the current configuration.
  if (dt > 0.0) {
    mid_step_coordinates<8>(b, lane_count, 0.5 * dt);
    brick::volume_gradient_lanes(lane_count, b.fx, b.fy, b.fz, b.mx, b.my, b.mz, b.Vm, b.amid2);
  }
  settle_mid_step_gradient<8>(b, lane_count, dt > 0.0);
  for (int k = 0; k < 9; ++k) std::fill_n(b.L[k], n, 0.0);
  for (int i = 0; i < 8; ++i)
    for (std::size_t l = 0; l < n; ++l) {
      b.L[0][l] += b.vx[i][l] * b.mx[i][l]; b.L[1][l] += b.vx[i][l] * b.my[i][l]; b.L[2][l] += b.vx[i][l] * b.mz[i][l];
      b.L[3][l] += b.vy[i][l] * b.mx[i][l]; b.L[4][l] += b.vy[i][l] * b.my[i][l]; b.L[5][l] += b.vy[i][l] * b.mz[i][l];
      b.L[6][l] += b.vz[i][l] * b.mx[i][l]; b.L[7][l] += b.vz[i][l] * b.my[i][l]; b.L[8][l] += b.vz[i][l] * b.mz[i][l];
    }
  for (std::size_t l = 0; l < n; ++l) {
    const double iv = 1.0 / b.Vm[l];
    const double L00 = b.L[0][l] * iv, L01 = b.L[1][l] * iv, L02 = b.L[2][l] * iv;
    const double L10 = b.L[3][l] * iv, L11 = b.L[4][l] * iv, L12 = b.L[5][l] * iv;
    const double L20 = b.L[6][l] * iv, L21 = b.L[7][l] * iv, L22 = b.L[8][l] * iv;
    b.d[0][l] = L00; b.d[1][l] = L11; b.d[2][l] = L22;
    b.d[3][l] = 0.5 * (L01 + L10); b.d[4][l] = 0.5 * (L12 + L21); b.d[5][l] = 0.5 * (L20 + L02);
    b.w[0][l] = 0.5 * (L01 - L10); b.w[1][l] = 0.5 * (L12 - L21); b.w[2][l] = 0.5 * (L20 - L02);
  }

  // Stress update over dt^{n-1/2} (solid_material.hpp). Old total stress power first, for
  // the trapezoidal internal energy below (stored in de).
  for (std::size_t l = 0; l < n; ++l) {
    double s[6];
    for (int k = 0; k < 6; ++k) s[k] = b.sig[k][l] + b.hist[k][l];
    b.de[l] = s[0] * b.d[0][l] + s[1] * b.d[1][l] + s[2] * b.d[2][l] +
              2.0 * (s[3] * b.d[3][l] + s[4] * b.d[4][l] + s[5] * b.d[5][l]);
  }
  if (!(dt > 0.0)) {
    for (int k = 0; k < 6; ++k)
      for (std::size_t l = 0; l < n; ++l) b.s_new[k][l] = b.sig[k][l] + b.hist[k][l];
  } else if (mat.law == SolidLaw::Elastic || visco) {
    // LAW1 and LAW34 over the lanes (HypoelasticStep, solid_material.hpp).
    const HypoelasticStep law(mat, dt);
    for (std::size_t l = 0; l < n; ++l) {
      const double s[6] = {b.sig[0][l], b.sig[1][l], b.sig[2][l], b.sig[3][l], b.sig[4][l], b.sig[5][l]};
      const double h[6] = {b.hist[0][l], b.hist[1][l], b.hist[2][l], b.hist[3][l], b.hist[4][l], b.hist[5][l]};
      const double d[6] = {b.d[0][l], b.d[1][l], b.d[2][l], b.d[3][l], b.d[4][l], b.d[5][l]};
      double sn[6], hn[6];
      law.apply(s, h, d, b.w[0][l], b.w[1][l], b.w[2][l], 1.0, 0.0, sn, hn);
      for (int k = 0; k < 6; ++k) {
        b.sig[k][l] = sn[k];
        b.hist[k][l] = hn[k];
        b.s_new[k][l] = sn[k] + hn[k];
      }
    }
  } else {
    // LAW2 / LAW36: radial return per lane (scalar).
    for (std::size_t l = 0; l < n; ++l) {
      if (b.ok[l] == 0.0) {
        for (int k = 0; k < 6; ++k) b.s_new[k][l] = b.sig[k][l];
        continue;
      }
      double s[6], out[6], ep = eps_p[e0 + l];
      for (int k = 0; k < 6; ++k) s[k] = b.sig[k][l];
      const double dd[6] = {b.d[0][l], b.d[1][l], b.d[2][l], b.d[3][l], b.d[4][l], b.d[5][l]};
      const SolidPointState st{s, nullptr, &ep, eps_rate.empty() ? nullptr : &eps_rate[e0 + l]};
      update_solid_stress(mat, st, dd, b.w[0][l], b.w[1][l], b.w[2][l], dt, out);
      for (int k = 0; k < 6; ++k) {
        b.sig[k][l] = s[k];
        b.s_new[k][l] = out[k];
      }
      eps_p[e0 + l] = ep;
      if (ep >= mat.plasticity.eps_p_max) alive[e0 + l] = 2;  // deleted after this cycle
    }
  }

  // Density, wave speed, characteristic length V / largest face area and V^(2/3) (square
  // and cube roots as vector code, lane_vector_ops.hpp).
  for (std::size_t l = 0; l < n; ++l) {
    b.rho[l] = b.mass[l] / b.V[l];
    b.c[l] = M / b.rho[l];
  }
  lanes::copy_lanes(n, b.amax2, b.tmp);
  lanes::sqrt_lanes(n, b.c);
  lanes::sqrt_lanes(n, b.tmp);
  for (std::size_t l = 0; l < n; ++l) b.lc[l] = b.V[l] / (4.0 * b.tmp[l]);
  if (hourglass != HourglassForm::Stiffness) {
    for (std::size_t l = 0; l < n; ++l) b.tmp[l] = b.V[l] * b.V[l];
    lanes::cbrt_lanes(n, b.tmp, b.v23);
  }

  // Bulk viscosity (compression only): q = rho l (qa^2 l dv^2 - qb c dv), dv = tr D < 0.
  // Internal energy: trapezoidal stress power 0.5 ((s - q I)^{n-1} + (s - q I)^n):D V dt
  // (all energies use this trapezoidal form so that they telescope with the kinetic
  // energy of the central difference scheme, see account_energies).
  // Internal forces: f_iI = -(sigma_ij - q delta_ij) b_jI  (b = V B).
  const double qa2 = qa * qa, qb_ = qb;  // locals: the lane stores cannot alias them
  for (std::size_t l = 0; l < n; ++l) {
    const double rho = b.rho[l], c = b.c[l], lc = b.lc[l];
    const double d0 = b.d[0][l], d1 = b.d[1][l], d2 = b.d[2][l], d3 = b.d[3][l], d4 = b.d[4][l], d5 = b.d[5][l];
    const double dv = d0 + d1 + d2;
    const bool comp = dv < 0.0;
    const double q = comp ? rho * lc * (qa2 * lc * dv * dv - qb_ * c * dv) : 0.0;
    b.qv[l] = comp ? qb_ * c + qa2 * lc * (-dv) : 0.0;
    const double s0 = b.s_new[0][l], s1 = b.s_new[1][l], s2 = b.s_new[2][l];
    const double sxy = b.s_new[3][l], syz = b.s_new[4][l], szx = b.s_new[5][l];
    const double p_new = s0 * d0 + s1 * d1 + s2 * d2 + 2.0 * (sxy * d3 + syz * d4 + szx * d5);
    b.de[l] = (0.5 * (b.de[l] + p_new) - 0.5 * (b.q_old[l] + q) * dv) * b.Vm[l] * dt;
    b.q[l] = q;
    b.s_new[0][l] = s0 - q;
    b.s_new[1][l] = s1 - q;
    b.s_new[2][l] = s2 - q;
  }
  for (int i = 0; i < 8; ++i)
    for (std::size_t l = 0; l < n; ++l) {
      const double sxx = b.s_new[0][l], syy = b.s_new[1][l], szz = b.s_new[2][l];
      const double sxy = b.s_new[3][l], syz = b.s_new[4][l], szx = b.s_new[5][l];
      b.fx[i][l] = -(sxx * b.bx[i][l] + sxy * b.by[i][l] + szx * b.bz[i][l]);
      b.fy[i][l] = -(sxy * b.bx[i][l] + syy * b.by[i][l] + syz * b.bz[i][l]);
      b.fz[i][l] = -(szx * b.bx[i][l] + syz * b.by[i][l] + szz * b.bz[i][l]);
    }

  // FB hourglass projection gamma_alpha,I = h_alpha,I - (sum_J h_alpha,J x_J) . B_I and
  // hourglass velocities q_alpha = sum_I v_I gamma_alpha,I.
  for (int a = 0; a < 4; ++a) {
    const double* ha = brick::kHourglass[a];
    for (std::size_t l = 0; l < n; ++l) {
      double hx = 0.0, hy = 0.0, hz = 0.0;
      for (int i = 0; i < 8; ++i) {
        hx += ha[i] * b.x[i][l];
        hy += ha[i] * b.y[i][l];
        hz += ha[i] * b.z[i][l];
      }
      const double iv = 1.0 / b.V[l];
      double qx = 0.0, qy = 0.0, qz = 0.0;
      for (int i = 0; i < 8; ++i) {
        const double gai = ha[i] - (hx * b.bx[i][l] + hy * b.by[i][l] + hz * b.bz[i][l]) * iv;
        b.gam[a][i][l] = gai;
        qx += b.vx[i][l] * gai;
        qy += b.vy[i][l] * gai;
        qz += b.vz[i][l] * gai;
      }
      b.qx[a][l] = qx; b.qy[a][l] = qy; b.qz[a][l] = qz;
    }
  }
  std::fill_n(b.p_int, n, 0.0);
  if (hourglass == HourglassForm::Viscous) {
    // f = -c q gamma, c = h rho c_wave V^(2/3) / 4 (FB 1981); trapezoidal work.
    const double cf = hourglass_coef * 0.25;
    for (std::size_t l = 0; l < n; ++l) {
      const double cv = cf * b.rho[l] * b.c[l] * b.v23[l];
      double p = 0.0;
      for (int a = 0; a < 4; ++a) {
        const double Qx = cv * b.qx[a][l], Qy = cv * b.qy[a][l], Qz = cv * b.qz[a][l];
        p += 0.5 * ((b.hg[a][l] + Qx) * b.qx[a][l] + (b.hg[4 + a][l] + Qy) * b.qy[a][l] +
                    (b.hg[8 + a][l] + Qz) * b.qz[a][l]);
        b.Qx[a][l] = Qx; b.Qy[a][l] = Qy; b.Qz[a][l] = Qz;
        b.hg[a][l] = Qx; b.hg[4 + a][l] = Qy; b.hg[8 + a][l] = Qz;
      }
      b.p_hg[l] = p * dt;
    }
  } else if (hourglass == HourglassForm::Stiffness) {
    // Q += k q dt, k = h (lambda + 2G) V (B:B) / 8.
    const double kf = hourglass_coef * (mat.lambda + 2.0 * mat.G) / 8.0;
    for (std::size_t l = 0; l < n; ++l) {
      double bb = 0.0;
      for (int i = 0; i < 8; ++i) bb += b.bx[i][l] * b.bx[i][l] + b.by[i][l] * b.by[i][l] + b.bz[i][l] * b.bz[i][l];
      const double kdt = kf * bb / b.V[l] * dt;
      double p = 0.0;
      for (int a = 0; a < 4; ++a) {
        const double ox = b.hg[a][l], oy = b.hg[4 + a][l], oz = b.hg[8 + a][l];
        const double Qx = ox + kdt * b.qx[a][l], Qy = oy + kdt * b.qy[a][l], Qz = oz + kdt * b.qz[a][l];
        b.Qx[a][l] = Qx; b.Qy[a][l] = Qy; b.Qz[a][l] = Qz;
        b.hg[a][l] = Qx; b.hg[4 + a][l] = Qy; b.hg[8 + a][l] = Qz;
        p += 0.5 * ((ox + Qx) * b.qx[a][l] + (oy + Qy) * b.qy[a][l] + (oz + Qz) * b.qz[a][l]);
      }
      b.p_hg[l] = p * dt;
    }
  } else {
    physical_hourglass_lanes(b, n, dt, mat.G, physical_coefficients(),
                             physical_coefficients().viscous * hourglass_coef * 0.25);
  }
  for (int i = 0; i < 8; ++i)
    for (std::size_t l = 0; l < n; ++l) {
      double fx = b.fx[i][l], fy = b.fy[i][l], fz = b.fz[i][l];
      for (int a = 0; a < 4; ++a) {
        fx -= b.Qx[a][l] * b.gam[a][i][l];
        fy -= b.Qy[a][l] * b.gam[a][i][l];
        fz -= b.Qz[a][l] * b.gam[a][i][l];
      }
      b.fx[i][l] = fx; b.fy[i][l] = fy; b.fz[i][l] = fz;
    }

  // Critical step: highest element frequency estimated by the Rayleigh quotient of the
  // dilatational mode u_I = B_I (exact for a box): with T = sum_I B_I (x) B_I,
  // omega^2 = n (lambda tr(T)^2 + 2 G T:T) / (rho tr(T)); dt = 2 / omega, i.e. an
  // effective length l_eff = 2 c / omega, reduced by bulk viscosity:
  // dt = l_eff / (Q + sqrt(Q^2 + c^2)).
  const double lambda = mat.lambda, two_G = 2.0 * mat.G;
  for (std::size_t l = 0; l < n; ++l) {
    double txx = 0, tyy = 0, tzz = 0, txy = 0, tyz = 0, tzx = 0;
    for (int i = 0; i < 8; ++i) {
      txx += b.bx[i][l] * b.bx[i][l]; tyy += b.by[i][l] * b.by[i][l]; tzz += b.bz[i][l] * b.bz[i][l];
      txy += b.bx[i][l] * b.by[i][l]; tyz += b.by[i][l] * b.bz[i][l]; tzx += b.bz[i][l] * b.bx[i][l];
    }
    const double iv = 1.0 / b.V[l];
    const double iv2 = iv * iv;
    const double trT = (txx + tyy + tzz) * iv2;
    const double TT = (txx * txx + tyy * tyy + tzz * tzz + 2.0 * (txy * txy + tyz * tyz + tzx * tzx)) * iv2 * iv2;
    b.dte[l] = 8.0 * (lambda * trT * trT + two_G * TT) / (b.rho[l] * trT);  // omega^2
    b.tmp[l] = b.qv[l] * b.qv[l] + b.c[l] * b.c[l];
  }
  lanes::sqrt_lanes(n, b.dte);
  lanes::sqrt_lanes(n, b.tmp);
  for (std::size_t l = 0; l < n; ++l) b.dte[l] = (2.0 * b.c[l] / b.dte[l]) / (b.qv[l] + b.tmp[l]);
  // Slot stiffness 2 m_I / dt^2 (in tmp: a vectorised loop before the indexed scatter).
  for (std::size_t l = 0; l < n; ++l) b.tmp[l] = b.ok[l] * 2.0 * (b.mass[l] / 8.0) / (b.dte[l] * b.dte[l]);

  // Hourglass viscosity limit. The viscous hourglass force -c sum_a gamma_a (gamma_a . v) is
  // a damper with matrix c sum_a gamma_a gamma_a^T, whose largest eigenvalue lambda is c times
  // that of the 4 x 4 Gram matrix gamma_a . gamma_b, bounded by its largest absolute row sum
  // (Gershgorin). Central differences with the damping force on v^{n-1/2} stay stable while
  // dt <= 2 m / lambda, m the nodal mass (here only this element's share m_e / 8:
  // conservative). For a parallelepiped the Gram matrix is 8 I and this step is about twice
  // the dilatational one, so it does not bind; a brick sheared and warped far out of shape
  // reaches row sums ~ 10^3 (hub_oblique_9p5, flesh at the impactor rim, 16 ms), which
  // without this limit turned unstable at 1.5 us with no added mass (engine-design.md §12.3).
  // Where it binds, the element step is 2 (m_e / 8) / lambda, and its slot stiffness for
  // mass scaling is the damper's equivalent at the present step, 2 lambda / dt: the nodal
  // step sqrt(2 m / k) then asks for m >= lambda dt / Tsca^2 (the damper needs lambda dt / 2),
  // linear in the step as a damper is, instead of the quadratic need of a spring.
  if (hourglass != HourglassForm::Stiffness) {
    const double cf = hourglass_coef * 0.25 * (hourglass == HourglassForm::Physical ? physical_coefficients().viscous : 1.0);
    for (std::size_t l = 0; l < n; ++l) {
      double g00 = 0, g01 = 0, g02 = 0, g03 = 0, g11 = 0, g12 = 0, g13 = 0, g22 = 0, g23 = 0, g33 = 0;
#pragma GCC unroll 8
      for (int i = 0; i < 8; ++i) {
        const double a0 = b.gam[0][i][l], a1 = b.gam[1][i][l], a2 = b.gam[2][i][l], a3 = b.gam[3][i][l];
        g00 += a0 * a0; g01 += a0 * a1; g02 += a0 * a2; g03 += a0 * a3;
        g11 += a1 * a1; g12 += a1 * a2; g13 += a1 * a3;
        g22 += a2 * a2; g23 += a2 * a3; g33 += a3 * a3;
      }
      g01 = std::abs(g01); g02 = std::abs(g02); g03 = std::abs(g03);
      g12 = std::abs(g12); g13 = std::abs(g13); g23 = std::abs(g23);
      const double row_max = std::max(std::max(g00 + g01 + g02 + g03, g01 + g11 + g12 + g13),
                                      std::max(g02 + g12 + g22 + g23, g03 + g13 + g23 + g33));
      const double lam = cf * b.rho[l] * b.c[l] * b.v23[l] * row_max;
      const double dte_hg = 0.25 * b.mass[l] / lam;  // +inf (no binding) when lam = 0
      const double k_spring = 0.25 * b.mass[l] / (b.dte[l] * b.dte[l]);
      const double k_damper = dt > 0.0 ? std::max(k_spring, 2.0 * lam / dt) : 0.25 * b.mass[l] / (dte_hg * dte_hg);
      const bool binds = dte_hg < b.dte[l];
      b.tmp[l] = binds && b.ok[l] != 0.0 ? k_damper : b.tmp[l];
      b.dte[l] = binds ? dte_hg : b.dte[l];
    }
  }

  // Scatter to the slots and write the state back (masked lanes: zero slots, state kept).
  for (std::size_t l = 0; l < n; ++l) {
    const std::size_t s0 = (e0 + l) * 8;
    const double k_slot = b.tmp[l];
    const bool ok = b.ok[l] != 0.0;
    for (int i = 0; i < 8; ++i) {
      slot_force.x[s0 + i] = ok ? b.fx[i][l] : 0.0;
      slot_force.y[s0 + i] = ok ? b.fy[i][l] : 0.0;
      slot_force.z[s0 + i] = ok ? b.fz[i][l] : 0.0;
      slot_stiffness[s0 + i] = ok ? k_slot : 0.0;
    }
  }
  const auto keep = [&](std::vector<double>& dst, const double* src) {
    double* out = dst.data() + e0;
    for (std::size_t l = 0; l < n; ++l) out[l] = b.ok[l] != 0.0 ? src[l] : out[l];
  };
  if (plastic || dt > 0.0)
    for (int k = 0; k < 6; ++k) keep(sig[k], b.sig[k]);
  if (visco && dt > 0.0)
    for (int k = 0; k < 6; ++k) keep(hist[k], b.hist[k]);
  for (int k = 0; k < 12; ++k) keep(hg[k], b.hg[k]);
  if (hourglass == HourglassForm::Physical)
    for (int k = 0; k < 12; ++k) keep(hg_visc[k], b.hgv[k]);
  keep(q_bulk, b.q);
  for (std::size_t l = 0; l < n; ++l) b.e_int[l] = (b.e_int[l] + b.de[l]) + b.p_int[l];
  keep(e_int, b.e_int);
  for (std::size_t l = 0; l < n; ++l)
    if (b.ok[l] != 0.0) e_hg[e0 + l] += b.p_hg[l];
  // /DT/BRICK/CST: a lane whose step fell to Tmin (or volume ratio to VDEF_min) keeps its
  // present geometry from the next cycle on (small_strain_switch.hpp).
  if (frozen_geometry.active())
    for (std::size_t l = 0; l < n; ++l) {
      const std::size_t e = e0 + l;
      if (b.ok[l] == 0.0 || frozen_geometry.frozen[e] || !small_strain.triggers(b.dte[l], b.V[l] / volume0[e]))
        continue;
      double* xf = &frozen_geometry.x[e * 24];
      for (int i = 0; i < 8; ++i) {
        xf[3 * i] = b.x[i][l]; xf[3 * i + 1] = b.y[i][l]; xf[3 * i + 2] = b.z[i][l];
      }
      frozen_geometry.frozen[e] = 1;
    }
  // Reductions in element order (the same sums whatever the thread count), in locals: the
  // reference arguments would be stored on every lane.
  double sum_int = e_int_inc, sum_hg = e_hg_inc, step_min = dt_min;
  Index step_elem = dt_elem;
  for (std::size_t l = 0; l < n; ++l) {
    if (b.ok[l] == 0.0) continue;
    sum_int += b.de[l];
    sum_int += b.p_int[l];
    sum_hg += b.p_hg[l];
    if (b.dte[l] < step_min) {
      step_min = b.dte[l];
      step_elem = static_cast<Index>(e0 + l);
    }
  }
  e_int_inc = sum_int;
  e_hg_inc = sum_hg;
  dt_min = step_min;
  dt_elem = step_elem;
}

// Per-chunk sums of the last compute_forces, reduced in chunk order by end_forces
// (independent of the thread that ran a chunk).
void SolidGroup::begin_forces(const StepContext& /*step*/, const NodalState& nodes) {
  chunk_sums_.assign(n_chunks(n_elements), ChunkSums{});
  if (nodal_pressure.enabled) nodal_pressure.update(nodes, connectivity, alive, frozen_geometry);
}

void SolidGroup::force_chunk(std::size_t ch, const StepContext& step, const NodalState& nodes) {
  ChunkSums& c = chunk_sums_[ch];
  if (nodes_per_element == 8)
    compute_brick_chunk(ch, step, nodes, c.e_int, c.e_hg, c.dt, c.dt_elem, c.inverted);
  else
    compute_tetra_chunk(ch, step, nodes, c.e_int, c.dt, c.dt_elem, c.inverted);
}

void SolidGroup::end_forces(GroupStepResult& result) {
  for (const ChunkSums& c : chunk_sums_) {
    energy.internal += c.e_int;
    energy.hourglass += c.e_hg;
    if (c.dt < result.dt_min) {
      result.dt_min = c.dt;
      result.dt_element = c.dt_elem;
    }
    if (result.inverted_element == kNoIndex && c.inverted != kNoIndex)
      result.inverted_element = c.inverted;
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

void SolidGroup::compute_forces(const StepContext& step, const NodalState& nodes,
                                GroupStepResult& result) {
  begin_forces(step, nodes);
  const std::size_t nch = chunk_sums_.size();
  // 8 = kSmallGroupChunks (cycle.cpp): smaller groups run on one thread.
  parallel_loop(nch, nch >= 8, [&](std::size_t ch) { force_chunk(ch, step, nodes); }, chunk_thread);
  end_forces(result);
}

}  // namespace hbm::solver
