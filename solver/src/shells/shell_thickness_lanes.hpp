// SPDX-License-Identifier: GPL-3.0-or-later
// Through-thickness integration of a batch of shell elements as lanes (element k of the
// batch is lane k), shared by the quad and triangle kernels. Elastic law: the
// expressions of integrate_thickness (shell_through_thickness.hpp) over the lanes, point
// after point, in loops GCC vectorises; other laws: integrate_thickness per lane.
// Lanes with ok[l] == 0 (deleted or folded elements) keep their stresses.
#pragma once

#include "shells/shell_group_data.hpp"
#include "shells/shell_through_thickness.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace hbm::solver::shells {

template <std::size_t W>
struct ThicknessLanes {
  alignas(64) double dem[3][W], dk[3][W];  // membrane, curvature increments (in)
  alignas(64) double t[W], nfail[W];       // thickness, failed points (nfail updated)
  alignas(64) double N[3][W], M[3][W];     // resultants (out)
  alignas(64) double dE[W], dezz[W];       // energy per area, thickness strain (out)
  alignas(64) double sig[kMaxThicknessPoints][3][W];

  // Integrates lanes 0..n-1 of elements idx[0..n-1] of group g over the step dt. spin: the
  // in-plane rotation of the material relative to the element frame per lane (update_point's
  // dspin), or nullptr (none).
  void integrate(ShellGroupData& g, const std::int32_t* idx, const double* ok, std::size_t n, double dt,
                 const double* spin = nullptr) {
    const ShellMaterial& mat = g.mat;
    const ShellSection& sec = g.sec;
    const auto np = static_cast<std::size_t>(sec.n_points);
    if (mat.law != ShellLaw::Elastic) {
      const int nh = mat.n_history();
      for (std::size_t l = 0; l < n; ++l) {
        for (int c = 0; c < 3; ++c) N[c][l] = M[c][l] = 0.0;
        dE[l] = dezz[l] = 0.0;
        if (ok[l] == 0.0) continue;
        const auto e = static_cast<std::size_t>(idx[l]);
        const double dm[3] = {dem[0][l], dem[1][l], dem[2][l]};
        const double dc[3] = {dk[0][l], dk[1][l], dk[2][l]};
        // A filtered rate (LAW36 with rate curves, LAW2 with F_cut): one for the element's points (OpenRadioss).
        double rate = -1.0;
        if (!g.eps_rate.empty() && dt > 0.0)
          rate = filtered_strain_rate(mat.plasticity.rate_filter, dt, element_strain_rate(dm, dc, t[l], dt),
                                      g.eps_rate[e]);
        ThicknessResult tr;
        integrate_thickness(mat, sec, t[l], dm, dc, dt, &g.stress[e * np * 3], &g.epsp[e * np],
                            nh ? &g.hist[e * np * static_cast<std::size_t>(nh)] : nullptr, tr, rate,
                            spin ? spin[l] : 0.0);
        for (int c = 0; c < 3; ++c) {
          N[c][l] = tr.N[c];
          M[c][l] = tr.M[c];
        }
        dE[l] = tr.dE;
        dezz[l] = tr.dezz;
        nfail[l] += tr.newly_failed;
      }
      return;
    }
    // Elastic: plane-stress Hooke (never fails), bitwise the expressions of
    // integrate_thickness.
    const double nu = mat.nu, cE = mat.E / (1.0 - nu * nu), cG = cE * 0.5 * (1.0 - nu), cz = -nu / mat.E;
    for (std::size_t l = 0; l < n; ++l) {
      const double* sp = &g.stress[static_cast<std::size_t>(idx[l]) * np * 3];
      for (std::size_t p = 0; p < np; ++p)
        for (int c = 0; c < 3; ++c) sig[p][c][l] = sp[3 * p + static_cast<std::size_t>(c)];
    }
    for (int c = 0; c < 3; ++c) {  // whole rows: stores inlined, no memset call
      std::fill_n(N[c], W, 0.0);
      std::fill_n(M[c], W, 0.0);
    }
    std::fill_n(dE, W, 0.0);
    std::fill_n(dezz, W, 0.0);
    for (std::size_t p = 0; p < np; ++p) {
      const double zeta = sec.zeta[p], wp = sec.weight[p];
      // Local restrict pointers: the loop then vectorises (through the thread_local
      // struct GCC finds no vector type).
      double *__restrict s0p = sig[p][0], *__restrict s1p = sig[p][1], *__restrict s2p = sig[p][2];
      const double* __restrict tl = t;
      const double *__restrict dm0 = dem[0], *__restrict dm1 = dem[1], *__restrict dm2 = dem[2];
      const double *__restrict dk0 = dk[0], *__restrict dk1 = dk[1], *__restrict dk2 = dk[2];
      double *__restrict e = dE, *__restrict ez = dezz;
      double *__restrict N0 = N[0], *__restrict N1 = N[1], *__restrict N2 = N[2];
      double *__restrict M0 = M[0], *__restrict M1 = M[1], *__restrict M2 = M[2];
      for (std::size_t l = 0; l < n; ++l) {
        const double ht = 0.5 * tl[l];
        const double z = zeta * ht;
        const double de0 = dm0[l] + z * dk0[l], de1 = dm1[l] + z * dk1[l], de2 = dm2[l] + z * dk2[l];
        const double s0 = s0p[l], s1 = s1p[l], s2 = s2p[l];
        const double n0 = s0 + cE * (de0 + nu * de1);
        const double n1 = s1 + cE * (nu * de0 + de1);
        const double n2 = s2 + cG * de2;
        const double dezz_p = cz * (n0 + n1 - (s0 + s1));
        const double w = wp * ht;
        e[l] += 0.5 * w * ((s0 + n0) * de0 + (s1 + n1) * de1 + (s2 + n2) * de2);
        ez[l] += 0.5 * wp * dezz_p;
        s0p[l] = n0;
        s1p[l] = n1;
        s2p[l] = n2;
        const double wz = w * z;
        N0[l] += w * n0;
        N1[l] += w * n1;
        N2[l] += w * n2;
        M0[l] += wz * n0;
        M1[l] += wz * n1;
        M2[l] += wz * n2;
      }
    }
    for (std::size_t l = 0; l < n; ++l) {
      if (ok[l] == 0.0) continue;  // masked: stresses kept
      double* sp = &g.stress[static_cast<std::size_t>(idx[l]) * np * 3];
      for (std::size_t p = 0; p < np; ++p)
        for (int c = 0; c < 3; ++c) sp[3 * p + static_cast<std::size_t>(c)] = sig[p][c][l];
    }
  }
};

}  // namespace hbm::solver::shells
