// SPDX-License-Identifier: GPL-3.0-or-later
// Verification (label verification), kernel level: a free plate of DKT triangles thicker
// than its cells (strip 40 x 10 mm, 8 x 2 cells split in triangles, t = 10 mm: t / l_c
// about 2.8; LAW1 E = 3.6 GPa, nu = 0.3, rho = 4.9e-7 kg/mm^3 as a model rib), released
// with transverse velocities alternating from node to node (the highest flexural mode of
// the lumped mesh). Run 4000 central-difference cycles at 0.9 x the kernel's own element
// step, recomputed every cycle: the energy kinetic + internal stays bounded (within a
// factor 3 of its initial value; no external work, no damping). At the membrane step
// l_c / c alone (the kernel's step before the flexural bound) the same plate blows up
// within a few hundred cycles; the step must hold min(l_c, l_c^2 / t) / c
// (shell_tria_dkt.cpp). The same plate of quads (Belytschko-Tsay) is bounded at its own
// membrane step.
#include "shells_harness.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

using namespace hbm::solver::shells;
using hbm::solver::shells::test::build_strip;
using hbm::solver::shells::test::ShellHarness;

namespace {

constexpr double kThickness = 10;  // mm, on 5 x 5 mm cells

// The free 40 x 10 mm strip, 8 x 2 cells (quads, or triangles), 10 mm thick, released with
// transverse velocities alternating from node to node (1 mm/ms).
ShellHarness thick_plate(bool tria) {
  const int nx = 8, ny = 2;
  ShellHarness h;
  build_strip(h, tria, 40, 10, nx, ny, kThickness);
  h.g.mat.law = ShellLaw::Elastic;
  h.g.mat.rho = 4.9e-7;
  h.g.mat.E = 3.6;
  h.g.mat.nu = 0.3;
  h.g.sec.set_points(3);
  h.finish();
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) h.vz[static_cast<std::size_t>(i * (ny + 1) + j)] = ((i + j) % 2 ? 1.0 : -1.0);
  h.forces(0.0);
  return h;
}

double own_step(const ShellHarness& h) { return 0.9 * *std::min_element(h.g.dt_elem.begin(), h.g.dt_elem.end()); }

// Lowest and highest energy (kinetic + internal) over the cycles relative to the initial
// one, on a copy of the harness; {0, inf} once it is no longer finite. Stable means
// bounded: in the highest mode near the stability limit the central-difference energy
// (kinetic energy of the half-step velocities plus strain energy) swings by a factor of
// about 2 while the discrete modified energy is conserved; an unstable step makes it grow
// without bound.
template <class StepOf>
std::pair<double, double> energy_bounds(ShellHarness h, StepOf step_of, int cycles) {
  const double e0 = h.kinetic() + h.internal();
  double lo = 1, hi = 1;
  for (int k = 0; k < cycles; ++k) {
    h.step(step_of(h));
    const double e = (h.kinetic() + h.internal()) / e0;
    if (!std::isfinite(e)) return {0.0, HUGE_VAL};
    lo = std::min(lo, e);
    hi = std::max(hi, e);
  }
  return {lo, hi};
}

TEST(ShellThickPlate, TriaIsStableAtItsOwnStepWhenThickerThanItsCells) {
  const ShellHarness h = thick_plate(true);
  const double c = std::sqrt(h.g.mat.E / (h.g.mat.rho * (1 - h.g.mat.nu * h.g.mat.nu)));
  const double lc = 2 * 12.5 / std::hypot(5.0, 5.0);  // 2A / longest side: half of a 5 x 5 mm cell
  const double dt_kernel = *std::min_element(h.g.dt_elem.begin(), h.g.dt_elem.end());
  // The kernel's step is the flexural bound l_c^2 / (c t), not the membrane l_c / c.
  EXPECT_NEAR(dt_kernel, lc * lc / (c * kThickness), 1e-9 * dt_kernel);
  EXPECT_LT(dt_kernel, 0.5 * lc / c);
  const auto own = energy_bounds(h, own_step, 4000);
  EXPECT_GT(own.first, 0.3);
  EXPECT_LT(own.second, 3.0);
  // The membrane step alone blows the same plate up within a few hundred cycles.
  const auto membrane = energy_bounds(h, [&](const ShellHarness&) { return 0.9 * lc / c; }, 500);
  EXPECT_GT(membrane.second, 1e3);
}

TEST(ShellThickPlate, QuadIsStableAtItsOwnStepWhenThickerThanItsCells) {
  // The same plate in 4-node Belytschko-Tsay shells: their step is the membrane one
  // (shell_quad_bt.cpp) and the plate stays bounded there, since the Mindlin element's
  // rotational inertia m (t^2 + A) / 12 carries its thick-plate modes.
  const auto own = energy_bounds(thick_plate(false), own_step, 4000);
  EXPECT_GT(own.first, 0.3);
  EXPECT_LT(own.second, 3.0);
}

}  // namespace
