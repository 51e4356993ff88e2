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
//
// Rates on the mid-step geometry x^{n-1/2} (rigid rotations strain nothing), forces on
// the current geometry x^n (force_geometry): the work 0.5 (f^{n-1} + f^n) . v^{n-1/2} dt
// then equals the energy increment to second order (docs/engine-design.md 14.3).
//
// Lanes: as the quad kernel (shell_quad_bt.cpp), the elements are computed in batches
// of TriaLanes::W (element k of the batch is lane k), every stage a loop over the lanes
// that GCC vectorises; deleted or degenerate elements are masked on output; each lane
// does the arithmetic of the one-element formulas in the same order.
#include "core/lane_vector_ops.hpp"
#include "shells/shell_group_data.hpp"
#include "shells/shell_lane_gather.hpp"
#include "shells/shell_thickness_lanes.hpp"

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

// One batch of triangles as lanes (thread_local, about 50 KB).
struct TriaLanes {
  static constexpr std::size_t W = 32;
  alignas(64) std::int32_t node[3][W];
  alignas(64) double X[3][W], Y[3][W], Z[3][W];        // mid-step positions
  alignas(64) double VX[3][W], VY[3][W], VZ[3][W];     // velocities (global)
  alignas(64) double WX[3][W], WY[3][W], WZ[3][W];     // angular velocities (global)
  alignas(64) double ex[3][W], ey[3][W], ez[3][W];     // local frame
  alignas(64) double x2[W], y2[W], l21[W];             // local coordinates of nodes 2, 3
  alignas(64) double vx[3][W], vy[3][W], w[3][W], bx[3][W], by[3][W];
  alignas(64) double B1[3][W], B2[3][W];
  alignas(64) double sc[3][W], ss[3][W], sl[3][W];     // sides: cos, sin, length
  alignas(64) double Bx[6][W], By[6][W];               // rotation rates at the 6 nodes
  alignas(64) double dNx[3][6][W], dNy[3][6][W], kap[3][3][W];
  alignas(64) double A[W], i2A[W], ok[W], okf[W], sq[W], dEdev[W], dE[W], lmax2[W], dte[W];
  alignas(64) double spin[W];                          // material rotation relative to the frame (LAW42)
  alignas(64) double Mg[3][3][W];                      // moments at the 3 points (force stage)
  alignas(64) double md[9][W];                         // extra: deviatoric moments at the points
  alignas(64) double Fx[6][W], Fy[6][W], Fw[3][W];
  ThicknessLanes<W> th;
  alignas(64) double f[6][W * 3];                      // force, moment ON the nodes, global,
                                                       // slot order (lane * 3 + node)
};

// Unnormalised normal r21 x r31 (ez), its length (sq) and |r21| (l21) from X, Y, Z.
void frame_lengths(TriaLanes& b, std::size_t n) {
  for (std::size_t l = 0; l < n; ++l) {
    const double r21x = b.X[1][l] - b.X[0][l], r21y = b.Y[1][l] - b.Y[0][l], r21z = b.Z[1][l] - b.Z[0][l];
    const double r31x = b.X[2][l] - b.X[0][l], r31y = b.Y[2][l] - b.Y[0][l], r31z = b.Z[2][l] - b.Z[0][l];
    const double cx = r21y * r31z - r21z * r31y, cy = r21z * r31x - r21x * r31z, cz = r21x * r31y - r21y * r31x;
    b.ez[0][l] = cx; b.ez[1][l] = cy; b.ez[2][l] = cz;
    b.sq[l] = cx * cx + cy * cy + cz * cz;
    b.l21[l] = r21x * r21x + r21y * r21y + r21z * r21z;
  }
  lanes::sqrt_lanes(n, b.sq);
  lanes::sqrt_lanes(n, b.l21);
}

// Local frame (after frame_lengths and masking): e3 = ez / |ez|, e1 along node 1 -> 2,
// e2 = e3 x e1; local coordinates of node 3 (node 1 at the origin, node 2 on the x axis).
void local_frame(TriaLanes& b, std::size_t n) {
  for (std::size_t l = 0; l < n; ++l) {
    const double nz = b.sq[l], l21 = b.l21[l];
    const double ezx = b.ez[0][l] / nz, ezy = b.ez[1][l] / nz, ezz = b.ez[2][l] / nz;
    b.ez[0][l] = ezx; b.ez[1][l] = ezy; b.ez[2][l] = ezz;
    const double exx = (b.X[1][l] - b.X[0][l]) / l21, exy = (b.Y[1][l] - b.Y[0][l]) / l21,
                 exz = (b.Z[1][l] - b.Z[0][l]) / l21;
    b.ex[0][l] = exx; b.ex[1][l] = exy; b.ex[2][l] = exz;
    const double eyx = ezy * exz - ezz * exy, eyy = ezz * exx - ezx * exz, eyz = ezx * exy - ezy * exx;
    b.ey[0][l] = eyx; b.ey[1][l] = eyy; b.ey[2][l] = eyz;
    const double r31x = b.X[2][l] - b.X[0][l], r31y = b.Y[2][l] - b.Y[0][l], r31z = b.Z[2][l] - b.Z[0][l];
    b.x2[l] = r31x * exx + r31y * exy + r31z * exz;
    b.y2[l] = r31x * eyx + r31y * eyy + r31z * eyz;
  }
}

// /DT/SH_3N/CST: switched lanes take the in-plane shape frozen at the switch (|r21|, local
// x, y of node 3, area) in the current frame; the frame keeps the orientation of the last
// evaluation (a triangle squeezed through flat would otherwise flip its normal and see
// its frozen shape mirrored). Layout: ShellGroupData::frozen_shape.
void use_frozen_shape(TriaLanes& b, std::size_t n, ShellGroupData& g, const std::int32_t* idx) {
  if (g.frozen.empty()) return;
  constexpr std::size_t kN = ShellGroupData::kFrozenNormal;
  for (std::size_t l = 0; l < n; ++l) {
    const auto e = static_cast<std::size_t>(idx[l]);
    if (!g.frozen[e] || b.ok[l] == 0.0) continue;
    double* f = g.frozen_values(e);
    if (b.ez[0][l] * f[kN] + b.ez[1][l] * f[kN + 1] + b.ez[2][l] * f[kN + 2] < 0.0)
      for (int c = 0; c < 3; ++c) {
        b.ez[c][l] = -b.ez[c][l];
        b.ey[c][l] = -b.ey[c][l];
      }
    for (int c = 0; c < 3; ++c) f[kN + c] = b.ez[c][l];
    b.l21[l] = f[0];
    b.x2[l] = f[1];
    b.y2[l] = f[2];
    b.A[l] = f[ShellGroupData::kFrozenArea];
    b.sq[l] = 2.0 * b.A[l];
  }
}

// CST B matrix and the DKT sides (sc, ss: side vector; sl: length, squared until the
// caller's square root) in local coordinates.
void side_geometry(TriaLanes& b, std::size_t n) {
  for (std::size_t l = 0; l < n; ++l) {
    const double x[3] = {0.0, b.l21[l], b.x2[l]}, y[3] = {0.0, 0.0, b.y2[l]};
    const double i2A = 0.5 / b.A[l];
    b.B1[0][l] = (y[1] - y[2]) * i2A; b.B1[1][l] = (y[2] - y[0]) * i2A; b.B1[2][l] = (y[0] - y[1]) * i2A;
    b.B2[0][l] = (x[2] - x[1]) * i2A; b.B2[1][l] = (x[0] - x[2]) * i2A; b.B2[2][l] = (x[1] - x[0]) * i2A;
    for (int k = 0; k < 3; ++k) {
      const int i = kSide[k][0], j = kSide[k][1];
      const double dx = x[j] - x[i], dy = y[j] - y[i];
      b.sc[k][l] = dx;
      b.ss[k][l] = dy;
      const double s = dx * dx + dy * dy;
      b.sl[k][l] = s > 0.0 ? s : 1.0;
    }
  }
}

// The geometry of the force stage on x^n = x^{n-1/2} + dt/2 v^{n-1/2}: frame, local
// coordinates, area (okf: ok and not folded there), B, sides (cos, sin, length) and the
// Cartesian derivatives dNx, dNy at the 3 points, with the expressions of the rate stage.
// (Forces on the mid-step geometry lag the rates of the energy increment by a step in the
// work 0.5 (f^{n-1} + f^n) . v^{n-1/2} dt; docs/engine-design.md 14.3.)
void force_geometry(TriaLanes& b, std::size_t n, double hdt, ShellGroupData& g, const std::int32_t* idx) {
  for (int i = 0; i < 3; ++i)
    for (std::size_t l = 0; l < n; ++l) {
      b.X[i][l] += hdt * b.VX[i][l];
      b.Y[i][l] += hdt * b.VY[i][l];
      b.Z[i][l] += hdt * b.VZ[i][l];
    }
  frame_lengths(b, n);
  for (std::size_t l = 0; l < n; ++l) {
    const double A = 0.5 * b.sq[l];
    const bool good = b.ok[l] != 0.0 && A > 0.0 && b.l21[l] > 0.0;
    b.okf[l] = good ? 1.0 : 0.0;
    b.A[l] = good ? A : 1.0;
    b.sq[l] = good ? b.sq[l] : 1.0;
    b.l21[l] = good ? b.l21[l] : 1.0;
  }
  local_frame(b, n);
  use_frozen_shape(b, n, g, idx);
  side_geometry(b, n);
  for (int k = 0; k < 3; ++k) lanes::sqrt_lanes(n, b.sl[k]);
  for (int k = 0; k < 3; ++k)
    for (std::size_t l = 0; l < n; ++l) {
      const double len = b.sl[k][l];
      b.sc[k][l] = b.sc[k][l] / len;
      b.ss[k][l] = b.ss[k][l] / len;
    }
  for (std::size_t l = 0; l < n; ++l) b.i2A[l] = 0.5 / b.A[l];
  for (int gp = 0; gp < 3; ++gp)
    for (int a = 0; a < 6; ++a) {
      const double dxi = kQD.dxi[gp][a], deta = kQD.deta[gp][a];
      const double *__restrict i2A = b.i2A, *__restrict x21 = b.l21, *__restrict x31 = b.x2, *__restrict y31 = b.y2;
      double *__restrict dNx = b.dNx[gp][a], *__restrict dNy = b.dNy[gp][a];
      for (std::size_t l = 0; l < n; ++l) {
        dNx[l] = y31[l] * dxi * i2A[l];  // y21 = 0
        dNy[l] = (-x31[l] * dxi + x21[l] * deta) * i2A[l];
      }
    }
}

}  // namespace

ShellKernelTotals tria_dkt_forces(ShellGroupData& g, const ShellNodalView& nv,
                                  const ShellSlotOut& out, double dt,
                                  std::span<const std::int32_t> elements) {
  ShellKernelTotals tot;
  const ShellMaterial& mat = g.mat;
  const ShellSection& sec = g.sec;
  const int np = sec.n_points;
  const double E = mat.young(), nu = mat.poisson();
  const double cwave = g.wave_speed;
  const double hdt = 0.5 * dt;
  static thread_local TriaLanes lanes;
  TriaLanes& b = lanes;
  constexpr std::size_t W = TriaLanes::W;

  for (std::size_t k0 = 0; k0 < elements.size(); k0 += W) {
    const std::size_t n = std::min(W, elements.size() - k0);
    const std::int32_t* idx = elements.data() + k0;
    const bool consecutive = static_cast<std::size_t>(idx[n - 1] - idx[0]) == n - 1;
    // Gather: mid-step geometry x^{n-1/2} = x^n - dt/2 v^{n-1/2} (the velocity gradient
    // of a rigid rotation is then skew, so rotations strain nothing), v, omega, state.
    for (std::size_t l = 0; l < n; ++l) {
      const auto e = static_cast<std::size_t>(idx[l]);
      for (int i = 0; i < 3; ++i) b.node[i][l] = g.conn[e * 3 + static_cast<std::size_t>(i)];
      b.th.t[l] = g.thick[e];
      b.th.nfail[l] = g.n_failed[e];
      const double* m9 = &g.extra[e * 9];
      for (int c = 0; c < 9; ++c) b.md[c][l] = m9[c];
    }
    gather_positions<3>(b, n, nv, hdt);
    gather_spins<3>(b, n, nv);
    // Local frame: e1 along node 1 -> 2, e3 = r21 x r31 / |.|, e2 = e3 x e1; area.
    frame_lengths(b, n);
    for (std::size_t l = 0; l < n; ++l) {
      const auto e = static_cast<std::size_t>(idx[l]);
      const double A = 0.5 * b.sq[l];
      const bool good = !g.deleted[e] && A > 0.0 && b.l21[l] > 0.0;
      if (!g.deleted[e] && !(A > 0.0) && tot.inverted < 0) tot.inverted = static_cast<std::int64_t>(e);
      b.ok[l] = good ? 1.0 : 0.0;
      b.A[l] = good ? A : 1.0;  // masked lanes: finite stand-ins
      b.sq[l] = good ? b.sq[l] : 1.0;
      b.l21[l] = good ? b.l21[l] : 1.0;
    }
    local_frame(b, n);
    use_frozen_shape(b, n, g, idx);
    for (std::size_t l = 0; l < n; ++l) {
      const double exx = b.ex[0][l], exy = b.ex[1][l], exz = b.ex[2][l];
      const double eyx = b.ey[0][l], eyy = b.ey[1][l], eyz = b.ey[2][l];
      const double ezx = b.ez[0][l], ezy = b.ez[1][l], ezz = b.ez[2][l];
      for (int i = 0; i < 3; ++i) {
        const double Vx = b.VX[i][l], Vy = b.VY[i][l], Vz = b.VZ[i][l];
        const double Wx = b.WX[i][l], Wy = b.WY[i][l], Wz = b.WZ[i][l];
        b.vx[i][l] = Vx * exx + Vy * exy + Vz * exz;
        b.vy[i][l] = Vx * eyx + Vy * eyy + Vz * eyz;
        b.w[i][l] = Vx * ezx + Vy * ezy + Vz * ezz;
        b.bx[i][l] = Wx * eyx + Wy * eyy + Wz * eyz;     // beta_x = th_y
        b.by[i][l] = -(Wx * exx + Wy * exy + Wz * exz);  // beta_y = -th_x
      }
    }
    // CST membrane; DKT side geometry (lengths in a loop of their own).
    side_geometry(b, n);
    for (std::size_t l = 0; l < n; ++l) {
      double dxx = 0, dyy = 0, dxy = 0;
      for (int i = 0; i < 3; ++i) {
        dxx += b.B1[i][l] * b.vx[i][l];
        dyy += b.B2[i][l] * b.vy[i][l];
        dxy += b.B2[i][l] * b.vx[i][l] + b.B1[i][l] * b.vy[i][l];
      }
      b.th.dem[0][l] = dxx * dt; b.th.dem[1][l] = dyy * dt; b.th.dem[2][l] = dxy * dt;
    }
    // LAW42 keeps a total strain: the material's in-plane spin 1/2 (dvy/dx - dvx/dy) less the
    // frame's (edge 1-2 turns at (vy2 - vy1) / l21) turns it within the frame.
    const bool total_strain = mat.law == ShellLaw::Ogden;
    if (total_strain)
      for (std::size_t l = 0; l < n; ++l) {
        double w = 0;
        for (int i = 0; i < 3; ++i) w += b.B1[i][l] * b.vy[i][l] - b.B2[i][l] * b.vx[i][l];
        b.spin[l] = (0.5 * w - (b.vy[1][l] - b.vy[0][l]) / b.l21[l]) * dt;
      }
    for (int k = 0; k < 3; ++k) lanes::sqrt_lanes(n, b.sl[k]);
    // DKT: rotation rates at the 6 nodes, curvatures at the 3 Hammer points (loops with
    // the lanes innermost: side, node and point indices are constants of each loop).
    for (int i = 0; i < 3; ++i) {
      std::copy_n(b.bx[i], n, b.Bx[i]);
      std::copy_n(b.by[i], n, b.By[i]);
    }
    for (int k = 0; k < 3; ++k) {
      const int i = kSide[k][0], j = kSide[k][1];
      double *__restrict sc = b.sc[k], *__restrict ss = b.ss[k];
      const double* __restrict sl = b.sl[k];
      const double *__restrict bxi = b.bx[i], *__restrict bxj = b.bx[j], *__restrict byi = b.by[i],
                                *__restrict byj = b.by[j], *__restrict wi = b.w[i], *__restrict wj = b.w[j];
      double *__restrict Bxk = b.Bx[3 + k], *__restrict Byk = b.By[3 + k];
      for (std::size_t l = 0; l < n; ++l) {
        const double len = sl[l];
        const double c = sc[l] / len, s = ss[l] / len;
        sc[l] = c;
        ss[l] = s;
        const double bs = -1.5 / len * (wj[l] - wi[l]) - 0.25 * (c * (bxi[l] + bxj[l]) + s * (byi[l] + byj[l]));
        const double bn = 0.5 * (-s * (bxi[l] + bxj[l]) + c * (byi[l] + byj[l]));
        Bxk[l] = c * bs - s * bn;
        Byk[l] = s * bs + c * bn;
      }
    }
    // Cartesian derivatives at the 3 points: d/dx = (y31 d/dxi - y21 d/deta)/2A,
    // d/dy = (-x31 d/dxi + x21 d/deta)/2A (local x21 = l21, x31 = x2, y21 = 0, y31 = y2).
    for (std::size_t l = 0; l < n; ++l) b.i2A[l] = 0.5 / b.A[l];
    for (int gp = 0; gp < 3; ++gp) {
      double *__restrict q0 = b.kap[gp][0], *__restrict q1 = b.kap[gp][1], *__restrict q2 = b.kap[gp][2];
      std::fill_n(q0, W, 0.0);  // whole rows: stores inlined, no memset call
      std::fill_n(q1, W, 0.0);
      std::fill_n(q2, W, 0.0);
      for (int a = 0; a < 6; ++a) {
        const double dxi = kQD.dxi[gp][a], deta = kQD.deta[gp][a];
        const double *__restrict i2A = b.i2A, *__restrict x21 = b.l21, *__restrict x31 = b.x2, *__restrict y31 = b.y2;
        const double *__restrict Bxa = b.Bx[a], *__restrict Bya = b.By[a];
        double *__restrict dNx = b.dNx[gp][a], *__restrict dNy = b.dNy[gp][a];
#pragma GCC ivdep
        for (std::size_t l = 0; l < n; ++l) {
          const double nx = y31[l] * dxi * i2A[l];  // y21 = 0
          const double ny = (-x31[l] * dxi + x21[l] * deta) * i2A[l];
          dNx[l] = nx;
          dNy[l] = ny;
          q0[l] += nx * Bxa[l];
          q1[l] += ny * Bya[l];
          q2[l] += ny * Bxa[l] + nx * Bya[l];
        }
      }
    }
    for (int c = 0; c < 3; ++c)
      for (std::size_t l = 0; l < n; ++l) {
        const double kc = (b.kap[0][c][l] + b.kap[1][c][l] + b.kap[2][c][l]) / 3.0;
        b.th.dk[c][l] = kc * dt;
      }
    // Through the thickness (centroid curvature kc).
    b.th.integrate(g, idx, b.ok, n, dt, total_strain ? b.spin : nullptr);
    // Elastic moments of the linear curvature part (plate stiffness D_b, bending only
    // with more than one point through the thickness); generalised forces on the
    // 6-node rotations F = A/3 sum_g dN^T M_g; Kirchhoff constraints transposed onto the
    // corner DOFs (w, beta_x, beta_y).
    for (std::size_t l = 0; l < n; ++l) {
      const double t = b.th.t[l];
      const double alive = (static_cast<double>(np) - b.th.nfail[l]) / np;
      const double Db = np > 1 ? E * t * t * t / (12.0 * (1.0 - nu * nu)) * alive : 0.0;
      double kc[3];
      for (int c = 0; c < 3; ++c) kc[c] = (b.kap[0][c][l] + b.kap[1][c][l] + b.kap[2][c][l]) / 3.0;
      double dEdev = 0;
      for (int gp = 0; gp < 3; ++gp) {
        const double d0 = (b.kap[gp][0][l] - kc[0]) * dt, d1 = (b.kap[gp][1][l] - kc[1]) * dt,
                     d2 = (b.kap[gp][2][l] - kc[2]) * dt;
        const double o0 = b.md[3 * gp][l], o1 = b.md[3 * gp + 1][l], o2 = b.md[3 * gp + 2][l];
        const double m0 = o0 + Db * (d0 + nu * d1);
        const double m1 = o1 + Db * (nu * d0 + d1);
        const double m2 = o2 + Db * 0.5 * (1.0 - nu) * d2;
        b.md[3 * gp][l] = m0; b.md[3 * gp + 1][l] = m1; b.md[3 * gp + 2][l] = m2;
        dEdev += 0.5 * ((o0 + m0) * d0 + (o1 + m1) * d1 + (o2 + m2) * d2);
        b.Mg[gp][0][l] = b.th.M[0][l] + m0;
        b.Mg[gp][1][l] = b.th.M[1][l] + m1;
        b.Mg[gp][2][l] = b.th.M[2][l] + m2;
      }
      b.dEdev[l] = dEdev;
      b.dE[l] = b.A[l] * b.th.dE[l] + b.A[l] / 3.0 * dEdev;  // on the mid-step area
    }
    force_geometry(b, n, hdt, g, idx);
    for (std::size_t l = 0; l < n; ++l) {
      double Mg[3][3];
      for (int gp = 0; gp < 3; ++gp)
        for (int c = 0; c < 3; ++c) Mg[gp][c] = b.Mg[gp][c][l];
      const double A3 = b.A[l] / 3.0;
      double Fx[6] = {}, Fy[6] = {};
      for (int gp = 0; gp < 3; ++gp)
        for (int a = 0; a < 6; ++a) {
          Fx[a] += A3 * (b.dNx[gp][a][l] * Mg[gp][0] + b.dNy[gp][a][l] * Mg[gp][2]);
          Fy[a] += A3 * (b.dNy[gp][a][l] * Mg[gp][1] + b.dNx[gp][a][l] * Mg[gp][2]);
        }
      double Fw[3] = {0, 0, 0};
      for (int k = 0; k < 3; ++k) {
        const int i = kSide[k][0], j = kSide[k][1];
        const double c = b.sc[k][l], s = b.ss[k][l], len = b.sl[k][l];
        const double Fs = c * Fx[3 + k] + s * Fy[3 + k];
        const double Fn = -s * Fx[3 + k] + c * Fy[3 + k];
        Fw[j] -= 1.5 / len * Fs;
        Fw[i] += 1.5 / len * Fs;
        const double gx = -0.25 * c * Fs - 0.5 * s * Fn;  // d/d beta_x(i) and (j)
        const double gy = -0.25 * s * Fs + 0.5 * c * Fn;
        Fx[i] += gx; Fx[j] += gx;
        Fy[i] += gy; Fy[j] += gy;
      }
      for (int i = 0; i < 3; ++i) {
        b.Fx[i][l] = Fx[i];
        b.Fy[i][l] = Fy[i];
        b.Fw[i][l] = Fw[i];
      }
    }
    // Nodal force and moment ON the nodes (minus the internal ones), global frame.
    // Written straight into the slot buffers when the batch's elements are consecutive,
    // else into the lanes and copied per element below.
    double* const slot_out[6] = {out.fx, out.fy, out.fz, out.mx, out.my, out.mz};
    double* dst[6];
    for (int c = 0; c < 6; ++c)
      dst[c] = consecutive ? slot_out[c] + static_cast<std::size_t>(idx[0]) * 3 : b.f[c];
    double *const f0 = dst[0], *const f1 = dst[1], *const f2 = dst[2], *const f3 = dst[3], *const f4 = dst[4],
                  *const f5 = dst[5];
#pragma GCC ivdep
    for (std::size_t l = 0; l < n; ++l)
#pragma GCC unroll 3
      for (int i = 0; i < 3; ++i) {
        const double A = b.A[l];
        const double fx = A * (b.B1[i][l] * b.th.N[0][l] + b.B2[i][l] * b.th.N[2][l]);
        const double fy = A * (b.B2[i][l] * b.th.N[1][l] + b.B1[i][l] * b.th.N[2][l]);
        const double fz = b.Fw[i][l];
        const double mx = -b.Fy[i][l];  // beta_y = -th_x
        const double my = b.Fx[i][l];   // beta_x = th_y
        const double exx = b.ex[0][l], exy = b.ex[1][l], exz = b.ex[2][l];
        const double eyx = b.ey[0][l], eyy = b.ey[1][l], eyz = b.ey[2][l];
        const double ezx = b.ez[0][l], ezy = b.ez[1][l], ezz = b.ez[2][l];
        const bool ok = b.okf[l] != 0.0;
        f0[3 * l + static_cast<std::size_t>(i)] = ok ? -(fx * exx + fy * eyx + fz * ezx) : 0.0;
        f1[3 * l + static_cast<std::size_t>(i)] = ok ? -(fx * exy + fy * eyy + fz * ezy) : 0.0;
        f2[3 * l + static_cast<std::size_t>(i)] = ok ? -(fx * exz + fy * eyz + fz * ezz) : 0.0;
        f3[3 * l + static_cast<std::size_t>(i)] = ok ? -(mx * exx + my * eyx) : 0.0;
        f4[3 * l + static_cast<std::size_t>(i)] = ok ? -(mx * exy + my * eyy) : 0.0;
        f5[3 * l + static_cast<std::size_t>(i)] = ok ? -(mx * exz + my * eyz) : 0.0;
      }
    // Stable step on the current geometry: min(l_c, l_c^2 / t) / c, l_c = 2A / longest side.
    // l_c / c is the membrane step; l_c^2 / (c t) the flexural one of a plate thicker than its
    // cell. With lumped masses the highest bending mode (transverse displacement alternating
    // from node to node, curvature ~ 8 w / l^2) has omega^2 = 64 D / (rho t l^4) =
    // 16/3 c^2 t^2 / l^4: a step 2 / omega = 0.87 l^2 / (c t), below l / c once t > 0.87 l.
    // Rings of triangles 1.3-4 l_c thick run stable up to 1.5-2 l_c^2 / (c t) and blow up at
    // the membrane step (ctest/solver/shells_thick_plate_verification.cpp).
    for (std::size_t l = 0; l < n; ++l) {
      double lmax2 = 0;
      for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const double dx = b.X[j][l] - b.X[i][l], dy = b.Y[j][l] - b.Y[i][l], dz = b.Z[j][l] - b.Z[i][l];
        const double l2 = ((0.0 + dx * dx) + dy * dy) + dz * dz;
        lmax2 = std::max(lmax2, l2);
      }
      b.lmax2[l] = lmax2 > 0.0 ? lmax2 : 1.0;
    }
    lanes::sqrt_lanes(n, b.lmax2);
    for (std::size_t l = 0; l < n; ++l) {
      const double lc = 2.0 * b.A[l] / b.lmax2[l];
      b.dte[l] = std::min(lc, lc * lc / b.th.t[l]) / cwave;
    }
    g.use_frozen_steps(b.dte, idx, n);
    // Slots of a batch with gaps (elements inside a rigid body left out), then the state
    // (masked lanes: zero slots; deleted elements no step; degenerate ones keep their
    // state).
    if (!consecutive)
      for (std::size_t l = 0; l < n; ++l)
        for (int c = 0; c < 6; ++c)
          std::copy_n(b.f[c] + 3 * l, 3, slot_out[c] + static_cast<std::size_t>(idx[l]) * 3);
    for (std::size_t l = 0; l < n; ++l) {
      const auto e = static_cast<std::size_t>(idx[l]);
      if (g.deleted[e]) {
        g.dt_elem[e] = 1e300;
        continue;
      }
      if (b.ok[l] == 0.0) continue;
      double* m9 = &g.extra[e * 9];
      for (int c = 0; c < 9; ++c) m9[c] = b.md[c][l];
      const int nf = static_cast<int>(b.th.nfail[l]);
      g.n_failed[e] = static_cast<std::uint8_t>(nf);
      const double dE = b.dE[l];
      g.eint[e] += dE;
      tot.de_int += dE;
      if (sec.thickness_change) g.thick[e] = b.th.t[l] * (1.0 + b.th.dezz[l]);
      g.area[e] = b.A[l];
      g.dt_elem[e] = b.dte[l];
      const double nrm[3] = {b.ez[0][l], b.ez[1][l], b.ez[2][l]};
      if (double* f = g.freeze_if_due(e, b.dte[l], b.A[l], nrm)) {
        f[0] = b.l21[l];
        f[1] = b.x2[l];
        f[2] = b.y2[l];
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
