// SPDX-License-Identifier: GPL-3.0-or-later
// Test harness for the shell kernels, independent of the engine core: a flat or curved
// mesh of one shell group, lumped masses (m = rho t A / npe per node, rotational
// inertia m (t^2 + A) / 12, the engine's rule), fixed DOFs and a central-difference loop
// with optional mass-proportional damping (dynamic relaxation for static answers).
#pragma once

#include "shells/shell_group_data.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace hbm::solver::shells::test {

struct ShellHarness {
  std::size_t nn = 0;
  std::vector<double> x, y, z, vx, vy, vz, wx, wy, wz;
  std::vector<double> m, I;
  std::vector<std::array<double, 6>> f;      // assembled force/moment on nodes
  std::vector<std::array<double, 6>> fext;   // external loads
  std::vector<std::array<std::uint8_t, 6>> fixed;
  std::vector<std::array<double, 6>> reaction;  // reaction on prescribed DOFs, last step
  ShellGroupData g;
  std::vector<double> sfx, sfy, sfz, smx, smy, smz;  // slot buffers
  std::vector<std::int32_t> all;                     // element list handed to the kernel
  double time = 0, dt_last = 0;
  double w_ext = 0;       // external work (loads + reactions of prescribed DOFs)
  double damping = 0;     // mass-proportional damping coefficient [1/time]

  int add_node(double px, double py, double pz) {
    x.push_back(px); y.push_back(py); z.push_back(pz);
    for (auto* a : {&vx, &vy, &vz, &wx, &wy, &wz, &m, &I}) a->push_back(0.0);
    f.push_back({}); fext.push_back({}); fixed.push_back({}); reaction.push_back({});
    return static_cast<int>(nn++);
  }
  void add_element(std::initializer_list<int> nodes, double t, std::int64_t id = 0) {
    for (int n : nodes) g.conn.push_back(n);
    g.thick.push_back(t);
    g.user_id.push_back(id ? id : static_cast<std::int64_t>(g.n + 1));
    g.part.push_back(0);
    ++g.n;
  }
  ShellNodalView view() const {
    return {x.data(), y.data(), z.data(), vx.data(), vy.data(), vz.data(),
            wx.data(), wy.data(), wz.data()};
  }
  // Allocates the group and lumps masses / inertias.
  void finish() {
    g.allocate();
    for (auto* a : {&sfx, &sfy, &sfz, &smx, &smy, &smz}) a->assign(g.n * g.nodes_per_element, 0.0);
    const int npe = g.nodes_per_element;
    for (std::size_t e = 0; e < g.n; ++e) {
      const double A = area(e);
      const double t = g.thick[e];
      const double me = g.mat.rho * t * A / npe;
      for (int k = 0; k < npe; ++k) {
        const auto n = g.conn[e * npe + k];
        m[n] += me;
        I[n] += me * (t * t + A) / 12.0;
      }
    }
  }
  double area(std::size_t e) const {
    const int npe = g.nodes_per_element;
    auto P = [&](int k) {
      const auto n = g.conn[e * npe + k];
      return std::array<double, 3>{x[n], y[n], z[n]};
    };
    auto cross_norm = [](std::array<double, 3> a, std::array<double, 3> b) {
      const double c0 = a[1] * b[2] - a[2] * b[1], c1 = a[2] * b[0] - a[0] * b[2],
                   c2 = a[0] * b[1] - a[1] * b[0];
      return std::sqrt(c0 * c0 + c1 * c1 + c2 * c2);
    };
    auto sub = [](std::array<double, 3> a, std::array<double, 3> b) {
      return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    };
    if (npe == 3) return 0.5 * cross_norm(sub(P(1), P(0)), sub(P(2), P(0)));
    return 0.5 * cross_norm(sub(P(2), P(0)), sub(P(3), P(1)));
  }
  // Element forces at the current state (dt: step the velocities acted over), assembled.
  ShellKernelTotals forces(double dt) {
    const ShellSlotOut out{sfx.data(), sfy.data(), sfz.data(), smx.data(), smy.data(), smz.data()};
    if (all.size() != g.n) {
      all.resize(g.n);
      for (std::size_t e = 0; e < g.n; ++e) all[e] = static_cast<std::int32_t>(e);
    }
    ShellKernelTotals tot = g.kind == ShellKind::QuadBT ? quad_bt_forces(g, view(), out, dt, all)
                                                         : tria_dkt_forces(g, view(), out, dt, all);
    for (auto& a : f) a.fill(0.0);
    const std::size_t nslot = g.n * static_cast<std::size_t>(g.nodes_per_element);
    for (std::size_t s = 0; s < nslot; ++s) {
      auto& fn = f[static_cast<std::size_t>(g.conn[s])];
      fn[0] += sfx[s]; fn[1] += sfy[s]; fn[2] += sfz[s];
      fn[3] += smx[s]; fn[4] += smy[s]; fn[5] += smz[s];
    }
    return tot;
  }
  double kinetic() const {
    double k = 0;
    for (std::size_t n = 0; n < nn; ++n)
      k += 0.5 * m[n] * (vx[n] * vx[n] + vy[n] * vy[n] + vz[n] * vz[n]) +
           0.5 * I[n] * (wx[n] * wx[n] + wy[n] * wy[n] + wz[n] * wz[n]);
    return k;
  }
  double internal() const {
    double s = 0;
    for (std::size_t e = 0; e < g.n; ++e) s += g.eint[e] + g.ehg[e];
    return s;
  }
  // One central-difference cycle with step dt. `prescribed(n, c, t)` returns the
  // velocity of fixed DOF c of node n at time t (fixed DOFs default to 0).
  // The external work counts applied loads and the reactions on prescribed DOFs
  // (reaction = -internal-force on that DOF, trapezoidal in time).
  ShellKernelTotals step(double dt,
                         const std::function<double(std::size_t, int, double)>& prescribed = {}) {
    ShellKernelTotals tot = forces(dt_last);
    auto vel = [&](std::size_t n, int c) -> double& {
      switch (c) {
        case 0: return vx[n]; case 1: return vy[n]; case 2: return vz[n];
        case 3: return wx[n]; case 4: return wy[n]; default: return wz[n];
      }
    };
    for (std::size_t n = 0; n < nn; ++n)
      for (int c = 0; c < 6; ++c) {
        double& v = vel(n, c);
        const double mass = c < 3 ? m[n] : I[n];
        const double ftot = f[n][c] + fext[n][c];
        if (fixed[n][c]) {
          const double vnew = prescribed ? prescribed(n, c, time + 0.5 * dt) : 0.0;
          // Reaction R with m (vnew - v)/dt = ftot + R; its work R * vmid * dt.
          const double R = mass * (vnew - v) / dt - ftot;
          w_ext += (R + fext[n][c]) * 0.5 * (v + vnew) * dt;
          reaction[n][c] = R;
          v = vnew;
        } else {
          const double vold = v;
          const double a = ftot / mass;
          v = (v * (1.0 - 0.5 * damping * dt) + dt * a) / (1.0 + 0.5 * damping * dt);
          w_ext += fext[n][c] * 0.5 * (vold + v) * dt;
        }
      }
    for (std::size_t n = 0; n < nn; ++n) {
      x[n] += dt * vx[n];
      y[n] += dt * vy[n];
      z[n] += dt * vz[n];
    }
    time += dt;
    dt_last = dt;
    return tot;
  }
};

// Flat rectangular strip [0, L] x [0, b] at z = 0, nx x ny cells, quads or each cell
// split into two triangles (alternating diagonals). Returns node index (i, j) -> i*(ny+1)+j.
inline void build_strip(ShellHarness& h, bool tria, double L, double b, int nx, int ny,
                        double t) {
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) h.add_node(L * i / nx, b * j / ny, 0.0);
  auto id = [&](int i, int j) { return i * (ny + 1) + j; };
  h.g.kind = tria ? ShellKind::TriaDKT : ShellKind::QuadBT;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const int a = id(i, j), b2 = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (!tria) {
        h.add_element({a, b2, c, d}, t);
      } else if ((i + j) % 2 == 0) {
        h.add_element({a, b2, c}, t);
        h.add_element({a, c, d}, t);
      } else {
        h.add_element({a, b2, d}, t);
        h.add_element({b2, c, d}, t);
      }
    }
}

}  // namespace hbm::solver::shells::test
