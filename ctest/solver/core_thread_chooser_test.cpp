// SPDX-License-Identifier: GPL-3.0-or-later
// ThreadChooser (solver/src/core/thread_chooser.hpp) fed with made-up cycle timings: the
// schedule it documents (probe `window` + 1 cycles with the maximum, the same with one
// thread, the first cycle of each probe not counted, the faster count kept for `stretch`
// cycles, then probe again), the choice that follows from the timings (ties go to one
// thread), and the cycle counts and text it reports.
#include "core/thread_chooser.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

using hbm::solver::ThreadChooser;

namespace {

// Runs `cycles` cycles; `seconds(threads, cycle)` is the time the cycle "took". Returns the
// thread count of every cycle.
std::vector<int> drive(ThreadChooser& c, int cycles, const std::function<double(int, int)>& seconds) {
  std::vector<int> used;
  for (int k = 0; k < cycles; ++k) {
    const int n = c.next_threads();
    used.push_back(n);
    c.cycle_done(seconds(n, k));
  }
  return used;
}

std::vector<int> repeat(int threads, int n) { return std::vector<int>(static_cast<std::size_t>(n), threads); }

std::vector<int> concat(std::initializer_list<std::vector<int>> parts) {
  std::vector<int> out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

}  // namespace

TEST(CoreThreadChooser, OneThreadAvailableMeansNothingToChoose) {
  ThreadChooser c(1, 4, 10);
  const auto used = drive(c, 50, [](int, int) { return 1e-3; });
  EXPECT_EQ(used, repeat(1, 50));
  EXPECT_EQ(c.cycles_one(), 50);
  EXPECT_EQ(c.cycles_max(), 0);
  EXPECT_TRUE(c.last_choice().empty());
  ThreadChooser zero(0);  // a count below 1 is taken as 1
  EXPECT_EQ(zero.max_threads(), 1);
  EXPECT_EQ(zero.next_threads(), 1);
}

// Two threads at 1 ms per cycle against one at 3 ms: the schedule is 5 cycles on 2 (probe,
// window 4 + the uncounted first), 5 on 1 (probe), 10 on 2 (stretch), then probe again.
TEST(CoreThreadChooser, KeepsTheFasterCountForAStretchThenProbesAgain) {
  ThreadChooser c(2, 4, 10);
  const auto used = drive(c, 30, [](int n, int) { return n == 1 ? 3e-3 : 1e-3; });
  EXPECT_EQ(used, concat({repeat(2, 5), repeat(1, 5), repeat(2, 10), repeat(2, 5), repeat(1, 5)}));
  EXPECT_EQ(c.cycles_one(), 10);
  EXPECT_EQ(c.cycles_max(), 20);
  EXPECT_EQ(c.last_choice(), "1 thread 3.000 ms/cycle, 2 threads 1.000 ms/cycle -> 2");
}

// One thread faster (a loaded machine): the stretch runs on one thread.
TEST(CoreThreadChooser, ChoosesOneThreadWhenItIsFaster) {
  ThreadChooser c(4, 3, 6);
  const auto used = drive(c, 14, [](int n, int) { return n == 1 ? 2e-3 : 7e-3; });
  EXPECT_EQ(used, concat({repeat(4, 4), repeat(1, 4), repeat(1, 6)}));
  EXPECT_EQ(c.last_choice(), "1 thread 2.000 ms/cycle, 4 threads 7.000 ms/cycle -> 1");
}

// Equal times: one thread (it leaves the other cores to other processes).
TEST(CoreThreadChooser, TieGoesToOneThread) {
  ThreadChooser c(2, 4, 10);
  const auto used = drive(c, 20, [](int, int) { return 2e-3; });
  EXPECT_EQ(used, concat({repeat(2, 5), repeat(1, 5), repeat(1, 10)}));
}

// The first cycle of a probe (threads waking up) is left out of the average: a 1 s first
// cycle on 2 threads would make the 2-thread mean 0.2 s and lose against 3 ms.
TEST(CoreThreadChooser, FirstCycleOfAProbeIsNotCounted) {
  ThreadChooser c(2, 4, 10);
  const auto used = drive(c, 20, [](int n, int k) {
    if (k == 0 || k == 5) return 1.0;  // first cycle of each probe
    return n == 1 ? 3e-3 : 1e-3;
  });
  EXPECT_EQ(used[10], 2);
  EXPECT_EQ(c.last_choice(), "1 thread 3.000 ms/cycle, 2 threads 1.000 ms/cycle -> 2");
}

// The load changes between probes: two threads win the first probe, lose the second.
TEST(CoreThreadChooser, FollowsAChangeOfLoad) {
  ThreadChooser c(2, 4, 10);
  const auto used = drive(c, 40, [](int n, int k) {
    const bool loaded = k >= 20;
    if (n == 1) return 3e-3;
    return loaded ? 9e-3 : 1e-3;
  });
  EXPECT_EQ(used, concat({repeat(2, 5), repeat(1, 5), repeat(2, 10), repeat(2, 5), repeat(1, 5), repeat(1, 10)}));
  EXPECT_EQ(c.last_choice(), "1 thread 3.000 ms/cycle, 2 threads 9.000 ms/cycle -> 1");
  EXPECT_EQ(c.cycles_one(), 20);
  EXPECT_EQ(c.cycles_max(), 20);
}
