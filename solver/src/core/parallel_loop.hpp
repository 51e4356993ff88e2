// SPDX-License-Identifier: GPL-3.0-or-later
// Loop over i = 0 .. n-1 that is an OpenMP parallel loop (static schedule) only when it
// can run on more than one thread, else a plain loop on the calling thread.
// Why: libgomp enters every `#pragma omp parallel` (also one whose `if` clause is false,
// and one run with a single allowed thread) through a team start and end, and the end
// wakes a futex: one system call per region. The hub model met 41 regions per cycle on
// one thread, 1.6 million system calls in a 60 ms run (3 s of system time). The body
// must not depend on the thread that runs an index (all callers keep per-index results
// and reduce them in index order), so both forms give the same bits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace hbm::solver {

// More than one thread can run a new parallel region here: more than one allowed and
// not inside an active region (nested regions run on the calling thread, see
// compute_element_forces).
inline bool parallel_region_useful() {
#ifdef _OPENMP
  return omp_get_max_threads() > 1 && !omp_in_parallel();
#else
  return false;
#endif
}

// `owner` (empty, or one entry per index): the thread that runs index i, taken modulo
// the team's size (a team smaller than asked for still runs every index); empty: a
// static schedule.
template <class Body>
void parallel_loop(std::size_t n, bool worth_threads, Body&& body, std::span<const std::uint8_t> owner = {}) {
  if (worth_threads && n > 1 && parallel_region_useful()) {
    if (owner.size() == n) {
#ifdef _OPENMP
#pragma omp parallel
      {
        const auto team = static_cast<unsigned>(omp_get_num_threads());
        const auto self = static_cast<unsigned>(omp_get_thread_num());
        for (std::size_t i = 0; i < n; ++i)
          if (owner[i] % team == self) body(i);
      }
#else
      for (std::size_t i = 0; i < n; ++i) body(i);
#endif
    } else {
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) body(i);
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) body(i);
  }
}

// body(begin, end) over the node ranges [bounds[k], bounds[k+1]) of a ThreadPartition,
// range k on thread k modulo the team's size; one call over [bounds.front(),
// bounds.back()) when no parallel region is useful.
template <class Body>
void parallel_ranges(std::span<const std::size_t> bounds, Body&& body) {
  if (bounds.size() < 2) return;
  const std::size_t n_ranges = bounds.size() - 1;
  if (n_ranges > 1 && parallel_region_useful()) {
#ifdef _OPENMP
#pragma omp parallel
    {
      const auto team = static_cast<std::size_t>(omp_get_num_threads());
      for (auto k = static_cast<std::size_t>(omp_get_thread_num()); k < n_ranges; k += team)
        body(bounds[k], bounds[k + 1]);
    }
    return;
#endif
  }
  body(bounds.front(), bounds.back());
}

}  // namespace hbm::solver
