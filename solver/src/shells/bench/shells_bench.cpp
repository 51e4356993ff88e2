// SPDX-License-Identifier: GPL-3.0-or-later
// hbm-shells-bench: ns per shell element-cycle of the engine's shell groups
// (ShellElementGroup::compute_forces, i.e. kernel + nodal stiffness slots), one thread
// unless OMP_NUM_THREADS says otherwise; thread CPU time (meaningful with one thread). Cases: 3-node CST+DKT and 4-node Belytschko-Tsay,
// 3 Gauss points through the thickness, LAW1 elastic and LAW2 elastoplastic with every
// point yielding every cycle (steady stretching plus bending: the worst case).
// Usage: hbm-shells-bench [n_elements (default 100000)] [cycles (default 200)] [case]
// case (optional): quad or tria, then elastic or plastic, e.g. "quad-elastic": that case only.
#include "shells/shell_element_group.hpp"

#include <omp.h>

#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace hbm::solver;
using namespace hbm::solver::shells;

namespace {

double run_case(bool tria, bool plastic, std::size_t n_target, int cycles) {
  // Square plate of nx x nx cells, 1 mm cells, t = 1 mm, steel.
  const std::size_t cells = tria ? n_target / 2 : n_target;
  const std::size_t nx = static_cast<std::size_t>(std::sqrt(static_cast<double>(cells)));
  NodalState nodes;
  nodes.resize((nx + 1) * (nx + 1));
  // Membrane strain rate 0.01/ms (10/s, rib loading in a frontal impact) with the body
  // model's step 1.5e-3 ms: 1.5e-5 strain per cycle; the yield stress is low enough that
  // every point is plastic after the warm-up cycles.
  const double rate = 1e-2;  // 1/ms
  const double dt = 1.5e-3;  // ms
  for (std::size_t i = 0; i <= nx; ++i)
    for (std::size_t j = 0; j <= nx; ++j) {
      const std::size_t n = i * (nx + 1) + j;
      const double x = static_cast<double>(i), y = static_cast<double>(j);
      nodes.x.x[n] = x;
      nodes.x.y[n] = y;
      nodes.v.x[n] = rate * x;
      nodes.v.y[n] = -0.3 * rate * y;
      nodes.v.z[n] = 1e-3 * rate * (x * x - y * y);  // plus a bending field
      nodes.omega.x[n] = 2e-3 * rate * y;
      nodes.omega.y[n] = 2e-3 * rate * x;
    }
  ShellElementGroup g;
  g.keyword = tria ? "/SH3N" : "/SHELL";
  g.part = 0;
  g.nodes_per_element = tria ? 3 : 4;
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < nx; ++j) {
      const Index a = static_cast<Index>(i * (nx + 1) + j), b = a + static_cast<Index>(nx + 1),
                  c = b + 1, d = a + 1;
      if (tria) {
        for (Index k : {a, b, c}) g.connectivity.push_back(k);
        for (Index k : {a, c, d}) g.connectivity.push_back(k);
      } else {
        for (Index k : {a, b, c, d}) g.connectivity.push_back(k);
      }
    }
  g.n_elements = g.connectivity.size() / g.nodes_per_element;
  for (std::size_t e = 0; e < g.n_elements; ++e) {
    g.element_id.push_back(static_cast<std::int64_t>(e + 1));
    g.data.thick.push_back(1.0);
  }
  g.data.mat.law = plastic ? ShellLaw::JohnsonCook : ShellLaw::Elastic;
  g.data.mat.rho = 7.85e-6;
  g.data.mat.E = 210;
  g.data.mat.nu = 0.3;
  g.data.mat.plasticity.jc.a = 0.001;  // yields within the warm-up cycles
  g.data.mat.plasticity.jc.b = 0.5;
  g.data.mat.plasticity.jc.n = 0.5;
  g.data.sec.set_points(3);
  g.initialize(nodes);
  StepContext step;
  step.dt_prev = dt;
  GroupStepResult res;
  for (int c = 0; c < 5; ++c) g.compute_forces(step, nodes, res);  // warm up, yield
  // CPU time of the calling thread (the machine is shared: wall time would count the
  // time this process waits for a core).
  auto cpu_ns = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return 1e9 * static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec);
  };
  const double t0 = cpu_ns();
  for (int c = 0; c < cycles; ++c) {
    GroupStepResult r;
    g.compute_forces(step, nodes, r);
  }
  const double ns = cpu_ns() - t0;
  std::size_t plastic_points = 0;
  for (double e : g.data.epsp) plastic_points += e > 0;
  if (plastic && plastic_points != g.data.epsp.size())
    std::fprintf(stderr, "warning: %zu of %zu points plastic\n", plastic_points, g.data.epsp.size());
  return ns / (static_cast<double>(cycles) * static_cast<double>(g.n_elements));
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 100000;
  const int cycles = argc > 2 ? std::atoi(argv[2]) : 200;
  std::printf("hbm-shells-bench: %zu elements, %d cycles, %d thread(s), 3 points through the thickness\n",
              n, cycles, omp_get_max_threads());
  std::printf("%-44s %14s\n", "case", "ns/elem-cycle");
  const std::string only = argc > 3 ? argv[3] : "";
  for (const bool tria : {true, false})
    for (const bool plastic : {false, true}) {
      const std::string name = std::string(tria ? "tria" : "quad") + (plastic ? "-plastic" : "-elastic");
      if (!only.empty() && name.find(only) == std::string::npos) continue;
      const double ns = run_case(tria, plastic, n, cycles);
      std::printf("%-44s %14.1f\n",
                  (std::string(tria ? "SH3N CST+DKT" : "SHELL Belytschko-Tsay") +
                   (plastic ? ", LAW2 elastoplastic (yielding)" : ", LAW1 elastic")).c_str(),
                  ns);
    }
  return 0;
}
