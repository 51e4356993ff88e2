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
#include "solid_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace hbm::solver {
namespace {

struct Patch {
  Model m;
  SolidGroup* g = nullptr;
};

// The body model's flesh on the distorted 30 mm block (solid_test_support.hpp), Isolid 24.
void make_patch(Patch& p) {
  BrickBlock b = testing::patch_block(testing::flesh());
  b.hourglass = HourglassForm::Physical;
  p.g = &make_brick_block(p.m, b);
  testing::distort_interior(p.m, b);  // volumes below from these positions
  p.g->icpre = 0;
  ASSERT_EQ(p.g->initialize(p.m.nodes), kNoIndex);
}

double max_interior_force(const Patch& p) { return testing::max_interior_force(p.m, *p.g); }

TEST(SolidIncompressiblePatch, ShearFollowsLaw34WithoutHourglass) {
  Patch p;
  make_patch(p);
  const double gdot = 1e-3, dt = 1e-3;  // engineering shear rate [1/ms]: 0.01 shear at 10 ms
  const int n = 10000;
  // v = gdot (z - 15) e_x: z does not change, so the field stays the same linear field.
  const double A[3][3] = {{0, 0, gdot}, {0, 0, 0}, {0, 0, 0}};
  testing::drive_linear(p.m, *p.g, A, dt, n);
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
  const double A[3][3] = {{-edot, 0, 0}, {0, -edot, 0}, {0, 0, -edot}};
  testing::drive_linear(p.m, *p.g, A, dt, n);
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
