// SPDX-License-Identifier: GPL-3.0-or-later
// Gather of the nodal fields of a shell batch into its lanes (shell_quad_bt.cpp,
// shell_tria_dkt.cpp; B is the kernel's lane struct with node[i][l] and the [node][lane]
// arrays X Y Z, VX VY VZ, WX WY WZ). Plain scalar loads, one node index read for several
// fields: GCC vectorises a one-field loop with vgatherdpd, which measured slower than
// plain loads here (hbm-shells-bench 4-node shell 103 -> 86 ns on the 2-core machine), so
// these loops are kept scalar (no-tree-vectorize on these functions only).
#pragma once

#include "shells/shell_group_data.hpp"

#include <cstddef>
#include <cstdint>

namespace hbm::solver::shells {

// Velocities and the mid-step positions x^{n-1/2} = x^n - dt/2 v^{n-1/2}.
template <int NPE, class B>
__attribute__((optimize("no-tree-vectorize"))) void gather_positions(B& b, std::size_t n, const ShellNodalView& nv,
                                                                     double hdt) {
  const double *__restrict x = nv.x, *__restrict y = nv.y, *__restrict z = nv.z;
  const double *__restrict vx = nv.vx, *__restrict vy = nv.vy, *__restrict vz = nv.vz;
  for (int i = 0; i < NPE; ++i)
    for (std::size_t l = 0; l < n; ++l) {
      const auto k = static_cast<std::size_t>(b.node[i][l]);
      const double u = vx[k], v = vy[k], w = vz[k];
      b.VX[i][l] = u;
      b.VY[i][l] = v;
      b.VZ[i][l] = w;
      b.X[i][l] = x[k] - hdt * u;
      b.Y[i][l] = y[k] - hdt * v;
      b.Z[i][l] = z[k] - hdt * w;
    }
}

// Angular velocities.
template <int NPE, class B>
__attribute__((optimize("no-tree-vectorize"))) void gather_spins(B& b, std::size_t n, const ShellNodalView& nv) {
  const double *__restrict wx = nv.wx, *__restrict wy = nv.wy, *__restrict wz = nv.wz;
  for (int i = 0; i < NPE; ++i)
    for (std::size_t l = 0; l < n; ++l) {
      const auto k = static_cast<std::size_t>(b.node[i][l]);
      b.WX[i][l] = wx[k];
      b.WY[i][l] = wy[k];
      b.WZ[i][l] = wz[k];
    }
}

}  // namespace hbm::solver::shells
