// SPDX-License-Identifier: GPL-3.0-or-later
// Unit test (label unit): a shell group's forces, energies, time step and deletions are
// bitwise the same with 1 and 2 OpenMP threads (fixed chunks, chunk-order reductions).
// 2000 triangles and 1000 quads (several chunks of kChunk), elastoplastic with failure,
// 40 cycles of a stretching + bending velocity field.
#include "shells/shell_element_group.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>

using namespace hbm::solver;
using namespace hbm::solver::shells;

namespace {

struct Result {
  std::vector<double> fx, mz, stress;
  double eint = 0, ehg = 0, dt = 0;
  std::int64_t eroded = 0;
};

Result run(bool tria, int threads) {
  omp_set_num_threads(threads);
  const std::size_t nx = tria ? 32 : 32;
  NodalState nodes;
  nodes.resize((nx + 1) * (nx + 1));
  for (std::size_t i = 0; i <= nx; ++i)
    for (std::size_t j = 0; j <= nx; ++j) {
      const std::size_t n = i * (nx + 1) + j;
      const double x = static_cast<double>(i), y = static_cast<double>(j);
      nodes.x.x[n] = x + 0.1 * std::sin(1.3 * y);
      nodes.x.y[n] = y;
      nodes.x.z[n] = 0.05 * std::sin(0.7 * x) * std::cos(0.4 * y);
      nodes.v.x[n] = 0.05 * x;
      nodes.v.y[n] = -0.01 * y;
      nodes.v.z[n] = 1e-3 * (x * x - y * y);
      nodes.omega.x[n] = 2e-3 * y;
      nodes.omega.y[n] = 2e-3 * x;
    }
  ShellElementGroup g;
  g.nodes_per_element = tria ? 3 : 4;
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < nx; ++j) {
      const Index a = static_cast<Index>(i * (nx + 1) + j), b = a + static_cast<Index>(nx + 1),
                  c = b + 1, d = a + 1;
      if (tria) {
        for (Index k : {a, b, c, a, c, d}) g.connectivity.push_back(k);
      } else {
        for (Index k : {a, b, c, d}) g.connectivity.push_back(k);
      }
    }
  g.n_elements = g.connectivity.size() / g.nodes_per_element;
  for (std::size_t e = 0; e < g.n_elements; ++e) {
    g.element_id.push_back(static_cast<std::int64_t>(e + 1));
    g.data.thick.push_back(0.5);
  }
  g.data.mat.law = ShellLaw::JohnsonCook;
  g.data.mat.rho = 7.85e-6;
  g.data.mat.E = 210;
  g.data.mat.nu = 0.3;
  g.data.mat.plasticity.jc.a = 0.2;
  g.data.mat.plasticity.jc.b = 0.3;
  g.data.mat.plasticity.jc.n = 0.4;
  g.data.mat.plasticity.eps_p_max = 0.01;
  g.data.sec.set_points(3);
  EXPECT_EQ(g.initialize(nodes), kNoIndex);
  StepContext step;
  step.dt_prev = 0.01;
  Result r;
  for (int c = 0; c < 40; ++c) {
    GroupStepResult res;
    g.compute_forces(step, nodes, res);
    r.dt = res.dt_min;
    g.newly_eroded.clear();
  }
  r.fx = g.slot_force.x;
  r.mz = g.slot_moment.z;
  r.stress = g.data.stress;
  r.eint = g.energy.internal;
  r.ehg = g.energy.hourglass;
  r.eroded = g.n_eroded;
  return r;
}

void compare(bool tria) {
  const Result a = run(tria, 1), b = run(tria, 2);
  EXPECT_GT(a.eroded, 0);  // the failure path is exercised
  EXPECT_EQ(a.eroded, b.eroded);
  EXPECT_EQ(std::memcmp(&a.eint, &b.eint, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&a.ehg, &b.ehg, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&a.dt, &b.dt, sizeof(double)), 0);
  ASSERT_EQ(a.fx.size(), b.fx.size());
  EXPECT_EQ(std::memcmp(a.fx.data(), b.fx.data(), a.fx.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(a.mz.data(), b.mz.data(), a.mz.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(a.stress.data(), b.stress.data(), a.stress.size() * sizeof(double)), 0);
}

}  // namespace

TEST(ShellThreads, TriaGroupBitwiseSameWithOneAndTwoThreads) { compare(true); }
TEST(ShellThreads, QuadGroupBitwiseSameWithOneAndTwoThreads) { compare(false); }
