// SPDX-License-Identifier: GPL-3.0-or-later
// 4-node Belytschko-Tsay shell (Belytschko, Lin & Tsay 1984, "Explicit algorithms for
// the nonlinear dynamics of shells", CMAME 42: 225-251), one in-plane integration point,
// Mindlin kinematics in a corotational frame, rate form:
//   d_xx = B1I vxI + z B1I thyI,  d_yy = B2I vyI - z B2I thxI,
//   2d_xy = B2I vxI + B1I vyI + z (B2I thyI - B1I thxI),
//   2d_xz = B1I vzI + thyI/4,      2d_yz = B2I vzI - thxI/4,
// B1 = (y24, y31, y42, y13)/(2A), B2 = (x42, x13, x24, x31)/(2A) in the local frame
// e3 = r31 x r42 / |.|, e1 along r21 projected, e2 = e3 x e1. Rates on the mid-step
// geometry x^{n-1/2} (rigid rotations strain nothing), forces on the current geometry
// x^n (frame, B, gamma, warping again there): the work 0.5 (f^{n-1} + f^n) . v^{n-1/2} dt
// then equals the energy increment to second order (docs/engine-design.md, shells).
//
// Warped elements (Belytschko, Wong & Chiang 1989, "Improvements in low-order shell
// elements for explicit transient analysis", CMAME 73: 223-239): each node sits at a
// height zI above the element's reference plane; the element works on the projected
// points, tied to the nodes by rigid links: v_proj = v - zI (thy e1 - thx e2), and the
// in-plane nodal forces act on the nodes with the moments of the links
// (my -= zI fx, mx += zI fy).
//
// Hourglass control, stiffness form with the /PROP/TYPE1 coefficients, gamma_I =
// h_I - (h.x) B1I - (h.y) B2I, h = (1,-1,1,-1) (Belytschko-Tsay 1984 / Flanagan &
// Belytschko 1981), stiffness per mode with S = A (B1.B1 + B2.B2):
//   membrane   Q_x,y += Hm E t S        gamma.v_x,y dt
//   rotation   Q_thx,thy += Hr E t^3/12 S  gamma.th_x,y dt
//   transverse Q_w  += Hf E t^3/12 S/A  gamma.(w + (x thy - y thx)/2) dt.
// The transverse mode is measured on w + (x beta_x + y beta_y)/2 (beta_x = thy,
// beta_y = -thx), which vanishes for every Kirchhoff field of constant curvature, so
// the twist and bending patch tests are passed with Hf > 0 (same idea as the physical
// stabilisation of Belytschko & Leviathan 1994).
//
// Lanes: the elements are computed in batches of QuadLanes::W (element k of the batch
// is lane k); the nodal values and the element state are gathered into [node][lane]
// arrays and every stage is a loop over the lanes that GCC vectorises (-march=native),
// as the brick kernel (solid_group.cpp). Lanes of deleted or folded elements are
// computed like the others on finite stand-in values and masked on output. Each lane
// does the arithmetic of the one-element formulas above in the same order, so the
// results do not depend on the batch nor on the thread count. Square roots sit in loops
// of their own (without -fno-math-errno a sqrt call keeps a loop scalar).
#include "core/lane_vector_ops.hpp"
#include "shells/shell_group_data.hpp"
#include "shells/shell_lane_gather.hpp"
#include "shells/shell_thickness_lanes.hpp"

#include <algorithm>
#include <cmath>

namespace hbm::solver::shells {

namespace {

// One batch of quads as lanes (thread_local, about 45 KB).
struct QuadLanes {
  static constexpr std::size_t W = 32;
  alignas(64) std::int32_t node[4][W];                 // node indices
  alignas(64) double X[4][W], Y[4][W], Z[4][W];        // mid-step positions
  alignas(64) double VX[4][W], VY[4][W], VZ[4][W];     // velocities (global)
  alignas(64) double WX[4][W], WY[4][W], WZ[4][W];     // angular velocities (global)
  alignas(64) double e1[3][W], e2[3][W], e3[3][W];     // local frame
  alignas(64) double x[4][W], y[4][W], zw[4][W];       // local coordinates, warping heights
  alignas(64) double vx[4][W], vy[4][W], vz[4][W], tx[4][W], ty[4][W];  // local rates
  alignas(64) double B1[4][W], B2[4][W], gam[4][W];
  alignas(64) double gxz[W], gyz[W];
  alignas(64) double A[W], ok[W], okf[W], alive[W], sq[W], lmax2[W];
  ThicknessLanes<W> th;                                // strain increments in, resultants out
  alignas(64) double q[7][W];                          // extra: Qx Qy, 5 hourglass forces
  alignas(64) double dEhg[W], dte[W];
  alignas(64) double f[6][W * 4];                      // force, moment ON the nodes, global,
                                                       // slot order (lane * 4 + node)
};

}  // namespace

namespace {

// Local frame e3 = r31 x r42 / |.|, e1 along r21 projected, e2 = e3 x e1, local
// coordinates about the centre (x, y, warping height zw) and area A of the points X Y Z.
void local_geometry(QuadLanes& b, std::size_t n) {
    for (std::size_t l = 0; l < n; ++l) {
      const double r31x = b.X[2][l] - b.X[0][l], r31y = b.Y[2][l] - b.Y[0][l], r31z = b.Z[2][l] - b.Z[0][l];
      const double r42x = b.X[3][l] - b.X[1][l], r42y = b.Y[3][l] - b.Y[1][l], r42z = b.Z[3][l] - b.Z[1][l];
      const double cx = r31y * r42z - r31z * r42y, cy = r31z * r42x - r31x * r42z, cz3 = r31x * r42y - r31y * r42x;
      b.e3[0][l] = cx; b.e3[1][l] = cy; b.e3[2][l] = cz3;
      const double s = cx * cx + cy * cy + cz3 * cz3;
      b.sq[l] = s > 0.0 ? s : 1.0;  // folded to a line: finite stand-in (masked)
    }
    lanes::sqrt_lanes(n, b.sq);
    for (std::size_t l = 0; l < n; ++l) b.sq[l] = 1.0 / b.sq[l];
    for (std::size_t l = 0; l < n; ++l) {
      const double n3 = b.sq[l];
      const double e3x = b.e3[0][l] * n3, e3y = b.e3[1][l] * n3, e3z = b.e3[2][l] * n3;
      b.e3[0][l] = e3x; b.e3[1][l] = e3y; b.e3[2][l] = e3z;
      const double r21x = b.X[1][l] - b.X[0][l], r21y = b.Y[1][l] - b.Y[0][l], r21z = b.Z[1][l] - b.Z[0][l];
      const double d21 = r21x * e3x + r21y * e3y + r21z * e3z;
      const double ax = r21x - d21 * e3x, ay = r21y - d21 * e3y, az = r21z - d21 * e3z;
      b.e1[0][l] = ax; b.e1[1][l] = ay; b.e1[2][l] = az;
      const double s = ax * ax + ay * ay + az * az;
      b.sq[l] = s > 0.0 ? s : 1.0;
    }
    lanes::sqrt_lanes(n, b.sq);
    for (std::size_t l = 0; l < n; ++l) b.sq[l] = 1.0 / b.sq[l];
    for (std::size_t l = 0; l < n; ++l) {
      const double n1 = b.sq[l];
      const double e1x = b.e1[0][l] * n1, e1y = b.e1[1][l] * n1, e1z = b.e1[2][l] * n1;
      b.e1[0][l] = e1x; b.e1[1][l] = e1y; b.e1[2][l] = e1z;
      const double e3x = b.e3[0][l], e3y = b.e3[1][l], e3z = b.e3[2][l];
      b.e2[0][l] = e3y * e1z - e3z * e1y;
      b.e2[1][l] = e3z * e1x - e3x * e1z;
      b.e2[2][l] = e3x * e1y - e3y * e1x;
    }
    for (std::size_t l = 0; l < n; ++l) {
      double xc = 0.25 * b.X[0][l], yc = 0.25 * b.Y[0][l], zc = 0.25 * b.Z[0][l];
      for (int i = 1; i < 4; ++i) {
        xc += 0.25 * b.X[i][l];
        yc += 0.25 * b.Y[i][l];
        zc += 0.25 * b.Z[i][l];
      }
      const double e1x = b.e1[0][l], e1y = b.e1[1][l], e1z = b.e1[2][l];
      const double e2x = b.e2[0][l], e2y = b.e2[1][l], e2z = b.e2[2][l];
      const double e3x = b.e3[0][l], e3y = b.e3[1][l], e3z = b.e3[2][l];
      for (int i = 0; i < 4; ++i) {
        const double d0 = b.X[i][l] - xc, d1 = b.Y[i][l] - yc, d2 = b.Z[i][l] - zc;
        const double xi = d0 * e1x + d1 * e1y + d2 * e1z;
        const double yi = d0 * e2x + d1 * e2y + d2 * e2z;
        const double zi = d0 * e3x + d1 * e3y + d2 * e3z;
        b.x[i][l] = xi; b.y[i][l] = yi; b.zw[i][l] = zi;
      }
      b.A[l] = 0.5 * ((b.x[2][l] - b.x[0][l]) * (b.y[3][l] - b.y[1][l]) -
                      (b.x[3][l] - b.x[1][l]) * (b.y[2][l] - b.y[0][l]));
    }
}

// /DT/SHELL/CST: switched lanes take the in-plane shape frozen at the switch (local x, y,
// area) in the current corotational frame; the frame keeps the orientation of the last
// evaluation (a quad squeezed flat would otherwise flip its normal r31 x r42 and see its
// frozen shape mirrored). Layout of frozen_shape: ShellGroupData.
constexpr std::size_t kArea = ShellGroupData::kFrozenArea, kNormal = ShellGroupData::kFrozenNormal;

void use_frozen_shape(QuadLanes& b, std::size_t n, ShellGroupData& g, const std::int32_t* idx) {
  if (g.frozen.empty()) return;
  for (std::size_t l = 0; l < n; ++l) {
    const auto e = static_cast<std::size_t>(idx[l]);
    if (!g.frozen[e]) continue;
    double* f = g.frozen_values(e);
    if (b.e3[0][l] * f[kNormal] + b.e3[1][l] * f[kNormal + 1] + b.e3[2][l] * f[kNormal + 2] < 0.0) {
      for (int c = 0; c < 3; ++c) {
        b.e3[c][l] = -b.e3[c][l];
        b.e2[c][l] = -b.e2[c][l];
      }
      for (int i = 0; i < 4; ++i) b.zw[i][l] = -b.zw[i][l];
    }
    for (int c = 0; c < 3; ++c) f[kNormal + c] = b.e3[c][l];
    for (int i = 0; i < 4; ++i) {
      b.x[i][l] = f[i];
      b.y[i][l] = f[4 + i];
    }
    b.A[l] = f[kArea];
  }
}

}  // namespace

ShellKernelTotals quad_bt_forces(ShellGroupData& g, const ShellNodalView& nv,
                                 const ShellSlotOut& out, double dt,
                                 std::span<const std::int32_t> elements) {
  ShellKernelTotals tot;
  const ShellMaterial& mat = g.mat;
  const ShellSection& sec = g.sec;
  const int np = sec.n_points;
  const double E = mat.young(), G = mat.shear_modulus();
  const double cwave = g.wave_speed;
  const double hdt = 0.5 * dt;
  static thread_local QuadLanes lanes;
  QuadLanes& b = lanes;
  constexpr std::size_t W = QuadLanes::W;

  for (std::size_t k0 = 0; k0 < elements.size(); k0 += W) {
    const std::size_t n = std::min(W, elements.size() - k0);
    const std::int32_t* idx = elements.data() + k0;
    const bool consecutive = static_cast<std::size_t>(idx[n - 1] - idx[0]) == n - 1;
    // Gather: mid-step geometry x^{n-1/2} = x^n - dt/2 v^{n-1/2} (the velocity gradient
    // of a rigid rotation is then skew, so rotations strain nothing), v, omega, state.
    for (std::size_t l = 0; l < n; ++l) {
      const auto e = static_cast<std::size_t>(idx[l]);
      for (int i = 0; i < 4; ++i) b.node[i][l] = g.conn[e * 4 + static_cast<std::size_t>(i)];
      b.th.t[l] = g.thick[e];
      b.th.nfail[l] = g.n_failed[e];
      const double* ex7 = &g.extra[e * 7];
      for (int c = 0; c < 7; ++c) b.q[c][l] = ex7[c];
    }
    // One nodal field pair at a time (few live pointers: no register spills).
    gather_positions<4>(b, n, nv, hdt);
    gather_spins<4>(b, n, nv);
    // Frame, local coordinates and area on the mid-step geometry; rates.
    local_geometry(b, n);
    use_frozen_shape(b, n, g, idx);
    for (std::size_t l = 0; l < n; ++l) {
      const double e1x = b.e1[0][l], e1y = b.e1[1][l], e1z = b.e1[2][l];
      const double e2x = b.e2[0][l], e2y = b.e2[1][l], e2z = b.e2[2][l];
      const double e3x = b.e3[0][l], e3y = b.e3[1][l], e3z = b.e3[2][l];
      for (int i = 0; i < 4; ++i) {
        const double zi = b.zw[i][l];
        const double wx = b.WX[i][l], wy = b.WY[i][l], wz = b.WZ[i][l];
        const double vgx = b.VX[i][l], vgy = b.VY[i][l], vgz = b.VZ[i][l];
        const double txi = wx * e1x + wy * e1y + wz * e1z;
        const double tyi = wx * e2x + wy * e2y + wz * e2z;
        b.tx[i][l] = txi; b.ty[i][l] = tyi;
        b.vx[i][l] = vgx * e1x + vgy * e1y + vgz * e1z - zi * tyi;
        b.vy[i][l] = vgx * e2x + vgy * e2y + vgz * e2z + zi * txi;
        b.vz[i][l] = vgx * e3x + vgy * e3y + vgz * e3z;
      }
    }
    for (std::size_t l = 0; l < n; ++l) {
      const auto e = static_cast<std::size_t>(idx[l]);
      const bool good = !g.deleted[e] && b.A[l] > 0.0;
      if (!g.deleted[e] && !(b.A[l] > 0.0) && tot.inverted < 0) tot.inverted = static_cast<std::int64_t>(e);
      b.ok[l] = good ? 1.0 : 0.0;
      b.A[l] = good ? b.A[l] : 1.0;
    }
    // B matrix, membrane / curvature / transverse shear rates.
    for (std::size_t l = 0; l < n; ++l) {
      const double i2A = 0.5 / b.A[l];
      const double x0 = b.x[0][l], x1 = b.x[1][l], x2 = b.x[2][l], x3 = b.x[3][l];
      const double y0 = b.y[0][l], y1 = b.y[1][l], y2 = b.y[2][l], y3 = b.y[3][l];
      b.B1[0][l] = (y1 - y3) * i2A; b.B1[1][l] = (y2 - y0) * i2A; b.B1[2][l] = (y3 - y1) * i2A; b.B1[3][l] = (y0 - y2) * i2A;
      b.B2[0][l] = (x3 - x1) * i2A; b.B2[1][l] = (x0 - x2) * i2A; b.B2[2][l] = (x1 - x3) * i2A; b.B2[3][l] = (x2 - x0) * i2A;
      double dxx = 0, dyy = 0, dxy = 0, kxx = 0, kyy = 0, kxy = 0, gxz = 0, gyz = 0;
      for (int i = 0; i < 4; ++i) {
        const double B1 = b.B1[i][l], B2 = b.B2[i][l];
        dxx += B1 * b.vx[i][l];
        dyy += B2 * b.vy[i][l];
        dxy += B2 * b.vx[i][l] + B1 * b.vy[i][l];
        kxx += B1 * b.ty[i][l];
        kyy -= B2 * b.tx[i][l];
        kxy += B2 * b.ty[i][l] - B1 * b.tx[i][l];
        gxz += B1 * b.vz[i][l] + 0.25 * b.ty[i][l];
        gyz += B2 * b.vz[i][l] - 0.25 * b.tx[i][l];
      }
      b.th.dem[0][l] = dxx * dt; b.th.dem[1][l] = dyy * dt; b.th.dem[2][l] = dxy * dt;
      b.th.dk[0][l] = kxx * dt; b.th.dk[1][l] = kyy * dt; b.th.dk[2][l] = kxy * dt;
      b.gxz[l] = gxz; b.gyz[l] = gyz;
    }
    // Through the thickness.
    b.th.integrate(g, idx, b.ok, n, dt);
    // Transverse shear (elastic, scaled by the fraction of points still carrying stress),
    // hourglass (stiffness form), stored resultants, energies.
    const double shear_G = sec.shear_factor * G;
    for (std::size_t l = 0; l < n; ++l) {
      const double A = b.A[l], t = b.th.t[l];
      const double alive = (static_cast<double>(np) - b.th.nfail[l]) / np;
      b.alive[l] = alive;
      const double ks = shear_G * t * alive;
      const double gxz = b.gxz[l], gyz = b.gyz[l];
      const double qx0 = b.q[0][l], qy0 = b.q[1][l];
      const double qx1 = qx0 + ks * gxz * dt, qy1 = qy0 + ks * gyz * dt;
      b.q[0][l] = qx1;
      b.q[1][l] = qy1;
      b.th.dE[l] = A * b.th.dE[l] + 0.5 * A * dt * ((qx0 + qx1) * gxz + (qy0 + qy1) * gyz);
      const double x0 = b.x[0][l], x1 = b.x[1][l], x2 = b.x[2][l], x3 = b.x[3][l];
      const double y0 = b.y[0][l], y1 = b.y[1][l], y2 = b.y[2][l], y3 = b.y[3][l];
      // h = (1, -1, 1, -1): h.x = x0 - x1 + x2 - x3.
      const double hx = ((x0 - x1) + x2) - x3;
      const double hy = ((y0 - y1) + y2) - y3;
      double qmx = 0, qmy = 0, qw = 0, qtx = 0, qty = 0, S = 0;
      for (int i = 0; i < 4; ++i) {
        const double hi = (i & 1) ? -1.0 : 1.0;
        const double B1 = b.B1[i][l], B2 = b.B2[i][l];
        const double gi = hi - hx * B1 - hy * B2;
        b.gam[i][l] = gi;
        qmx += gi * b.vx[i][l];
        qmy += gi * b.vy[i][l];
        qw += gi * (b.vz[i][l] + 0.5 * (b.x[i][l] * b.ty[i][l] - b.y[i][l] * b.tx[i][l]));
        qtx += gi * b.tx[i][l];
        qty += gi * b.ty[i][l];
        S += B1 * B1 + B2 * B2;
      }
      S *= A;
      const double cm = sec.hm * E * t * S * alive;
      const double cb = E * t * t * t / 12.0 * S * alive;
      const double cr = sec.hr * cb, cw = sec.hf * cb / A;
      const double h0 = b.q[2][l], h1 = b.q[3][l], h2 = b.q[4][l], h3 = b.q[5][l], h4 = b.q[6][l];
      const double n0 = h0 + cm * qmx * dt, n1 = h1 + cm * qmy * dt, n2 = h2 + cw * qw * dt,
                   n3 = h3 + cr * qtx * dt, n4 = h4 + cr * qty * dt;
      b.q[2][l] = n0; b.q[3][l] = n1; b.q[4][l] = n2; b.q[5][l] = n3; b.q[6][l] = n4;
      b.dEhg[l] = 0.5 * dt * ((h0 + n0) * qmx + (h1 + n1) * qmy + (h2 + n2) * qw + (h3 + n3) * qtx + (h4 + n4) * qty);
    }
    // The forces act at x^n: frame, local coordinates, B and gamma again on the current
    // geometry x^n = x^{n-1/2} + dt/2 v^{n-1/2}. (On the mid-step geometry, as the rates,
    // the force f^{n-1} of the previous cycle sat on x^{n-3/2}, a whole step behind the
    // rates it is paired with in the work 0.5 (f^{n-1} + f^n) . v^{n-1/2} dt: the kernel's
    // energy then exceeded that work by sigma^{n-1} : (B^{n-1/2} - B^{n-3/2}) v dt / 2 per
    // step, first order and one-sided, 4.6 J in each clavicle of the frontal hub case.
    // With forces on x^n the two half steps cancel to second order; Belytschko, Liu &
    // Moran, Nonlinear Finite Elements, box 6.1: rates at n-1/2, forces at n.)
    for (int i = 0; i < 4; ++i)
      for (std::size_t l = 0; l < n; ++l) {
        b.X[i][l] += hdt * b.VX[i][l];
        b.Y[i][l] += hdt * b.VY[i][l];
        b.Z[i][l] += hdt * b.VZ[i][l];
      }
    local_geometry(b, n);
    use_frozen_shape(b, n, g, idx);
    for (std::size_t l = 0; l < n; ++l) {
      const bool good = b.ok[l] != 0.0 && b.A[l] > 0.0;
      b.okf[l] = good ? 1.0 : 0.0;
      b.A[l] = good ? b.A[l] : 1.0;
      const double i2A = 0.5 / b.A[l];
      const double x0 = b.x[0][l], x1 = b.x[1][l], x2 = b.x[2][l], x3 = b.x[3][l];
      const double y0 = b.y[0][l], y1 = b.y[1][l], y2 = b.y[2][l], y3 = b.y[3][l];
      b.B1[0][l] = (y1 - y3) * i2A; b.B1[1][l] = (y2 - y0) * i2A; b.B1[2][l] = (y3 - y1) * i2A; b.B1[3][l] = (y0 - y2) * i2A;
      b.B2[0][l] = (x3 - x1) * i2A; b.B2[1][l] = (x0 - x2) * i2A; b.B2[2][l] = (x1 - x3) * i2A; b.B2[3][l] = (x2 - x0) * i2A;
      const double hx = ((x0 - x1) + x2) - x3;
      const double hy = ((y0 - y1) + y2) - y3;
      for (int i = 0; i < 4; ++i) {
        const double hi = (i & 1) ? -1.0 : 1.0;
        b.gam[i][l] = hi - hx * b.B1[i][l] - hy * b.B2[i][l];
      }
    }
    // Internal (resisting) nodal forces in the local frame; the force and moment ON the
    // node (minus the internal ones) in the global frame.
    // Written straight into the slot buffers when the batch's elements are consecutive,
    // else into the lanes and copied per element below.
    double* const slot_out[6] = {out.fx, out.fy, out.fz, out.mx, out.my, out.mz};
    double* dst[6];
    for (int c = 0; c < 6; ++c)
      dst[c] = consecutive ? slot_out[c] + static_cast<std::size_t>(idx[0]) * 4 : b.f[c];
    double *const f0 = dst[0], *const f1 = dst[1], *const f2 = dst[2], *const f3 = dst[3], *const f4 = dst[4],
                  *const f5 = dst[5];
#pragma GCC ivdep
    for (std::size_t l = 0; l < n; ++l)
#pragma GCC unroll 4
      for (int i = 0; i < 4; ++i) {
        const double A = b.A[l], B1 = b.B1[i][l], B2 = b.B2[i][l], gi = b.gam[i][l];
        const double Nxx = b.th.N[0][l], Nyy = b.th.N[1][l], Nxy = b.th.N[2][l];
        const double Mxx = b.th.M[0][l], Myy = b.th.M[1][l], Mxy = b.th.M[2][l];
        const double Qx = b.q[0][l], Qy = b.q[1][l];
        const double Hmx = b.q[2][l], Hmy = b.q[3][l], Hw = b.q[4][l], Htx = b.q[5][l], Hty = b.q[6][l];
        const double fx = A * (B1 * Nxx + B2 * Nxy) + gi * Hmx;
        const double fy = A * (B2 * Nyy + B1 * Nxy) + gi * Hmy;
        const double fz = A * (B1 * Qx + B2 * Qy) + gi * Hw;
        // Moments conjugate to thx, thy (the transverse hourglass term includes its
        // rotation part (x thy - y thx)/2), plus the rigid-link moments (warping).
        double mx = -A * (B2 * Myy + B1 * Mxy + 0.25 * Qy) + gi * (Htx - 0.5 * b.y[i][l] * Hw);
        double my = A * (B1 * Mxx + B2 * Mxy + 0.25 * Qx) + gi * (Hty + 0.5 * b.x[i][l] * Hw);
        mx += b.zw[i][l] * fy;
        my -= b.zw[i][l] * fx;
        const double e1x = b.e1[0][l], e1y = b.e1[1][l], e1z = b.e1[2][l];
        const double e2x = b.e2[0][l], e2y = b.e2[1][l], e2z = b.e2[2][l];
        const double e3x = b.e3[0][l], e3y = b.e3[1][l], e3z = b.e3[2][l];
        const bool ok = b.okf[l] != 0.0;
        f0[4 * l + static_cast<std::size_t>(i)] = ok ? -(fx * e1x + fy * e2x + fz * e3x) : 0.0;
        f1[4 * l + static_cast<std::size_t>(i)] = ok ? -(fx * e1y + fy * e2y + fz * e3y) : 0.0;
        f2[4 * l + static_cast<std::size_t>(i)] = ok ? -(fx * e1z + fy * e2z + fz * e3z) : 0.0;
        f3[4 * l + static_cast<std::size_t>(i)] = ok ? -(mx * e1x + my * e2x) : 0.0;
        f4[4 * l + static_cast<std::size_t>(i)] = ok ? -(mx * e1y + my * e2y) : 0.0;
        f5[4 * l + static_cast<std::size_t>(i)] = ok ? -(mx * e1z + my * e2z) : 0.0;
      }
    // Stable step A / longest side / c on the mid-step geometry.
    for (std::size_t l = 0; l < n; ++l) {
      double lmax2 = 0;
      for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) & 3;
        const double dx = b.X[j][l] - b.X[i][l], dy = b.Y[j][l] - b.Y[i][l], dz = b.Z[j][l] - b.Z[i][l];
        const double l2 = ((0.0 + dx * dx) + dy * dy) + dz * dz;
        lmax2 = std::max(lmax2, l2);
      }
      b.lmax2[l] = lmax2 > 0.0 ? lmax2 : 1.0;
    }
    lanes::sqrt_lanes(n, b.lmax2);
    for (std::size_t l = 0; l < n; ++l) b.dte[l] = b.A[l] / b.lmax2[l] / cwave;
    g.use_frozen_steps(b.dte, idx, n);
    // Slots of a batch with gaps (elements inside a rigid body left out), then the state
    // (masked lanes: zero slots; deleted elements no step; degenerate ones keep their
    // state).
    if (!consecutive)
      for (std::size_t l = 0; l < n; ++l)
        for (int c = 0; c < 6; ++c)
          std::copy_n(b.f[c] + 4 * l, 4, slot_out[c] + static_cast<std::size_t>(idx[l]) * 4);
    for (std::size_t l = 0; l < n; ++l) {
      const auto e = static_cast<std::size_t>(idx[l]);
      if (g.deleted[e]) {
        g.dt_elem[e] = 1e300;
        continue;
      }
      if (b.ok[l] == 0.0) continue;
      double* ex7 = &g.extra[e * 7];
      for (int c = 0; c < 7; ++c) ex7[c] = b.q[c][l];
      const int nf = static_cast<int>(b.th.nfail[l]);
      g.n_failed[e] = static_cast<std::uint8_t>(nf);
      g.eint[e] += b.th.dE[l];
      g.ehg[e] += b.dEhg[l];
      tot.de_int += b.th.dE[l];
      tot.de_hg += b.dEhg[l];
      if (sec.thickness_change) g.thick[e] = b.th.t[l] * (1.0 + b.th.dezz[l]);
      g.area[e] = b.A[l];
      g.dt_elem[e] = b.dte[l];
      const double nrm[3] = {b.e3[0][l], b.e3[1][l], b.e3[2][l]};
      if (double* f = g.freeze_if_due(e, b.dte[l], b.A[l], nrm))
        for (int i = 0; i < 4; ++i) {
          f[i] = b.x[i][l];
          f[4 + i] = b.y[i][l];
        }
      if (b.dte[l] < tot.dt_min) {
        tot.dt_min = b.dte[l];
        tot.dt_element = static_cast<std::int64_t>(e);
      }
      if (nf >= sec.points_to_delete()) {
        g.deleted[e] = 1;
        ++tot.newly_deleted;
      }
    }
  }
  return tot;
}

}  // namespace hbm::solver::shells
