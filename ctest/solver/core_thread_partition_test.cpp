// SPDX-License-Identifier: GPL-3.0-or-later
// ThreadPartition (core/thread_partition.cpp): node ranges and chunk owners for several
// threads, and the cycle run over them.
//  - the ranges cover the nodes once, cut at node chunks; every chunk has an owner;
//  - on a uniform block (20 x 20 x 20 bricks, 63 chunks, numbered layer by layer) the
//    work of each thread is within one chunk of an even share, and at least 90 % of the
//    node references of a thread's chunks fall in its own node range (the point of it);
//  - the cycle gives bitwise the same positions, velocities and energies with 1, 2 and 3
//    threads (3 on a 2-core machine: a team larger than the cores, ranges taken modulo).
#include "hbm/solver/cycle.hpp"
#include "hbm/solver/thread_partition.hpp"
#include "solid/brick_block.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace hbm::solver {
namespace {

constexpr int kCells = 20;  // 8000 bricks: 63 chunks, one large group

void make_block(Model& m) {
  BrickBlock b;
  b.nx = b.ny = b.nz = kCells;
  b.lx = b.ly = b.lz = 10.0 * kCells;  // 10 mm cells
  b.material.rho = 1e-6;                // kg/mm^3
  b.material.set_elastic(0.2, 0.3);     // GPa
  make_brick_block(m, b);
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i) {  // smooth velocity field [mm/ms]
    m.nodes.v.x[i] = 0.5 * std::sin(0.01 * m.nodes.x.y[i]);
    m.nodes.v.z[i] = 0.5 * std::cos(0.013 * m.nodes.x.x[i]);
  }
  m.control.dt_scale = 0.9;
}

TEST(ThreadPartition, RangesCoverTheNodesAndTheWorkIsSharedWhereTheNodesAre) {
  Model m;
  make_block(m);
  const ElementGroup& g = *m.groups[0];
  const std::size_t nch = g.n_force_chunks();
  ASSERT_EQ(nch, 63u);
  for (int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    ThreadPartition p;
    const std::vector<std::uint8_t> run_whole(m.groups.size(), 0);
    p.build(m, threads, run_whole);
    EXPECT_TRUE(p.active_for(threads));
    ASSERT_EQ(p.node_begin.size(), static_cast<std::size_t>(threads) + 1);
    EXPECT_EQ(p.node_begin.front(), 0u);
    EXPECT_EQ(p.node_begin.back(), m.nodes.n_nodes);
    for (int t = 1; t < threads; ++t) {
      EXPECT_LE(p.node_begin[t - 1], p.node_begin[t]);
      EXPECT_EQ(p.node_begin[t] % kChunk, 0u) << t;
    }
    ASSERT_EQ(g.chunk_thread.size(), nch);
    std::vector<std::size_t> elements(threads, 0), refs(threads, 0), own_refs(threads, 0);
    std::vector<Index> chunk;
    for (std::size_t ch = 0; ch < nch; ++ch) {
      const std::size_t t = g.chunk_thread[ch];
      ASSERT_LT(t, static_cast<std::size_t>(threads));
      g.force_chunk_elements(ch, chunk);
      elements[t] += chunk.size();
      for (Index e : chunk)
        for (std::size_t k = 0; k < 8; ++k) {
          const auto n = static_cast<std::size_t>(g.connectivity[static_cast<std::size_t>(e) * 8 + k]);
          ++refs[t];
          own_refs[t] += n >= p.node_begin[t] && n < p.node_begin[t + 1];
        }
    }
    const double even = static_cast<double>(g.n_elements) / threads;
    for (int t = 0; t < threads; ++t) {
      EXPECT_NEAR(static_cast<double>(elements[t]), even, 1.5 * kChunk) << "thread " << t;
      EXPECT_GE(static_cast<double>(own_refs[t]), 0.9 * static_cast<double>(refs[t])) << "thread " << t;
    }
  }
}

struct BlockState {
  std::vector<double> x, v;
  GlobalEnergies energies;
};

BlockState run_block(int threads, int cycles) {
#ifdef _OPENMP
  omp_set_num_threads(threads);
#endif
  Model m;
  make_block(m);
  CycleState c;
  for (int k = 0; k < cycles; ++k) run_cycle(m, c);
  if (threads > 1) {
    EXPECT_TRUE(c.partition.active_for(threads)) << threads;
  }
  BlockState s;
  for (const auto* a : {&m.nodes.x.x, &m.nodes.x.y, &m.nodes.x.z}) s.x.insert(s.x.end(), a->begin(), a->end());
  for (const auto* a : {&m.nodes.v.x, &m.nodes.v.y, &m.nodes.v.z}) s.v.insert(s.v.end(), a->begin(), a->end());
  s.energies = c.energies;
  return s;
}

TEST(ThreadPartition, CycleIsBitwiseTheSameFor1And2And3Threads) {
#ifdef _OPENMP
  const int saved = omp_get_max_threads();
#endif
  const BlockState one = run_block(1, 40);
  // Something moved (else the comparison says little).
  double moved = 0.0;
  Model m0;
  make_block(m0);
  for (std::size_t i = 0; i < m0.nodes.n_nodes; ++i) moved = std::max(moved, std::abs(one.x[i] - m0.nodes.x.x[i]));
  EXPECT_GT(moved, 1e-3);
  EXPECT_GT(one.energies.internal, 0.0);
  for (int threads : {2, 3}) {
    const BlockState other = run_block(threads, 40);
    EXPECT_TRUE(one.x == other.x) << threads << " threads: positions differ";
    EXPECT_TRUE(one.v == other.v) << threads << " threads: velocities differ";
    EXPECT_EQ(one.energies.internal, other.energies.internal) << threads;
    EXPECT_EQ(one.energies.hourglass, other.energies.hourglass) << threads;
    EXPECT_EQ(one.energies.kinetic, other.energies.kinetic) << threads;
  }
#ifdef _OPENMP
  omp_set_num_threads(saved);
#endif
}

}  // namespace
}  // namespace hbm::solver
