// SPDX-License-Identifier: GPL-3.0-or-later
// Run-time choice of the OpenMP thread count (hbm-solver without --threads): results do
// not depend on the thread count (bitwise), so the run may switch between cycles. On a
// small machine shared with other processes, more threads can be slower than one (every
// parallel region waits for a thread the scheduler gave to someone else). The chooser
// times a window of cycles with each candidate count (1 and the OpenMP maximum), keeps
// the faster one for a stretch of cycles, then measures again (the load changes).
#pragma once

#include <cstdint>
#include <string>

namespace hbm::solver {

class ThreadChooser {
 public:
  // max_threads <= 1: nothing to choose (always 1 / the fixed count).
  explicit ThreadChooser(int max_threads, int window = 20, int stretch = 2000);

  // Thread count for the next cycle (call before it, then set it in OpenMP).
  int next_threads();
  // Wall seconds the cycle took with the count next_threads() returned.
  void cycle_done(double seconds);

  // Cycles run with 1 thread and with the maximum.
  std::int64_t cycles_one() const { return cycles_[0]; }
  std::int64_t cycles_max() const { return cycles_[1]; }
  int max_threads() const { return max_; }
  // Last comparison, e.g. "1 thread 2.10 ms/cycle, 2 threads 9.70 ms/cycle -> 1".
  const std::string& last_choice() const { return last_; }

 private:
  enum class Phase : std::uint8_t { ProbeMax, ProbeOne, Run };
  int max_, window_, stretch_;
  Phase phase_ = Phase::ProbeMax;
  int count_ = 0;            // cycles done in the current phase
  double sum_ = 0.0;         // seconds in the current probe
  double per_max_ = 0.0;     // seconds per cycle with max_ threads (last probe)
  int chosen_ = 1;
  int current_ = 1;
  std::int64_t cycles_[2] = {0, 0};
  std::string last_;
};

}  // namespace hbm::solver
