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

template <class Body>
void parallel_loop(std::size_t n, bool worth_threads, Body&& body) {
  if (worth_threads && n > 1 && parallel_region_useful()) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) body(i);
  } else {
    for (std::size_t i = 0; i < n; ++i) body(i);
  }
}

}  // namespace hbm::solver
