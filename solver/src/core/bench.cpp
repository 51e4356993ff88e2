// SPDX-License-Identifier: GPL-3.0-or-later
// hbm-solver --bench: ns per element-cycle (brick forces) and per node-cycle (assembly,
// time step, nodal update) on a cubic block of LAW1 bricks with a velocity field,
// for 1 and 2 threads (or the given count). Double precision.
#include "hbm/solver/cycle.hpp"
#include "solid/brick_block.hpp"

#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <ostream>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace hbm::solver {

namespace {

void bench_once(std::size_t n_elements, int threads, std::ostream& out) {
#ifdef _OPENMP
  omp_set_num_threads(threads);
#endif
  const int n = std::max(1, static_cast<int>(std::lround(std::cbrt(static_cast<double>(n_elements)))));
  Model m;
  BrickBlock b;
  b.nx = b.ny = b.nz = n;
  b.lx = b.ly = b.lz = 10.0 * n;  // 10 mm elements
  b.material.rho = 1e-6;          // kg/mm^3
  b.material.set_elastic(0.2, 0.3);  // GPa
  make_brick_block(m, b);
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i) {  // smooth velocity field [mm/ms]
    m.nodes.v.x[i] = 1e-3 * std::sin(0.01 * m.nodes.x.y[i]);
    m.nodes.v.z[i] = 1e-3 * std::cos(0.01 * m.nodes.x.x[i]);
  }
  m.control.dt_scale = 0.9;
  CycleState c;
  const int warm = 3, cycles = 40;
  for (int k = 0; k < warm; ++k) run_cycle(m, c);
  c.times = PhaseTimes{};
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < cycles; ++k) run_cycle(m, c);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // CPU time of this thread for the element kernel alone (one thread only): robust
  // against other processes sharing the cores.
  double cpu_forces = 0.0;
  if (threads == 1) {
    timespec ta{}, tb{};
    GroupStepResult res;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ta);
    for (int k = 0; k < cycles; ++k) m.groups[0]->compute_forces(c.step, m.nodes, res);
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &tb);
    cpu_forces = static_cast<double>(tb.tv_sec - ta.tv_sec) + 1e-9 * static_cast<double>(tb.tv_nsec - ta.tv_nsec);
  }
  const double ne = static_cast<double>(m.groups[0]->n_elements) * cycles;
  const double nn = static_cast<double>(m.nodes.n_nodes) * cycles;
  char b1[512];
  std::snprintf(b1, sizeof b1,
                "threads %d  bricks %zu  nodes %zu  cycles %d\n"
                "  brick forces   %8.1f ns/element-cycle\n"
                "  assembly       %8.1f ns/node-cycle\n"
                "  time step      %8.1f ns/node-cycle\n"
                "  nodal update   %8.1f ns/node-cycle  (accelerations, velocities, positions)\n"
                "  whole cycle    %8.1f ns/element-cycle\n"
                "  brick forces, thread CPU time: %.1f ns/element-cycle\n",
                threads, m.groups[0]->n_elements, m.nodes.n_nodes, cycles, 1e9 * c.times.element_forces / ne,
                1e9 * c.times.assembly / nn, 1e9 * c.times.time_step / nn, 1e9 * c.times.nodal_update / nn,
                1e9 * wall / ne, threads == 1 ? 1e9 * cpu_forces / ne : 0.0);
  out << b1 << std::flush;
}

}  // namespace

int run_bench(std::size_t n_elements, int threads, std::ostream& out) {
  out << "hbm-solver bench: LAW1 brick block, one-point FB, viscous hourglass, double precision\n";
  if (threads > 0) {
    bench_once(n_elements, threads, out);
  } else {
    bench_once(n_elements, 1, out);
    bench_once(n_elements, 2, out);
  }
  return 0;
}

}  // namespace hbm::solver
