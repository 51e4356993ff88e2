// SPDX-License-Identifier: GPL-3.0-or-later
// Which thread does which part of a cycle when several run: each thread owns one range
// of node indices and the element chunks (and whole small groups) whose nodes lie
// mostly in that range. The nodal phases (assembly, velocity and position updates) run
// over the owned ranges, the element kernels over the owned chunks, so a thread's
// elements mostly read the positions and velocities the same thread wrote in the last
// cycle and its slot forces are mostly gathered by itself. Without this, with the nodal
// phases on one thread, the other core's kernels met every node's x and v in the first
// core's cache each cycle: on the 2-core machine the element kernels took 45-85 % more
// CPU time at 2 threads than at 1 (docs/engine-design.md section 14.7).
// Speed only: every element and every node is computed alone and every sum is reduced
// in a fixed order, so results are bitwise the same for any partition or thread count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace hbm::solver {

struct Model;

struct ThreadPartition {
  // Below this much element work per cycle (in one-point brick equivalents, about 0.15
  // us each) the whole cycle stays on one thread: a parallel region costs microseconds
  // on idle cores and up to a scheduler time slice when another process holds a core
  // (ctest -j2 running two threaded tests), which small models do not earn back.
  static constexpr double kMinSharedWork = 2048.0;

  // Cycles after which the partition is built again from the measured time of each group
  // (the static relative costs are estimates; the small groups' fixed cost per call is
  // not in them).
  static constexpr std::int64_t kMeasureCycles = 200;

  int threads = 0;                     // built for this many threads (0: not built)
  bool shared = false;                 // enough work to share (kMinSharedWork)
  bool measured = false;               // built from measured group times
  std::vector<std::size_t> node_begin; // threads + 1 bounds, multiples of kChunk but the last
  std::vector<std::uint8_t> group_thread;  // per group: owner when the group runs whole
  std::vector<double> work_share;          // per thread: its share of the element work

  // Builds for `n_threads` threads. run_whole[g] != 0: group g runs on one thread
  // (owned as one piece); else its force chunks are shared out (ElementGroup::chunk_thread
  // is set for every group). Work is weighed by ElementGroup::relative_element_cost; a
  // chunk or group sits at the median node index of its elements and goes to the
  // thread whose node range holds that index; the node ranges are cut where the
  // cumulative work, in node-index order, reaches k / n_threads of the total.
  // group_seconds (empty, or one per group): measured time of each group over the same
  // cycles, used instead of the relative costs (a chunk gets its group's time per element).
  void build(Model& m, int n_threads, std::span<const std::uint8_t> run_whole,
             std::span<const double> group_seconds = {});
  bool built_for(int n_threads) const { return threads == n_threads; }
  bool active_for(int n_threads) const { return n_threads > 1 && threads == n_threads && shared; }
};

}  // namespace hbm::solver
