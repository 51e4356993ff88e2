// SPDX-License-Identifier: GPL-3.0-or-later
// Patch tests of the one-point brick with the physical hourglass form (Isolid 24,
// Icpre 0) for the body model's flesh (LAW34, K = 0.129 GPa, G0 = 5.15 kPa, K/G0 = 25 000)
// on a distorted 3 x 3 x 3 block driven by a linear velocity field:
//  - simple shear at constant rate: every element's shear stress follows the LAW34
//    hereditary integral exactly, s_xz(t) = Ginf g + (G0 - Ginf) gdot (1 - e^{-beta t}) / beta
//    (no locking: the pressure stays 0), the hourglass forces and energy are zero, and the
//    assembled force of every interior node is zero;
//  - uniform compression: p = -K ln(V/V0) in every element (hypoelastic bulk), interior
//    nodes in equilibrium.
#include "solid/brick_block.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace hbm::solver {
namespace {

struct Patch {
  Model m;
  SolidGroup* g = nullptr;
  std::vector<bool> interior;
};

void make_patch(Patch& p) {
  BrickBlock b;
  b.nx = b.ny = b.nz = 3;
  b.lx = b.ly = b.lz = 30;
  b.material.rho = 1.02e-6;
  b.material.law = SolidLaw::Viscoelastic;
  b.material.set_viscoelastic(0.12875, 5.15e-6, 1.5e-6, 0.1);  // flesh, beta 100 /s
  b.hourglass = HourglassForm::Physical;
  // Distort the interior nodes before the block is built (volumes from these positions).
  Model& m = p.m;
  p.g = &make_brick_block(m, b);
  p.interior.assign(m.nodes.n_nodes, false);
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i) {
    const double x = m.nodes.x.x[i], y = m.nodes.x.y[i], z = m.nodes.x.z[i];
    const bool in = x > 1 && x < 29 && y > 1 && y < 29 && z > 1 && z < 29;
    p.interior[i] = in;
    if (in) {
      m.nodes.x.x[i] += 2.0 * std::sin(0.3 * static_cast<double>(i));
      m.nodes.x.y[i] += 1.5 * std::cos(0.7 * static_cast<double>(i));
      m.nodes.x.z[i] -= 1.8 * std::sin(1.1 * static_cast<double>(i));
    }
  }
  m.nodes.x0 = m.nodes.x;
  p.g->icpre = 0;
  ASSERT_EQ(p.g->initialize(m.nodes), kNoIndex);
}

double max_interior_force(const Patch& p) {
  const SolidGroup& g = *p.g;
  std::vector<double> fx(p.m.nodes.n_nodes, 0.0), fy = fx, fz = fx;
  for (std::size_t sl = 0; sl < g.connectivity.size(); ++sl) {
    const auto n = static_cast<std::size_t>(g.connectivity[sl]);
    fx[n] += g.slot_force.x[sl];
    fy[n] += g.slot_force.y[sl];
    fz[n] += g.slot_force.z[sl];
  }
  double f = 0.0;
  for (std::size_t i = 0; i < fx.size(); ++i)
    if (p.interior[i]) f = std::max(f, std::sqrt(fx[i] * fx[i] + fy[i] * fy[i] + fz[i] * fz[i]));
  return f;
}

TEST(SolidIncompressiblePatch, ShearFollowsLaw34WithoutHourglass) {
  Patch p;
  make_patch(p);
  const double gdot = 1e-3, dt = 1e-3;  // engineering shear rate [1/ms]: 0.01 shear at 10 ms
  const int n = 10000;
  // v = gdot (z - 15) e_x: z does not change, so the field stays the same linear field.
  NodalState& s = p.m.nodes;
  StepContext step;
  GroupStepResult res;
  for (int k = 0; k <= n; ++k) {
    for (std::size_t i = 0; i < s.n_nodes; ++i) {
      s.v.x[i] = gdot * (s.x.z[i] - 15.0);
      s.v.y[i] = s.v.z[i] = 0.0;
    }
    if (k > 0) {
      for (std::size_t i = 0; i < s.n_nodes; ++i) s.x.x[i] += dt * s.v.x[i];
      step.dt_prev = dt;
      step.time += dt;
    }
    p.g->compute_forces(step, s, res);
  }
  const SolidMaterial& mat = p.g->material;
  const double t = n * dt, beta = mat.beta;
  const double expect = mat.Ginf * gdot * t + (mat.G0 - mat.Ginf) * gdot * (1.0 - std::exp(-beta * t)) / beta;
  for (std::size_t e = 0; e < p.g->n_elements; ++e) {
    double sg[6];
    p.g->stress(e, sg);
    EXPECT_NEAR(sg[5], expect, 1e-3 * expect) << "element " << e;  // zx
    EXPECT_NEAR((sg[0] + sg[1] + sg[2]) / 3.0, 0.0, 1e-4 * expect) << "element " << e;
    for (int a = 0; a < 12; ++a) EXPECT_NEAR(p.g->hg[static_cast<std::size_t>(a)][e], 0.0, 1e-12);
  }
  EXPECT_NEAR(p.g->energy.hourglass, 0.0, 1e-15);
  // Interior nodes: net force zero against the element force scale s_xz * face area.
  EXPECT_LT(max_interior_force(p), 1e-7 * expect * 100.0);
}

TEST(SolidIncompressiblePatch, CompressionGivesBulkPressureOnly) {
  Patch p;
  make_patch(p);
  const double edot = 1e-3, dt = 1e-3;  // volumetric rate 3 edot
  const int n = 1000;
  p.g->qa = p.g->qb = 0.0;  // bulk viscosity differs per element: leave it out here
  NodalState& s = p.m.nodes;
  StepContext step;
  GroupStepResult res;
  for (int k = 1; k <= n; ++k) {
    for (std::size_t i = 0; i < s.n_nodes; ++i) {
      s.v.x[i] = -edot * (s.x.x[i] - 15.0);
      s.v.y[i] = -edot * (s.x.y[i] - 15.0);
      s.v.z[i] = -edot * (s.x.z[i] - 15.0);
    }
    for (std::size_t i = 0; i < s.n_nodes; ++i) {
      s.x.x[i] += dt * s.v.x[i];
      s.x.y[i] += dt * s.v.y[i];
      s.x.z[i] += dt * s.v.z[i];
    }
    step.dt_prev = dt;
    step.time += dt;
    p.g->compute_forces(step, s, res);
  }
  // Volume ratio of every element: (1 - edot dt)^(3n).
  const double lnJ = 3.0 * n * std::log(1.0 - edot * dt);
  const double p_expect = -p.g->material.K * lnJ;
  for (std::size_t e = 0; e < p.g->n_elements; ++e) {
    double sg[6];
    p.g->stress(e, sg);
    EXPECT_NEAR(-(sg[0] + sg[1] + sg[2]) / 3.0, p_expect, 1e-6 * p_expect) << "element " << e;
    EXPECT_NEAR(sg[3], 0.0, 1e-9 * p_expect);
  }
  EXPECT_LT(max_interior_force(p), 1e-7 * p_expect * 100.0);
}

}  // namespace
}  // namespace hbm::solver
