// SPDX-License-Identifier: GPL-3.0-or-later
// Verification (label verification), kernel level, elastoplastic shells:
//  1. Three-point bending of a plate strip (span S = 100 mm, b = 10 mm, t = 2 mm, LAW2
//     perfectly plastic sigma_y = 0.3 GPa, 9 Gauss points through the thickness), centre
//     line pushed down slowly on roller supports: the load levels at the plastic limit
//     P = 4 M_p / S, M_p = sigma_y t^2 b / 4, within 5%.
//  2. A strip (50 x 10 x 1 mm, LAW2 a = 0.3, b = 0.2, n = 0.5, EPS_p_max = 0.1) pulled at
//     one end until its points reach EPS_p_max: the elements are deleted when the
//     (logarithmic) strain is eps_p_max + sigma_y(eps_p_max) / E (1%), and after the
//     deletion the energy balance W_ext = E_int + E_kin still closes within 1%
//     (deleted elements keep their internal energy); the strip is cut (the first
//     row to fail unloads the others) and the pulled end carries no force afterwards.
#include "shells_harness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace hbm::solver::shells;
using hbm::solver::shells::test::build_strip;
using hbm::solver::shells::test::ShellHarness;

namespace {

double three_point_limit_load(bool tria) {
  const double S = 100, b = 10, t = 2, E = 210, rho = 7.85e-6, sy = 0.3;
  // One element across the width: the prescribed centre-line w then leaves the
  // anticlastic curvature free (with a middle node held level too, the strip would be
  // forced towards plane strain and M_p would rise by 2/sqrt(3)).
  const int nx = 40, ny = 1;
  ShellHarness h;
  build_strip(h, tria, S, b, nx, ny, t);
  h.g.mat.law = ShellLaw::JohnsonCook;
  h.g.mat.rho = rho;
  h.g.mat.E = E;
  h.g.mat.nu = 0.3;
  h.g.mat.plasticity.jc.a = sy;
  h.g.mat.plasticity.jc.b = 0;
  h.g.sec.set_points(9);
  h.finish();
  auto id = [&](int i, int j) { return i * (ny + 1) + j; };
  for (int j = 0; j <= ny; ++j) {
    h.fixed[id(0, j)][2] = 1;   // rollers: w = 0 at both supports
    h.fixed[id(nx, j)][2] = 1;
    h.fixed[id(nx / 2, j)][2] = 1;  // centre line: prescribed w
  }
  h.fixed[id(0, 0)][0] = h.fixed[id(0, 0)][1] = 1;  // rigid in-plane motion
  h.fixed[id(nx, 0)][1] = 1;
  const double I = b * t * t * t / 12;
  const double P_lim = sy * t * t * b / S;
  const double delta_e = P_lim * S * S * S / (48 * E * I);
  const double f1 = std::numbers::pi / (2 * S * S) * std::sqrt(E * I / (rho * b * t));
  const double T1 = 1 / f1, t_load = 15 * T1, delta_end = 3.0 * delta_e;
  const double vmax = delta_end / (t_load - 2 * T1);  // cosine ramp over 2 periods
  auto vel = [&](double tt) {
    return -vmax * (tt < 2 * T1 ? 0.5 * (1 - std::cos(std::numbers::pi * tt / (2 * T1))) : 1.0);
  };
  const std::size_t c0 = static_cast<std::size_t>(id(nx / 2, 0));
  const std::size_t c1 = static_cast<std::size_t>(id(nx / 2, ny));
  auto prescribed = [&](std::size_t n, int c, double tt) {
    return (c == 2 && n >= c0 && n <= c1) ? vel(tt) : 0.0;
  };
  h.damping = 0.05 * 2 * std::numbers::pi * f1;
  h.forces(0.0);
  double dt = 1e300;
  for (double d : h.g.dt_elem) dt = std::min(dt, d);
  dt *= 0.8;
  double P = 0, Pavg = 0;
  int navg = 0;
  while (h.time < t_load) {
    h.step(dt, prescribed);
    P = 0;
    for (std::size_t n = c0; n <= c1; ++n) P -= h.reaction[n][2];
    if (h.time > t_load - T1) {  // average over the last period (inertia ripple)
      Pavg += P;
      ++navg;
    }
  }
  Pavg /= navg;
  const double centre = -h.z[c0];
  std::printf("%s: 3-point bending load %.5f kN at %.3f mm (P_lim %.5f kN, %+.2f%%)\n",
              tria ? "SH3N DKT" : "SHELL BT", Pavg, centre, P_lim, 100 * (Pavg / P_lim - 1));
  return Pavg / P_lim;
}

struct PullResult {
  double strain_at_deletion = 0, strain_expected = 0, energy_error = 0, w_ext = 0;
  double end_force_peak = 0;  // pulled-end reaction [kN]
  bool cut = false;           // no live element path from the fixed to the pulled end
  std::size_t deleted = 0, n = 0;
};

PullResult pull_to_failure(bool tria) {
  const double L = 50, b = 10, t = 1, E = 210, rho = 7.85e-6;
  const int nx = 10, ny = 2;
  ShellHarness h;
  build_strip(h, tria, L, b, nx, ny, t);
  h.g.mat.law = ShellLaw::JohnsonCook;
  h.g.mat.rho = rho;
  h.g.mat.E = E;
  h.g.mat.nu = 0.3;
  h.g.mat.plasticity.jc.a = 0.3;
  h.g.mat.plasticity.jc.b = 0.2;
  h.g.mat.plasticity.jc.n = 0.5;
  h.g.mat.plasticity.eps_p_max = 0.1;
  h.g.sec.set_points(3);
  h.finish();
  auto id = [&](int i, int j) { return i * (ny + 1) + j; };
  for (int j = 0; j <= ny; ++j) {
    h.fixed[id(0, j)][0] = 1;
    h.fixed[id(nx, j)][0] = 1;
  }
  h.fixed[id(0, 0)][1] = 1;
  for (std::size_t n = 0; n < h.nn; ++n) h.fixed[n][2] = 1;  // stays in its plane
  const double v = 1.0;                                          // mm/ms
  const double t_ramp = 0.2;
  auto prescribed = [&](std::size_t n, int c, double tt) {
    if (c == 0 && static_cast<int>(n) >= id(nx, 0))
      return v * std::min(1.0, tt / t_ramp);
    return 0.0;
  };
  h.forces(0.0);
  double dt = 1e300;
  for (double d : h.g.dt_elem) dt = std::min(dt, d);
  dt *= 0.8;
  PullResult r;
  r.n = h.g.n;
  const auto& jc = h.g.mat.plasticity.jc;
  const double sy_f = jc.a + jc.b * std::sqrt(h.g.mat.plasticity.eps_p_max);
  r.strain_expected = h.g.mat.plasticity.eps_p_max + sy_f / E;
  bool first = true;
  double t_after = 1e300;
  while (h.time < t_after) {
    const ShellKernelTotals tot = h.step(dt, prescribed);
    double Fend = 0;
    for (int j = 0; j <= ny; ++j) Fend += h.reaction[id(nx, j)][0];
    r.end_force_peak = std::max(r.end_force_peak, Fend);
    if (tot.newly_deleted && first) {
      // Strain measured between the end node lines (log strain of the uniform strip).
      const double len = h.x[id(nx, 0)] - h.x[id(0, 0)];
      r.strain_at_deletion = std::log(len / L);
      first = false;
      t_after = h.time + 0.5;  // keep pulling the free nodes a while after deletion
    }
    if (h.time > 20) break;
  }
  for (auto d : h.g.deleted) r.deleted += d;
  // Is the pulled end still connected to the fixed end through live elements?
  std::vector<char> reached(h.nn, 0);
  for (int j = 0; j <= ny; ++j) reached[id(0, j)] = 1;
  const int npe = h.g.nodes_per_element;
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t e = 0; e < h.g.n; ++e) {
      if (h.g.deleted[e]) continue;
      bool any = false;
      for (int k = 0; k < npe; ++k) any = any || reached[h.g.conn[e * npe + k]];
      if (!any) continue;
      for (int k = 0; k < npe; ++k)
        if (!reached[h.g.conn[e * npe + k]]) reached[h.g.conn[e * npe + k]] = 1, grew = true;
    }
  }
  r.cut = true;
  for (int j = 0; j <= ny; ++j) r.cut = r.cut && !reached[id(nx, j)];
  r.w_ext = h.w_ext;
  r.energy_error = (h.internal() + h.kinetic() - h.w_ext) / h.w_ext;
  std::printf("%s: deleted %zu/%zu at log strain %.5f (expected %.5f), W_ext %.6f J, "
              "E_int %.6f J, E_kin %.6f J, balance error %.3e\n",
              tria ? "SH3N DKT" : "SHELL BT", r.deleted, r.n, r.strain_at_deletion,
              r.strain_expected, h.w_ext, h.internal(), h.kinetic(), r.energy_error);
  return r;
}

}  // namespace

TEST(ShellPlastic, QuadThreePointBendingReachesPlasticLimitLoad) {
  EXPECT_NEAR(three_point_limit_load(false), 1.0, 0.05);
}
TEST(ShellPlastic, TriaThreePointBendingReachesPlasticLimitLoad) {
  EXPECT_NEAR(three_point_limit_load(true), 1.0, 0.05);
}

TEST(ShellPlastic, QuadPulledStripDeletedAtEpsPMaxEnergyBalanced) {
  const PullResult r = pull_to_failure(false);
  EXPECT_GE(r.deleted, 2u);  // at least one row across the width: the strip is cut
  EXPECT_TRUE(r.cut);
  EXPECT_GT(r.end_force_peak, 0.0);
  EXPECT_NEAR(r.strain_at_deletion, r.strain_expected, 0.01 * r.strain_expected);
  EXPECT_LT(std::abs(r.energy_error), 0.01);
}
TEST(ShellPlastic, TriaPulledStripDeletedAtEpsPMaxEnergyBalanced) {
  const PullResult r = pull_to_failure(true);
  EXPECT_GE(r.deleted, 4u);
  EXPECT_TRUE(r.cut);
  EXPECT_GT(r.end_force_peak, 0.0);
  EXPECT_NEAR(r.strain_at_deletion, r.strain_expected, 0.01 * r.strain_expected);
  EXPECT_LT(std::abs(r.energy_error), 0.01);
}
