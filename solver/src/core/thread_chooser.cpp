// SPDX-License-Identifier: GPL-3.0-or-later
// ThreadChooser: probe windows with the maximum and with one thread, keep the faster
// (see thread_chooser.hpp).
#include "core/thread_chooser.hpp"

#include <cstdio>

namespace hbm::solver {

ThreadChooser::ThreadChooser(int max_threads, int window, int stretch)
    : max_(max_threads < 1 ? 1 : max_threads), window_(window < 1 ? 1 : window), stretch_(stretch < 1 ? 1 : stretch) {
  if (max_ == 1) phase_ = Phase::Run;
  chosen_ = current_ = 1;
}

int ThreadChooser::next_threads() {
  switch (phase_) {
    case Phase::ProbeMax: current_ = max_; break;
    case Phase::ProbeOne: current_ = 1; break;
    case Phase::Run: current_ = chosen_; break;
  }
  return current_;
}

void ThreadChooser::cycle_done(double seconds) {
  ++cycles_[current_ == 1 ? 0 : 1];
  if (max_ == 1) return;
  ++count_;
  // The first cycle of a probe pays for waking the threads up: not counted.
  if (phase_ != Phase::Run && count_ > 1) sum_ += seconds;
  if (phase_ == Phase::ProbeMax && count_ == window_ + 1) {
    per_max_ = sum_ / window_;
    phase_ = Phase::ProbeOne;
    count_ = 0;
    sum_ = 0.0;
  } else if (phase_ == Phase::ProbeOne && count_ == window_ + 1) {
    const double per_one = sum_ / window_;
    chosen_ = per_one <= per_max_ ? 1 : max_;
    char b[160];
    std::snprintf(b, sizeof b, "1 thread %.3f ms/cycle, %d threads %.3f ms/cycle -> %d", 1e3 * per_one, max_,
                  1e3 * per_max_, chosen_);
    last_ = b;
    phase_ = Phase::Run;
    count_ = 0;
    sum_ = 0.0;
  } else if (phase_ == Phase::Run && count_ >= stretch_) {
    phase_ = Phase::ProbeMax;
    count_ = 0;
    sum_ = 0.0;
  }
}

}  // namespace hbm::solver
