// SPDX-License-Identifier: GPL-3.0-or-later
// Verification of the average nodal pressure tetra (/TETRA4 with /PROP/TYPE14 Itetra4 3,
// Bonet & Burton 1998; solver/src/solid/nodal_pressure_average.hpp), on blocks of bricks
// each cut into the six tetras around its main diagonal (conforming on a structured grid):
//  - patch tests on a distorted 3 x 3 x 3 block of the body model's flesh (LAW34, K/G0 =
//    25 000): uniform compression gives p = -K ln J in every tetra (every nodal volume
//    scales by J), simple shear follows the hereditary integral
//    s_xz(t) = Ginf g + (G0 - Ginf) gdot (1 - e^{-beta t}) / beta with p = 0, and the
//    interior nodes stay in equilibrium;
//  - plane-strain cantilever against Euler-Bernoulli, f1 = (1.8751^2 / 2 pi)
//    sqrt(E' I / (rho A L^4)), E' = E / (1 - nu^2): at nu = 0.4999 the element pressure
//    (constant strain tetra) locks, the nodal pressure keeps the ratio to the beam that the
//    compressible material (nu = 0.3) has; energy is conserved;
//  - Itetra4 1 in a deck is an error naming file, line and field.
#include "example_deck_runner.hpp"
#include "solid_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <vector>

namespace hbm::solver {
namespace {

using namespace testing;

// The six tetras of a brick (nodes 0-3 bottom, 4-7 top) around its diagonal 0-6: each face
// is cut along its diagonal through node 0 or node 6, so neighbouring bricks of a
// structured block, all oriented alike, share their face diagonals.
constexpr int kKuhn[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};

// Structured block (brick_block) with its group replaced by tetras on the same nodes;
// `distort` moves interior nodes before V0 and masses are computed.
SolidGroup& make_tetra_block(Model& m, const BrickBlock& b, bool nodal_pressure, bool distort = false) {
  SolidGroup& bricks = make_brick_block(m, b);
  if (distort) distort_interior(m, b);
  auto g = std::make_unique<SolidGroup>();
  g->keyword = "/TETRA4";
  g->part = 0;
  g->nodes_per_element = 4;
  g->material = b.material;
  g->nodal_pressure.enabled = nodal_pressure;
  for (std::size_t e = 0; e < bricks.n_elements; ++e)
    for (const auto& t : kKuhn) {
      Index n[4];
      for (int i = 0; i < 4; ++i) n[i] = bricks.connectivity[e * 8 + static_cast<std::size_t>(t[i])];
      // Positive volume: (n2 - n1) x (n3 - n1) . (n4 - n1) > 0, else swap two nodes.
      auto X = [&](Index k, int c) {
        const auto s = static_cast<std::size_t>(k);
        return c == 0 ? m.nodes.x.x[s] : c == 1 ? m.nodes.x.y[s] : m.nodes.x.z[s];
      };
      double a[3], c[3], d[3];
      for (int k = 0; k < 3; ++k) {
        a[k] = X(n[1], k) - X(n[0], k);
        c[k] = X(n[2], k) - X(n[0], k);
        d[k] = X(n[3], k) - X(n[0], k);
      }
      const double v = a[0] * (c[1] * d[2] - c[2] * d[1]) + a[1] * (c[2] * d[0] - c[0] * d[2]) + a[2] * (c[0] * d[1] - c[1] * d[0]);
      if (v < 0) std::swap(n[2], n[3]);
      for (Index k : n) g->connectivity.push_back(k);
      g->element_id.push_back(static_cast<std::int64_t>(g->element_id.size()) + 1);
    }
  return replace_block_group(m, std::move(g));
}

TEST(SolidTetraNodalPressurePatch, FleshCompressionGivesBulkPressure) {
  Model m;
  SolidGroup& g = make_tetra_block(m, patch_block(flesh()), true, true);
  g.qa = g.qb = 0.0;
  const double edot = 1e-3, dt = 1e-3;
  const int n = 1000;
  const double A[3][3] = {{-edot, 0, 0}, {0, -edot, 0}, {0, 0, -edot}};
  drive_linear(m, g, A, dt, n);
  // Each step moves x by dt A (x - 15): the volume ratio is (1 - edot dt)^(3n).
  const double lnJ = 3.0 * n * std::log(1.0 - edot * dt);
  const double p_expect = -g.material.K * lnJ;
  ASSERT_EQ(g.n_elements, 162u);
  for (std::size_t e = 0; e < g.n_elements; ++e) {
    double s[6];
    g.stress(e, s);
    EXPECT_NEAR(-(s[0] + s[1] + s[2]) / 3.0, p_expect, 1e-6 * p_expect) << "element " << e;
    EXPECT_NEAR(s[3], 0.0, 1e-9 * p_expect);
  }
  EXPECT_LT(max_interior_force(m, g), 1e-7 * p_expect * 100.0);
}

TEST(SolidTetraNodalPressurePatch, FleshShearFollowsLaw34WithoutPressure) {
  Model m;
  SolidGroup& g = make_tetra_block(m, patch_block(flesh()), true, true);
  const double gdot = 1e-3, dt = 1e-3;  // 0.01 engineering shear at 10 ms
  const int n = 10000;
  const double A[3][3] = {{0, 0, gdot}, {0, 0, 0}, {0, 0, 0}};
  drive_linear(m, g, A, dt, n);
  const SolidMaterial& mat = g.material;
  const double t = n * dt, beta = mat.beta;
  const double expect = mat.Ginf * gdot * t + (mat.G0 - mat.Ginf) * gdot * (1.0 - std::exp(-beta * t)) / beta;
  for (std::size_t e = 0; e < g.n_elements; ++e) {
    double s[6];
    g.stress(e, s);
    EXPECT_NEAR(s[5], expect, 1e-3 * expect) << "element " << e;
    EXPECT_NEAR((s[0] + s[1] + s[2]) / 3.0, 0.0, 1e-4 * expect) << "element " << e;
  }
  // Round-off of the nodal volumes times K = 25 000 G0: equilibrium to 1e-4 of the shear force.
  EXPECT_LT(max_interior_force(m, g), 1e-4 * expect * 100.0);
}

// The plastic laws run element by element (compute_tetra_scalar) with the same nodal
// pressure: a perfectly plastic LAW2 block (yield 1 MPa) compressed while sheared keeps the
// mean stress K ln J in every tetra (J2 plasticity does not touch it) and its von Mises
// stress at the yield stress once it flows.
TEST(SolidTetraNodalPressurePatch, PlasticBlockKeepsNodalPressureOnTheYieldSurface) {
  SolidMaterial mat;
  mat.rho = 7.8e-6;
  mat.law = SolidLaw::JohnsonCook;
  mat.set_elastic(210.0, 0.3);
  mat.plasticity.kind = PlasticityLaw::Kind::JohnsonCook;
  mat.plasticity.jc.a = 1e-3;  // 1 MPa, no hardening
  mat.plasticity.jc.b = 0.0;
  Model m;
  SolidGroup& g = make_tetra_block(m, patch_block(mat), true, true);
  g.qa = g.qb = 0.0;
  const double edot = 1e-4, gdot = 2e-4, dt = 1e-3;
  const int n = 200;
  const double A[3][3] = {{-edot, 0, gdot}, {0, -edot, 0}, {0, 0, -edot}};
  drive_linear(m, g, A, dt, n);
  const double lnJ = 3.0 * n * std::log(1.0 - edot * dt);  // det(I + dt A) = (1 - edot dt)^3
  for (std::size_t e = 0; e < g.n_elements; ++e) {
    double s[6];
    g.stress(e, s);
    EXPECT_NEAR((s[0] + s[1] + s[2]) / 3.0, mat.K * lnJ, 1e-6 * std::abs(mat.K * lnJ)) << "element " << e;
    EXPECT_NEAR(von_mises(s), 1e-3, 1e-9) << "element " << e;
  }
}

// Cantilever 80 x 10 x 10 of nx x 1 x nz bricks of six tetras (solid_test_support.hpp).
BendingResult cantilever(double nu, bool nodal_pressure, int nx, int nz, bool plane_strain) {
  Model m;
  const BrickBlock b = cantilever_block(nu, nx, nz);
  SolidGroup& g = make_tetra_block(m, b, nodal_pressure);
  g.qa = g.qb = 0.0;  // undamped
  const BendingResult r = run_cantilever(m, b, plane_strain);
  std::printf("tetra nu %.4f nodal pressure %d plane strain %d mesh %dx1x%d: f %.5f beam %.5f ratio %.4f energy error %.2e cycles %lld\n",
              nu, nodal_pressure ? 1 : 0, plane_strain ? 1 : 0, nx, nz, r.f_fem, r.f_beam, r.f_fem / r.f_beam,
              r.energy_error, r.cycles);
  return r;
}

// The beam free in y (3D, E' = E): a tetra mesh has 3 velocity components per node and,
// with the nodal pressure, one volume constraint per node; the element pressure puts one
// on each of the six tetras of a brick.
TEST(SolidTetraNodalPressureBending, NearlyIncompressibleDoesNotLock) {
  const BendingResult a = cantilever(0.3, true, 32, 4, false);
  const BendingResult b = cantilever(0.499, true, 32, 4, false);
  const double r = (b.f_fem / b.f_beam) / (a.f_fem / a.f_beam);
  EXPECT_GT(r, 0.98) << "nu 0.499 ratio " << b.f_fem / b.f_beam << " nu 0.3 ratio " << a.f_fem / a.f_beam;
  EXPECT_LT(r, 1.12) << "nu 0.499 ratio " << b.f_fem / b.f_beam << " nu 0.3 ratio " << a.f_fem / a.f_beam;
  EXPECT_LT(std::abs(b.energy_error), 1e-6);
}

TEST(SolidTetraNodalPressureBending, ElementPressureLocks) {
  const BendingResult a = cantilever(0.3, false, 32, 4, false);
  const BendingResult b = cantilever(0.499, false, 32, 4, false);
  EXPECT_GT((b.f_fem / b.f_beam) / (a.f_fem / a.f_beam), 2.5)
      << "nu 0.499 ratio " << b.f_fem / b.f_beam << " nu 0.3 ratio " << a.f_fem / a.f_beam;
}

// 12 288 tetras in 96 chunks, each a batch of lanes, and the serial nodal volume pass.
TEST(SolidTetraNodalPressureThreads, OneAndTwoThreadsBitwiseIdentical) {
  auto build = [](Model& m, const BrickBlock& b) {
    SolidGroup* g = &make_tetra_block(m, b, true);
    return [g](std::vector<double>& out) {
      for (const auto& c : g->sig) out.insert(out.end(), c.begin(), c.end());
      for (const auto& c : g->hist) out.insert(out.end(), c.begin(), c.end());
    };
  };
  const std::vector<double> a = run_block_on_threads(1, build), b = run_block_on_threads(2, build);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
}

TEST(SolidTetraNodalPressureDeck, UnsupportedItetra4IsADeckError) {
  // The tetra example deck with Itetra4 1 in /PROP/TYPE14 line 3 (columns 61-70).
  std::string out;
  EXPECT_EQ(run_modified_deck("tetra_prism_uniaxial", "itetra4", "/PROP/TYPE14/1\nsolid\n         0\n",
                              "/PROP/TYPE14/1\nsolid\n         0         0         0         0         0         0         1\n",
                              out),
            1);
  EXPECT_NE(out.find("tetra_prism_uniaxial_0000.rad:37: error: /PROP/TYPE14/1 field Itetra4"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::current_path() / ("bad_itetra4" + per_process_suffix()) / "out"))
      << "no output folder on a deck error";
}

}  // namespace
}  // namespace hbm::solver
