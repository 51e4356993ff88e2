// SPDX-License-Identifier: GPL-3.0-or-later
// 3-node shell: constant-strain membrane (CST) plus the Discrete Kirchhoff Triangle
// bending element (Batoz, Bathe & Ho 1980, "A study of three-node triangular plate
// bending elements", IJNME 15: 1771-1812), corotational frame, rate form.
//
// Local frame: e1 along node 1 -> 2, e3 = r21 x r31 / |.|, e2 = e3 x e1.
// DKT: the normal rotations (beta_x = th_y, beta_y = -th_x) are quadratic over the
// triangle (6-node shape functions); at each mid-side k of side i-j (length l,
// tangent s, normal n) the Kirchhoff constraints of Batoz et al. give
//   beta_s(k) = -3/(2l) (w_j - w_i) - (beta_s(i) + beta_s(j))/4,
//   beta_n(k) = (beta_n(i) + beta_n(j))/2,
// and the curvatures are kappa = (beta_x,x, beta_y,y, beta_x,y + beta_y,x), linear over
// the element. No transverse shear, so no shear locking.
//
// Integration: curvature is linear, so elastic bending is integrated exactly by the
// 3-point rule (Hammer points (1/6,1/6), (2/3,1/6), (1/6,2/3), weights 1/3). The
// through-thickness material integration (plasticity, failure) is done once, at the
// centroid, with kappa_c = mean of the three point curvatures; the linear part
// kappa_g - kappa_c carries an elastic moment dM_g = D_b (kappa_g - kappa_c) (stored,
// rate form), like the one-point elements of Radioss (QEPH) stabilise their
// higher-order modes with an elastic physical moment. The element is exact DKT for an
// elastic material and costs one material evaluation per through-thickness point.
// Drilling rotations carry no stiffness (Radioss Idrill = 0); they are kept bounded by
// the nodal rotational inertia.
#include "shells/shell_group_data.hpp"
#include "shells/shell_through_thickness.hpp"

#include <algorithm>
#include <cmath>

namespace hbm::solver::shells {

namespace {

// Derivatives (d/dxi, d/deta) of the 6-node quadratic shape functions
// (corners 1,2,3; mid-sides 4 = 2-3, 5 = 3-1, 6 = 1-2) at the 3 Hammer points.
struct QuadraticDerivs {
  double dxi[3][6], deta[3][6];
  constexpr QuadraticDerivs() : dxi{}, deta{} {
    const double pts[3][2] = {{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}};
    for (int g = 0; g < 3; ++g) {
      const double L2 = pts[g][0], L3 = pts[g][1], L1 = 1.0 - L2 - L3;
      dxi[g][0] = -(4 * L1 - 1); deta[g][0] = -(4 * L1 - 1);
      dxi[g][1] = 4 * L2 - 1;    deta[g][1] = 0;
      dxi[g][2] = 0;             deta[g][2] = 4 * L3 - 1;
      dxi[g][3] = 4 * L3;        deta[g][3] = 4 * L2;
      dxi[g][4] = -4 * L3;       deta[g][4] = 4 * (L1 - L3);
      dxi[g][5] = 4 * (L1 - L2); deta[g][5] = -4 * L2;
    }
  }
};
constexpr QuadraticDerivs kQD{};

// Side k (mid-side node 3+k) joins corners kSide[k][0] -> kSide[k][1].
constexpr int kSide[3][2] = {{1, 2}, {2, 0}, {0, 1}};

}  // namespace

ShellKernelTotals tria_dkt_forces(ShellGroupData& g, const ShellNodalView& nv,
                                 const ShellSlotOut& out, double dt,
                                 std::span<const std::int32_t> elements) {
  ShellKernelTotals tot;
  const ShellMaterial& mat = g.mat;
  const ShellSection& sec = g.sec;
  const int np = sec.n_points;
  const int nh = mat.n_history();
  const double E = mat.young(), nu = mat.poisson();
  const double cwave = mat.plate_wave_speed();

  for (const std::int32_t el : elements) {
    const auto e = static_cast<std::size_t>(el);
    const std::size_t s0 = e * 3;
    auto zero_slots = [&] {
      for (std::size_t s = s0; s < s0 + 3; ++s)
        out.fx[s] = out.fy[s] = out.fz[s] = out.mx[s] = out.my[s] = out.mz[s] = 0.0;
    };
    if (g.deleted[e]) {
      zero_slots();
      g.dt_elem[e] = 1e300;
      continue;
    }
    const std::int32_t* cn = &g.conn[e * 3];
    double X[3][3], V[3][3], W[3][3];
    for (int i = 0; i < 3; ++i) {
      const auto n = cn[i];
      X[i][0] = nv.x[n]; X[i][1] = nv.y[n]; X[i][2] = nv.z[n];
      V[i][0] = nv.vx[n]; V[i][1] = nv.vy[n]; V[i][2] = nv.vz[n];
      W[i][0] = nv.wx[n]; W[i][1] = nv.wy[n]; W[i][2] = nv.wz[n];
      // Mid-step geometry x^{n-1/2} = x^n - dt/2 v^{n-1/2}: the velocity gradient of a
      // rigid rotation is then skew (Cayley transform), so rotations strain nothing.
      for (int k = 0; k < 3; ++k) X[i][k] -= 0.5 * dt * V[i][k];
    }
    double r21[3], r31[3], ex[3], ey[3], ez[3];
    for (int k = 0; k < 3; ++k) {
      r21[k] = X[1][k] - X[0][k];
      r31[k] = X[2][k] - X[0][k];
    }
    ez[0] = r21[1] * r31[2] - r21[2] * r31[1];
    ez[1] = r21[2] * r31[0] - r21[0] * r31[2];
    ez[2] = r21[0] * r31[1] - r21[1] * r31[0];
    const double nz = std::sqrt(ez[0] * ez[0] + ez[1] * ez[1] + ez[2] * ez[2]);
    const double A = 0.5 * nz;
    if (!(A > 0)) {  // degenerate (collapsed) triangle: reported, the core stops the run
      if (tot.inverted < 0) tot.inverted = static_cast<std::int64_t>(e);
      zero_slots();
      continue;
    }
    for (double& c : ez) c /= nz;
    const double l21 = std::sqrt(r21[0] * r21[0] + r21[1] * r21[1] + r21[2] * r21[2]);
    for (int k = 0; k < 3; ++k) ex[k] = r21[k] / l21;
    ey[0] = ez[1] * ex[2] - ez[2] * ex[1];
    ey[1] = ez[2] * ex[0] - ez[0] * ex[2];
    ey[2] = ez[0] * ex[1] - ez[1] * ex[0];
    // Local coordinates: node 1 at the origin, node 2 on the x axis.
    const double x[3] = {0.0, l21, r31[0] * ex[0] + r31[1] * ex[1] + r31[2] * ex[2]};
    const double y[3] = {0.0, 0.0, r31[0] * ey[0] + r31[1] * ey[1] + r31[2] * ey[2]};
    double vx[3], vy[3], w[3], bx[3], by[3];
    for (int i = 0; i < 3; ++i) {
      vx[i] = V[i][0] * ex[0] + V[i][1] * ex[1] + V[i][2] * ex[2];
      vy[i] = V[i][0] * ey[0] + V[i][1] * ey[1] + V[i][2] * ey[2];
      w[i] = V[i][0] * ez[0] + V[i][1] * ez[1] + V[i][2] * ez[2];
      bx[i] = W[i][0] * ey[0] + W[i][1] * ey[1] + W[i][2] * ey[2];     // beta_x = th_y
      by[i] = -(W[i][0] * ex[0] + W[i][1] * ex[1] + W[i][2] * ex[2]);  // beta_y = -th_x
    }
    // CST membrane.
    const double i2A = 0.5 / A;
    const double B1[3] = {(y[1] - y[2]) * i2A, (y[2] - y[0]) * i2A, (y[0] - y[1]) * i2A};
    const double B2[3] = {(x[2] - x[1]) * i2A, (x[0] - x[2]) * i2A, (x[1] - x[0]) * i2A};
    double dxx = 0, dyy = 0, dxy = 0;
    for (int i = 0; i < 3; ++i) {
      dxx += B1[i] * vx[i];
      dyy += B2[i] * vy[i];
      dxy += B2[i] * vx[i] + B1[i] * vy[i];
    }
    // DKT: rotation rates at the 6 nodes.
    double Bx[6], By[6], sc[3], ss[3], sl[3];
    for (int i = 0; i < 3; ++i) { Bx[i] = bx[i]; By[i] = by[i]; }
    for (int k = 0; k < 3; ++k) {
      const int i = kSide[k][0], j = kSide[k][1];
      const double dx = x[j] - x[i], dy = y[j] - y[i];
      const double l = std::sqrt(dx * dx + dy * dy);
      const double c = dx / l, s = dy / l;
      sc[k] = c; ss[k] = s; sl[k] = l;
      const double bs = -1.5 / l * (w[j] - w[i]) - 0.25 * (c * (bx[i] + bx[j]) + s * (by[i] + by[j]));
      const double bn = 0.5 * (-s * (bx[i] + bx[j]) + c * (by[i] + by[j]));
      Bx[3 + k] = c * bs - s * bn;
      By[3 + k] = s * bs + c * bn;
    }
    // Cartesian derivatives at the 3 points: d/dx = (y31 d/dxi - y21 d/deta)/2A, ...
    const double x21 = x[1] - x[0], x31 = x[2] - x[0], y21 = y[1] - y[0], y31 = y[2] - y[0];
    double dNx[3][6], dNy[3][6], kap[3][3];
    for (int gp = 0; gp < 3; ++gp) {
      double k0 = 0, k1 = 0, k2 = 0;
      for (int a = 0; a < 6; ++a) {
        const double nx = (y31 * kQD.dxi[gp][a] - y21 * kQD.deta[gp][a]) * i2A;
        const double ny = (-x31 * kQD.dxi[gp][a] + x21 * kQD.deta[gp][a]) * i2A;
        dNx[gp][a] = nx;
        dNy[gp][a] = ny;
        k0 += nx * Bx[a];
        k1 += ny * By[a];
        k2 += ny * Bx[a] + nx * By[a];
      }
      kap[gp][0] = k0; kap[gp][1] = k1; kap[gp][2] = k2;
    }
    const double kc[3] = {(kap[0][0] + kap[1][0] + kap[2][0]) / 3.0,
                          (kap[0][1] + kap[1][1] + kap[2][1]) / 3.0,
                          (kap[0][2] + kap[1][2] + kap[2][2]) / 3.0};
    const double t = g.thick[e];
    const double dem[3] = {dxx * dt, dyy * dt, dxy * dt};
    const double dk[3] = {kc[0] * dt, kc[1] * dt, kc[2] * dt};
    ThicknessResult tr;
    integrate_thickness(mat, sec, t, dem, dk, dt, &g.stress[e * np * 3], &g.epsp[e * np],
                        nh ? &g.hist[e * np * nh] : nullptr, tr);
    const int nf = g.n_failed[e] + tr.newly_failed;
    g.n_failed[e] = static_cast<std::uint8_t>(nf);
    const double alive = static_cast<double>(np - nf) / np;
    // Elastic moments of the linear curvature part (plate stiffness D_b, bending only
    // when there is more than one point through the thickness).
    double* md = &g.extra[e * 9];
    const double Db = np > 1 ? E * t * t * t / (12.0 * (1.0 - nu * nu)) * alive : 0.0;
    double dEdev = 0;
    double Mg[3][3];
    for (int gp = 0; gp < 3; ++gp) {
      const double d0 = (kap[gp][0] - kc[0]) * dt, d1 = (kap[gp][1] - kc[1]) * dt,
                   d2 = (kap[gp][2] - kc[2]) * dt;
      double* m = md + 3 * gp;
      const double o0 = m[0], o1 = m[1], o2 = m[2];
      m[0] += Db * (d0 + nu * d1);
      m[1] += Db * (nu * d0 + d1);
      m[2] += Db * 0.5 * (1.0 - nu) * d2;
      dEdev += 0.5 * ((o0 + m[0]) * d0 + (o1 + m[1]) * d1 + (o2 + m[2]) * d2);
      Mg[gp][0] = tr.M[0] + m[0];
      Mg[gp][1] = tr.M[1] + m[1];
      Mg[gp][2] = tr.M[2] + m[2];
    }
    // Generalised forces on the 6-node rotations: F = A/3 sum_g dN^T M_g.
    double Fx[6] = {}, Fy[6] = {};
    const double A3 = A / 3.0;
    for (int gp = 0; gp < 3; ++gp)
      for (int a = 0; a < 6; ++a) {
        Fx[a] += A3 * (dNx[gp][a] * Mg[gp][0] + dNy[gp][a] * Mg[gp][2]);
        Fy[a] += A3 * (dNy[gp][a] * Mg[gp][1] + dNx[gp][a] * Mg[gp][2]);
      }
    // Transpose of the Kirchhoff constraints onto the corner DOFs (w, beta_x, beta_y).
    double Fw[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      const int i = kSide[k][0], j = kSide[k][1];
      const double c = sc[k], s = ss[k], l = sl[k];
      const double Fs = c * Fx[3 + k] + s * Fy[3 + k];
      const double Fn = -s * Fx[3 + k] + c * Fy[3 + k];
      Fw[j] -= 1.5 / l * Fs;
      Fw[i] += 1.5 / l * Fs;
      const double gx = -0.25 * c * Fs - 0.5 * s * Fn;  // d/d beta_x(i) and (j)
      const double gy = -0.25 * s * Fs + 0.5 * c * Fn;
      Fx[i] += gx; Fx[j] += gx;
      Fy[i] += gy; Fy[j] += gy;
    }
    const double Nxx = tr.N[0], Nyy = tr.N[1], Nxy = tr.N[2];
    for (int i = 0; i < 3; ++i) {
      const double fx = A * (B1[i] * Nxx + B2[i] * Nxy);
      const double fy = A * (B2[i] * Nyy + B1[i] * Nxy);
      const double fz = Fw[i];
      const double mx = -Fy[i];  // beta_y = -th_x
      const double my = Fx[i];   // beta_x = th_y
      const std::size_t s = s0 + static_cast<std::size_t>(i);
      out.fx[s] = -(fx * ex[0] + fy * ey[0] + fz * ez[0]);
      out.fy[s] = -(fx * ex[1] + fy * ey[1] + fz * ez[1]);
      out.fz[s] = -(fx * ex[2] + fy * ey[2] + fz * ez[2]);
      out.mx[s] = -(mx * ex[0] + my * ey[0]);
      out.my[s] = -(mx * ex[1] + my * ey[1]);
      out.mz[s] = -(mx * ex[2] + my * ey[2]);
    }
    const double dE = A * tr.dE + A3 * dEdev;
    g.eint[e] += dE;
    tot.de_int += dE;
    if (sec.thickness_change) g.thick[e] = t * (1.0 + tr.dezz);
    g.area[e] = A;
    double lmax2 = 0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      double l2 = 0;
      for (int k = 0; k < 3; ++k) l2 += (X[j][k] - X[i][k]) * (X[j][k] - X[i][k]);
      lmax2 = std::max(lmax2, l2);
    }
    g.dt_elem[e] = 2.0 * A / std::sqrt(lmax2) / cwave;
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
