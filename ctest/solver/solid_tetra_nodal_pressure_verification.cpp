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
#include "hbm/solver/cycle.hpp"
#include "loads/loads.hpp"
#include "solid/brick_block.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <vector>

namespace hbm::solver {
namespace {

// The six tetras of a brick (nodes 0-3 bottom, 4-7 top) around its diagonal 0-6: each face
// is cut along its diagonal through node 0 or node 6, so neighbouring bricks of a
// structured block, all oriented alike, share their face diagonals.
constexpr int kKuhn[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};

// Structured block (brick_block) with its group replaced by tetras on the same nodes;
// `distort` moves interior nodes before V0 and masses are computed.
SolidGroup& make_tetra_block(Model& m, const BrickBlock& b, bool nodal_pressure, bool distort = false) {
  SolidGroup& bricks = make_brick_block(m, b);
  if (distort)
    for (std::size_t i = 0; i < m.nodes.n_nodes; ++i) {
      const double x = m.nodes.x.x[i], y = m.nodes.x.y[i], z = m.nodes.x.z[i];
      const double t = 1e-6 * (b.lx + b.ly + b.lz);
      if (x > t && x < b.lx - t && y > t && y < b.ly - t && z > t && z < b.lz - t) {
        m.nodes.x.x[i] += 2.0 * std::sin(0.3 * static_cast<double>(i));
        m.nodes.x.y[i] += 1.5 * std::cos(0.7 * static_cast<double>(i));
        m.nodes.x.z[i] -= 1.8 * std::sin(1.1 * static_cast<double>(i));
      }
    }
  m.nodes.x0 = m.nodes.x;
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
  g->n_elements = g->element_id.size();
  EXPECT_EQ(g->initialize(m.nodes), kNoIndex);
  std::fill(m.nodes.mass0.begin(), m.nodes.mass0.end(), 0.0);
  for (std::size_t e = 0; e < g->n_elements; ++e)
    for (int a = 0; a < 4; ++a) m.nodes.mass0[static_cast<std::size_t>(g->connectivity[e * 4 + a])] += g->mass[e] / 4;
  m.nodes.mass = m.nodes.mass0;
  SolidGroup& ref = *g;
  m.groups[0] = std::move(g);
  build_incidence(m);
  return ref;
}

SolidMaterial flesh() {
  SolidMaterial mat;
  mat.rho = 1.02e-6;
  mat.law = SolidLaw::Viscoelastic;
  mat.set_viscoelastic(0.12875, 5.15e-6, 1.5e-6, 0.1);  // K, G0, Ginf [GPa], beta 100 /s
  return mat;
}

BrickBlock patch_block(const SolidMaterial& mat) {
  BrickBlock b;
  b.nx = b.ny = b.nz = 3;
  b.lx = b.ly = b.lz = 30;
  b.material = mat;
  return b;
}

// Largest net force on an interior node of the 30 mm block.
double max_interior_force(const Model& m, const SolidGroup& g) {
  std::vector<double> fx(m.nodes.n_nodes, 0.0), fy = fx, fz = fx;
  for (std::size_t sl = 0; sl < g.connectivity.size(); ++sl) {
    const auto n = static_cast<std::size_t>(g.connectivity[sl]);
    fx[n] += g.slot_force.x[sl];
    fy[n] += g.slot_force.y[sl];
    fz[n] += g.slot_force.z[sl];
  }
  double f = 0.0;
  for (std::size_t i = 0; i < fx.size(); ++i) {
    const double x = m.nodes.x0.x[i], y = m.nodes.x0.y[i], z = m.nodes.x0.z[i];
    if (x > 1 && x < 29 && y > 1 && y < 29 && z > 1 && z < 29)
      f = std::max(f, std::sqrt(fx[i] * fx[i] + fy[i] * fy[i] + fz[i] * fz[i]));
  }
  return f;
}

// Drive the block with v = A (x - 15) (A fixed) for n steps of dt.
void drive_linear(Model& m, SolidGroup& g, const double A[3][3], double dt, int n) {
  NodalState& s = m.nodes;
  StepContext step;
  GroupStepResult res;
  for (int k = 0; k <= n; ++k) {
    for (std::size_t i = 0; i < s.n_nodes; ++i) {
      const double r[3] = {s.x.x[i] - 15.0, s.x.y[i] - 15.0, s.x.z[i] - 15.0};
      s.v.x[i] = A[0][0] * r[0] + A[0][1] * r[1] + A[0][2] * r[2];
      s.v.y[i] = A[1][0] * r[0] + A[1][1] * r[1] + A[1][2] * r[2];
      s.v.z[i] = A[2][0] * r[0] + A[2][1] * r[1] + A[2][2] * r[2];
    }
    if (k > 0) {
      for (std::size_t i = 0; i < s.n_nodes; ++i) {
        s.x.x[i] += dt * s.v.x[i];
        s.x.y[i] += dt * s.v.y[i];
        s.x.z[i] += dt * s.v.z[i];
      }
      step.dt_prev = dt;
      step.time += dt;
    }
    g.compute_forces(step, s, res);
  }
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

struct BendingResult {
  double f_fem = 0, f_beam = 0, energy_error = 0;
};

// Cantilever along x, L = 80, h = 10 (z), width 10 (y), nx x 1 x nz bricks of six tetras,
// clamped at x = 0, y fixed everywhere (plane strain); initial velocity in the first beam
// mode; frequency from two downward zero crossings of the tip.
BendingResult cantilever(double nu, bool nodal_pressure, int nx, int nz, bool plane_strain = true) {
  Model m;
  BrickBlock b;
  b.nx = nx;
  b.ny = 1;
  b.nz = nz;
  b.lx = 80;
  b.ly = 10;
  b.lz = 10;
  b.material.rho = 1e-6;
  b.material.set_elastic(0.2, nu);
  SolidGroup& g = make_tetra_block(m, b, nodal_pressure);
  g.qa = g.qb = 0.0;  // undamped
  auto clamp = std::make_unique<FixedDofs>();
  clamp->fixed = {true, true, true, false, false, false};
  auto plane = std::make_unique<FixedDofs>();
  plane->fixed = {false, true, false, false, false, false};
  std::size_t tip = 0;
  const double L = b.lx, beta = 1.8751 / L, sigma = 0.7341, v0 = 1e-3;
  auto phi = [&](double x) {
    const double s = beta * x;
    return std::cosh(s) - std::cos(s) - sigma * (std::sinh(s) - std::sin(s));
  };
  const double phi_tip = phi(L);
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i) {
    const double x = m.nodes.x.x[i];
    if (x < 1e-9) clamp->nodes.push_back(static_cast<Index>(i));
    if (plane_strain) plane->nodes.push_back(static_cast<Index>(i));
    m.nodes.v.z[i] = v0 * phi(x) / phi_tip;
    if (x > L - 1e-9 && m.nodes.x.y[i] < 1e-9 &&
        (m.nodes.x.x[tip] < L - 1e-9 || std::abs(m.nodes.x.z[i] - 5.0) < std::abs(m.nodes.x.z[tip] - 5.0)))
      tip = i;
  }
  m.constraints.push_back(std::move(clamp));
  m.constraints.push_back(std::move(plane));
  m.control.dt_scale = 0.9;
  BendingResult r;
  const double E1 = plane_strain ? 0.2 / (1.0 - nu * nu) : 0.2, h = b.lz;
  r.f_beam = 1.8751 * 1.8751 / (2.0 * std::numbers::pi) * std::sqrt(E1 * h * h / (12.0 * b.material.rho * std::pow(L, 4)));
  CycleState c;
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i)
    c.energies.initial_total += 0.5 * m.nodes.mass[i] * m.nodes.v.z[i] * m.nodes.v.z[i];
  std::vector<double> down;
  double z_prev = 0.0, t_prev = 0.0;
  const double t_end = 4.0 / r.f_beam;
  while (c.step.time < t_end) {
    run_cycle(m, c);
    const double zt = m.nodes.x.z[tip] - m.nodes.x0.z[tip];
    const double t = c.step.time;
    if (z_prev > 0.0 && zt <= 0.0) down.push_back(t_prev + (t - t_prev) * z_prev / (z_prev - zt));
    z_prev = zt;
    t_prev = t;
    if (c.stop != StopReason::None || down.size() >= 2) break;
  }
  r.f_fem = down.size() >= 2 ? 1.0 / (down[1] - down[0]) : 0.0;
  r.energy_error = c.energies.energy_error();
  std::printf("tetra nu %.4f nodal pressure %d plane strain %d mesh %dx1x%d: f %.5f beam %.5f ratio %.4f energy error %.2e cycles %lld\n", nu,
              nodal_pressure ? 1 : 0, plane_strain ? 1 : 0, nx, nz, r.f_fem, r.f_beam, r.f_fem / r.f_beam, r.energy_error,
              static_cast<long long>(c.step.cycle));
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

TEST(SolidTetraNodalPressureDeck, UnsupportedItetra4IsADeckError) {
#ifdef HBM_SOLVER_EXE
  // The tetra example deck with Itetra4 1 in /PROP/TYPE14 line 3 (columns 61-70).
  const auto dir = std::filesystem::current_path() / "tetra_bad_itetra4";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::string deck = testing::read_text(testing::example_deck("tetra_prism_uniaxial"));
  const std::string good = "/PROP/TYPE14/1\nsolid\n         0\n";
  const auto at = deck.find(good);
  ASSERT_NE(at, std::string::npos);
  deck.replace(at, good.size(), "/PROP/TYPE14/1\nsolid\n         0         0         0         0         0         0         1\n");
  std::ofstream(dir / "bad_0000.rad") << deck;
  std::filesystem::copy_file(std::filesystem::path(HBM_SOURCE_DIR) /
                                 "decks/examples/tetra_prism_uniaxial/tetra_prism_uniaxial_0001.rad",
                             dir / "bad_0001.rad", std::filesystem::copy_options::overwrite_existing);
  const std::string cmd = std::string("'") + HBM_SOLVER_EXE + "' '" + (dir / "bad_0000.rad").string() + "' --out '" +
                          (dir / "out").string() + "' > '" + (dir / "log").string() + "' 2>&1";
  EXPECT_NE(std::system(cmd.c_str()), 0);
  const std::string log = testing::read_text(dir / "log");
  EXPECT_NE(log.find("bad_0000.rad:37: error: /PROP/TYPE14/1 field Itetra4"), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "no output folder on a deck error";
#else
  GTEST_SKIP() << "hbm-solver was not built";
#endif
}

}  // namespace
}  // namespace hbm::solver
