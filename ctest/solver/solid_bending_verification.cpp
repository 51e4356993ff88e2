// SPDX-License-Identifier: GPL-3.0-or-later
// Coarse-mesh cantilever in bending (one brick through the thickness), plane strain:
// the first natural frequency against Euler-Bernoulli beam theory,
//   f1 = (1.8751^2 / 2 pi) sqrt(E' I / (rho A L^4)),  E' = E / (1 - nu^2),
// for the one-point brick with its hourglass forms. One element through the thickness
// carries the whole bending strain in the hourglass modes, so the hourglass stiffness
// decides the frequency: the physical form with the plane-stress bending coefficients
// (Icpre 0, Belytschko & Bindeman 1993) must be close to the beam, for a compressible
// (nu 0.3) and a nearly incompressible (nu 0.4999) material (no volumetric locking);
// the deviatoric-only form (Icpre 1) is too soft by sqrt((4/3 G) / E') and the viscous form
// has no bending stiffness at all. Energy is conserved in the physical form.
#include "hbm/solver/cycle.hpp"
#include "loads/loads.hpp"
#include "solid/brick_block.hpp"
#include "solid_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace hbm::solver {
namespace {

struct BendingResult {
  double f_fem = 0;      // measured first frequency [1/time]
  double f_beam = 0;     // Euler-Bernoulli [1/time]
  double energy_error = 0;
  double hourglass_fraction = 0;  // max over the run of E_hg / (E_int + E_hg)
};

// Cantilever along x, L = 80, h = 10 (z), width 10 (y), 8 x 1 x 1 bricks, clamped at x = 0,
// y fixed everywhere (plane strain). Initial velocity in the first beam mode shape.
BendingResult cantilever(double nu, HourglassForm form, int icpre, double angle = 0.0) {
  Model m;
  BrickBlock b;
  b.nx = 8;
  b.ny = 1;
  b.nz = 1;
  b.lx = 80;
  b.ly = 10;
  b.lz = 10;
  b.material.rho = 1e-6;
  b.material.set_elastic(0.2, nu);
  b.hourglass = form;
  SolidGroup& g = make_brick_block(m, b);
  g.icpre = icpre;
  g.qa = g.qb = 0.0;  // no bulk viscosity: undamped oscillation
  auto clamp = std::make_unique<FixedDofs>();
  clamp->fixed = {true, true, true, false, false, false};
  auto plane = std::make_unique<FixedDofs>();
  plane->fixed = {false, true, false, false, false, false};
  std::size_t tip = 0;
  const double L = b.lx;
  const double v0 = 1e-3;  // tip velocity [length/time]: small, linear
  auto phi = [&](double x) { return testing::cantilever_first_mode(x, L); };
  const double phi_tip = phi(L);
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i) {
    const double x = m.nodes.x.x[i];
    if (x < 1e-9) clamp->nodes.push_back(static_cast<Index>(i));
    plane->nodes.push_back(static_cast<Index>(i));
    m.nodes.v.z[i] = v0 * phi(x) / phi_tip;
    if (x > L - 1e-9 && m.nodes.x.z[i] < 1e-9 && m.nodes.x.y[i] < 1e-9) tip = i;
  }
  // Turn the beam about y by `angle` (positions, velocities): the response is objective.
  const double ca = std::cos(angle), sa = std::sin(angle);
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i) {
    const double x = m.nodes.x.x[i], z = m.nodes.x.z[i], vx = m.nodes.v.x[i], vz = m.nodes.v.z[i];
    m.nodes.x.x[i] = m.nodes.x0.x[i] = ca * x - sa * z;
    m.nodes.x.z[i] = m.nodes.x0.z[i] = sa * x + ca * z;
    m.nodes.v.x[i] = ca * vx - sa * vz;
    m.nodes.v.z[i] = sa * vx + ca * vz;
  }
  g.initialize(m.nodes);
  m.constraints.push_back(std::move(clamp));
  m.constraints.push_back(std::move(plane));
  m.control.dt_scale = 0.9;

  BendingResult r;
  const double E1 = 0.2 / (1.0 - nu * nu), h = b.lz;
  r.f_beam = 1.8751 * 1.8751 / (2.0 * std::numbers::pi) * std::sqrt(E1 * h * h / (12.0 * b.material.rho * std::pow(L, 4)));
  CycleState c;
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i)
    c.energies.initial_total += 0.5 * m.nodes.mass[i] * (m.nodes.v.x[i] * m.nodes.v.x[i] + m.nodes.v.z[i] * m.nodes.v.z[i]);
  std::vector<double> up;  // downward zero crossings of the tip displacement
  double z_prev = 0.0, t_prev = 0.0;
  const double t_end = 4.0 / r.f_beam;
  // The tip starts at z = 0 moving up: its downward crossings (z from + to -) come at
  // T/2, 3T/2, ...
  while (c.step.time < t_end) {
    run_cycle(m, c);
    const double z = sa * (m.nodes.x.x[tip] - m.nodes.x0.x[tip]) + ca * (m.nodes.x.z[tip] - m.nodes.x0.z[tip]);
    const double t = c.step.time;
    if (z_prev > 0.0 && z <= 0.0) up.push_back(t_prev + (t - t_prev) * z_prev / (z_prev - z));
    z_prev = z;
    t_prev = t;
    const double ie = c.energies.internal, he = c.energies.hourglass;
    if (ie + he > 0) r.hourglass_fraction = std::max(r.hourglass_fraction, he / (ie + he));
    if (c.stop != StopReason::None || up.size() >= 2) break;
  }
  r.f_fem = up.size() >= 2 ? 1.0 / (up[1] - up[0]) : 0.0;
  r.energy_error = c.energies.energy_error();
  std::printf("nu %.4f form %d icpre %d: f %.5f beam %.5f ratio %.4f energy error %.2e\n", nu,
              static_cast<int>(form), icpre, r.f_fem, r.f_beam, r.f_fem / r.f_beam, r.energy_error);
  return r;
}

TEST(SolidBending, PhysicalHourglassMatchesBeamTheoryCompressible) {
  const BendingResult r = cantilever(0.3, HourglassForm::Physical, 0);
  EXPECT_NEAR(r.f_fem / r.f_beam, 1.0, 0.05) << "f " << r.f_fem << " beam " << r.f_beam;
  EXPECT_LT(std::abs(r.energy_error), 1e-6);
}

TEST(SolidBending, PhysicalHourglassNearlyIncompressibleDoesNotLock) {
  const BendingResult r = cantilever(0.4999, HourglassForm::Physical, 0);
  EXPECT_NEAR(r.f_fem / r.f_beam, 1.0, 0.05) << "f " << r.f_fem << " beam " << r.f_beam;
  EXPECT_LT(std::abs(r.energy_error), 1e-6);
}

TEST(SolidBending, PhysicalHourglassIsObjective) {
  // The same beam turned by 35 degrees about y: same frequency (corotational frame).
  const BendingResult a = cantilever(0.3, HourglassForm::Physical, 0);
  const BendingResult b = cantilever(0.3, HourglassForm::Physical, 0, 35.0 * std::numbers::pi / 180.0);
  EXPECT_NEAR(b.f_fem / a.f_fem, 1.0, 1e-3) << "f " << b.f_fem << " unrotated " << a.f_fem;
  EXPECT_LT(std::abs(b.energy_error), 1e-6);
}

TEST(SolidBending, DeviatoricOnlyFormIsTooSoftInBending) {
  // Icpre 1: bending modulus 4/3 G instead of E' = 2G/(1 - nu): f ratio sqrt(2(1 - nu)/3).
  const BendingResult r = cantilever(0.4999, HourglassForm::Physical, 1);
  EXPECT_NEAR(r.f_fem / r.f_beam, std::sqrt(2.0 * (1.0 - 0.4999) / 3.0), 0.05)
      << "f " << r.f_fem << " beam " << r.f_beam;
}

TEST(SolidBending, ViscousFormHasNoBendingStiffness) {
  const BendingResult r = cantilever(0.3, HourglassForm::Viscous, 0);
  EXPECT_LT(r.f_fem / r.f_beam, 0.5) << "f " << r.f_fem << " beam " << r.f_beam;
}

}  // namespace
}  // namespace hbm::solver
