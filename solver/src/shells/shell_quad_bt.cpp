// SPDX-License-Identifier: GPL-3.0-or-later
// 4-node Belytschko-Tsay shell (Belytschko, Lin & Tsay 1984, "Explicit algorithms for
// the nonlinear dynamics of shells", CMAME 42: 225-251), one in-plane integration point,
// Mindlin kinematics in a corotational frame, rate form:
//   d_xx = B1I vxI + z B1I thyI,  d_yy = B2I vyI - z B2I thxI,
//   2d_xy = B2I vxI + B1I vyI + z (B2I thyI - B1I thxI),
//   2d_xz = B1I vzI + thyI/4,      2d_yz = B2I vzI - thxI/4,
// B1 = (y24, y31, y42, y13)/(2A), B2 = (x42, x13, x24, x31)/(2A) in the local frame
// e3 = r31 x r42 / |.|, e1 along r21 projected, e2 = e3 x e1.
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
#include "shells/shell_group_data.hpp"
#include "shells/shell_through_thickness.hpp"

#include <algorithm>
#include <cmath>

namespace hbm::solver::shells {

ShellKernelTotals quad_bt_forces(ShellGroupData& g, const ShellNodalView& nv,
                                 const ShellSlotOut& out, double dt,
                                 std::span<const std::int32_t> elements) {
  ShellKernelTotals tot;
  const ShellMaterial& mat = g.mat;
  const ShellSection& sec = g.sec;
  const int np = sec.n_points;
  const int nh = mat.n_history();
  const double E = mat.young(), G = mat.shear_modulus();
  const double cwave = mat.plate_wave_speed();
  static constexpr double h[4] = {1.0, -1.0, 1.0, -1.0};

  for (const std::int32_t el : elements) {
    const auto e = static_cast<std::size_t>(el);
    const std::size_t s0 = e * 4;
    auto zero_slots = [&] {
      for (std::size_t s = s0; s < s0 + 4; ++s)
        out.fx[s] = out.fy[s] = out.fz[s] = out.mx[s] = out.my[s] = out.mz[s] = 0.0;
    };
    if (g.deleted[e]) {
      zero_slots();
      g.dt_elem[e] = 1e300;
      continue;
    }
    const std::int32_t* cn = &g.conn[e * 4];
    double X[4][3], V[4][3], W[4][3];
    for (int i = 0; i < 4; ++i) {
      const auto n = cn[i];
      X[i][0] = nv.x[n]; X[i][1] = nv.y[n]; X[i][2] = nv.z[n];
      V[i][0] = nv.vx[n]; V[i][1] = nv.vy[n]; V[i][2] = nv.vz[n];
      W[i][0] = nv.wx[n]; W[i][1] = nv.wy[n]; W[i][2] = nv.wz[n];
      // Mid-step geometry x^{n-1/2} = x^n - dt/2 v^{n-1/2}: the velocity gradient of a
      // rigid rotation is then skew (Cayley transform), so rotations strain nothing.
      for (int k = 0; k < 3; ++k) X[i][k] -= 0.5 * dt * V[i][k];
    }
    // Local frame.
    double r31[3], r42[3], r21[3], e3[3], ex[3], ey[3];
    for (int k = 0; k < 3; ++k) {
      r31[k] = X[2][k] - X[0][k];
      r42[k] = X[3][k] - X[1][k];
      r21[k] = X[1][k] - X[0][k];
    }
    e3[0] = r31[1] * r42[2] - r31[2] * r42[1];
    e3[1] = r31[2] * r42[0] - r31[0] * r42[2];
    e3[2] = r31[0] * r42[1] - r31[1] * r42[0];
    const double n3 = 1.0 / std::sqrt(e3[0] * e3[0] + e3[1] * e3[1] + e3[2] * e3[2]);
    for (double& c : e3) c *= n3;
    const double d21 = r21[0] * e3[0] + r21[1] * e3[1] + r21[2] * e3[2];
    for (int k = 0; k < 3; ++k) ex[k] = r21[k] - d21 * e3[k];
    const double n1 = 1.0 / std::sqrt(ex[0] * ex[0] + ex[1] * ex[1] + ex[2] * ex[2]);
    for (double& c : ex) c *= n1;
    ey[0] = e3[1] * ex[2] - e3[2] * ex[1];
    ey[1] = e3[2] * ex[0] - e3[0] * ex[2];
    ey[2] = e3[0] * ex[1] - e3[1] * ex[0];
    double xc[3] = {0, 0, 0};
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) xc[k] += 0.25 * X[i][k];
    // Local coordinates, velocities, rotations (projected by the rigid links).
    double x[4], y[4], zw[4], vx[4], vy[4], vz[4], tx[4], ty[4];
    for (int i = 0; i < 4; ++i) {
      const double d[3] = {X[i][0] - xc[0], X[i][1] - xc[1], X[i][2] - xc[2]};
      x[i] = d[0] * ex[0] + d[1] * ex[1] + d[2] * ex[2];
      y[i] = d[0] * ey[0] + d[1] * ey[1] + d[2] * ey[2];
      zw[i] = d[0] * e3[0] + d[1] * e3[1] + d[2] * e3[2];
      tx[i] = W[i][0] * ex[0] + W[i][1] * ex[1] + W[i][2] * ex[2];
      ty[i] = W[i][0] * ey[0] + W[i][1] * ey[1] + W[i][2] * ey[2];
      vx[i] = V[i][0] * ex[0] + V[i][1] * ex[1] + V[i][2] * ex[2] - zw[i] * ty[i];
      vy[i] = V[i][0] * ey[0] + V[i][1] * ey[1] + V[i][2] * ey[2] + zw[i] * tx[i];
      vz[i] = V[i][0] * e3[0] + V[i][1] * e3[1] + V[i][2] * e3[2];
    }
    const double A = 0.5 * ((x[2] - x[0]) * (y[3] - y[1]) - (x[3] - x[1]) * (y[2] - y[0]));
    if (!(A > 0)) {  // folded or degenerate: reported, the core stops the run
      if (tot.inverted < 0) tot.inverted = static_cast<std::int64_t>(e);
      zero_slots();
      continue;
    }
    const double i2A = 0.5 / A;
    const double B1[4] = {(y[1] - y[3]) * i2A, (y[2] - y[0]) * i2A, (y[3] - y[1]) * i2A, (y[0] - y[2]) * i2A};
    const double B2[4] = {(x[3] - x[1]) * i2A, (x[0] - x[2]) * i2A, (x[1] - x[3]) * i2A, (x[2] - x[0]) * i2A};
    double dxx = 0, dyy = 0, dxy = 0, kxx = 0, kyy = 0, kxy = 0, gxz = 0, gyz = 0;
    for (int i = 0; i < 4; ++i) {
      dxx += B1[i] * vx[i];
      dyy += B2[i] * vy[i];
      dxy += B2[i] * vx[i] + B1[i] * vy[i];
      kxx += B1[i] * ty[i];
      kyy -= B2[i] * tx[i];
      kxy += B2[i] * ty[i] - B1[i] * tx[i];
      gxz += B1[i] * vz[i] + 0.25 * ty[i];
      gyz += B2[i] * vz[i] - 0.25 * tx[i];
    }
    const double t = g.thick[e];
    const double dem[3] = {dxx * dt, dyy * dt, dxy * dt};
    const double dk[3] = {kxx * dt, kyy * dt, kxy * dt};
    ThicknessResult tr;
    integrate_thickness(mat, sec, t, dem, dk, dt, &g.stress[e * np * 3], &g.epsp[e * np],
                        nh ? &g.hist[e * np * nh] : nullptr, tr);
    double* ex7 = &g.extra[e * 7];
    // Transverse shear (elastic), scaled by the fraction of points still carrying stress.
    const int nf = g.n_failed[e] + tr.newly_failed;
    g.n_failed[e] = static_cast<std::uint8_t>(nf);
    const double alive = static_cast<double>(np - nf) / np;
    const double ks = sec.shear_factor * G * t * alive;
    const double qx0 = ex7[0], qy0 = ex7[1];
    ex7[0] += ks * gxz * dt;
    ex7[1] += ks * gyz * dt;
    double dE = A * tr.dE + 0.5 * A * dt * ((qx0 + ex7[0]) * gxz + (qy0 + ex7[1]) * gyz);
    // Hourglass.
    const double hx = h[0] * x[0] + h[1] * x[1] + h[2] * x[2] + h[3] * x[3];
    const double hy = h[0] * y[0] + h[1] * y[1] + h[2] * y[2] + h[3] * y[3];
    double gam[4], qmx = 0, qmy = 0, qw = 0, qtx = 0, qty = 0, S = 0;
    for (int i = 0; i < 4; ++i) {
      gam[i] = h[i] - hx * B1[i] - hy * B2[i];
      qmx += gam[i] * vx[i];
      qmy += gam[i] * vy[i];
      qw += gam[i] * (vz[i] + 0.5 * (x[i] * ty[i] - y[i] * tx[i]));
      qtx += gam[i] * tx[i];
      qty += gam[i] * ty[i];
      S += B1[i] * B1[i] + B2[i] * B2[i];
    }
    S *= A;
    const double cm = sec.hm * E * t * S * alive;
    const double cb = E * t * t * t / 12.0 * S * alive;
    const double cr = sec.hr * cb, cw = sec.hf * cb / A;
    const double q0[5] = {ex7[2], ex7[3], ex7[4], ex7[5], ex7[6]};
    ex7[2] += cm * qmx * dt;
    ex7[3] += cm * qmy * dt;
    ex7[4] += cw * qw * dt;
    ex7[5] += cr * qtx * dt;
    ex7[6] += cr * qty * dt;
    const double dEhg = 0.5 * dt * ((q0[0] + ex7[2]) * qmx + (q0[1] + ex7[3]) * qmy +
                                    (q0[2] + ex7[4]) * qw + (q0[3] + ex7[5]) * qtx +
                                    (q0[4] + ex7[6]) * qty);
    // Internal (resisting) nodal forces in the local frame.
    const double Nxx = tr.N[0], Nyy = tr.N[1], Nxy = tr.N[2];
    const double Mxx = tr.M[0], Myy = tr.M[1], Mxy = tr.M[2];
    const double Qx = ex7[0], Qy = ex7[1];
    const double Hmx = ex7[2], Hmy = ex7[3], Hw = ex7[4], Htx = ex7[5], Hty = ex7[6];
    for (int i = 0; i < 4; ++i) {
      const double fx = A * (B1[i] * Nxx + B2[i] * Nxy) + gam[i] * Hmx;
      const double fy = A * (B2[i] * Nyy + B1[i] * Nxy) + gam[i] * Hmy;
      const double fz = A * (B1[i] * Qx + B2[i] * Qy) + gam[i] * Hw;
      // Moments conjugate to thx, thy (the transverse hourglass term includes its
      // rotation part (x thy - y thx)/2).
      double mx = -A * (B2[i] * Myy + B1[i] * Mxy + 0.25 * Qy) + gam[i] * (Htx - 0.5 * y[i] * Hw);
      double my = A * (B1[i] * Mxx + B2[i] * Mxy + 0.25 * Qx) + gam[i] * (Hty + 0.5 * x[i] * Hw);
      mx += zw[i] * fy;  // rigid-link moments (warping)
      my -= zw[i] * fx;
      // Force ON the node = minus the internal force, back to the global frame.
      const std::size_t s = s0 + static_cast<std::size_t>(i);
      out.fx[s] = -(fx * ex[0] + fy * ey[0] + fz * e3[0]);
      out.fy[s] = -(fx * ex[1] + fy * ey[1] + fz * e3[1]);
      out.fz[s] = -(fx * ex[2] + fy * ey[2] + fz * e3[2]);
      out.mx[s] = -(mx * ex[0] + my * ey[0]);
      out.my[s] = -(mx * ex[1] + my * ey[1]);
      out.mz[s] = -(mx * ex[2] + my * ey[2]);
    }
    g.eint[e] += dE;
    g.ehg[e] += dEhg;
    tot.de_int += dE;
    tot.de_hg += dEhg;
    if (sec.thickness_change) g.thick[e] = t * (1.0 + tr.dezz);
    g.area[e] = A;
    double lmax2 = 0;
    for (int i = 0; i < 4; ++i) {
      const int j = (i + 1) & 3;
      double l2 = 0;
      for (int k = 0; k < 3; ++k) l2 += (X[j][k] - X[i][k]) * (X[j][k] - X[i][k]);
      lmax2 = std::max(lmax2, l2);
    }
    g.dt_elem[e] = A / std::sqrt(lmax2) / cwave;
    if (g.dt_elem[e] < tot.dt_min) {
      tot.dt_min = g.dt_elem[e];
      tot.dt_element = static_cast<std::int64_t>(e);
    }
    if (nf >= sec.points_to_delete()) {
      g.deleted[e] = 1;
      ++tot.newly_deleted;
    }
  }
  return tot;
}

}  // namespace hbm::solver::shells
