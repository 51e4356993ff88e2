// SPDX-License-Identifier: GPL-3.0-or-later
// Bench of the spring and rigid-body kernels: ns per spring-cycle for /PROP/TYPE4 (linear
// and nonlinear H=1), TYPE8 and TYPE13 groups of N springs (compute_forces: kinematics,
// law, slot forces, nodal stiffness, energy sum), and ns per rigid-body-cycle (the three
// constraint stages) for many small bodies (8 secondaries) and per secondary node-cycle
// for one large body. Prints figures; asserts nothing (speed targets live in benches,
// never in timed tests). Run: hbm-springs-bench [N] (default 100000), OMP_NUM_THREADS=1
// (the figures are process CPU time per cycle: per-core cost, independent of the load).
#include "rigid/rigid_body.hpp"
#include "springs/spring_group_factory.hpp"

#include <cmath>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

using namespace hbm::solver;

// Process CPU time [s]: on a loaded machine wall time overstates the kernels' cost; with
// one thread (OMP_NUM_THREADS=1) CPU time is the time the kernels actually ran.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

namespace {

// N springs along a wavy line: spring e joins nodes e and e+1; nodes slightly displaced
// and moving so that every law does real work.
NodalState chain(std::size_t n) {
  NodalState s;
  s.resize(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    s.x0.x[i] = 10.0 * static_cast<double>(i);
    s.x0.y[i] = 3.0 * std::sin(0.1 * static_cast<double>(i));
    s.x0.z[i] = 2.0 * std::cos(0.07 * static_cast<double>(i));
    s.x.x[i] = s.x0.x[i] + 0.01 * std::sin(0.3 * static_cast<double>(i));
    s.x.y[i] = s.x0.y[i] + 0.01 * std::cos(0.2 * static_cast<double>(i));
    s.x.z[i] = s.x0.z[i];
    s.v.x[i] = 0.1 * std::sin(0.5 * static_cast<double>(i));
    s.omega.x[i] = 0.01;
    s.omega.y[i] = 0.02 * std::sin(0.1 * static_cast<double>(i));
    s.mass0[i] = s.mass[i] = 0.01;
    s.inertia0[i] = s.inertia[i] = 0.1;
    s.has_rotation[i] = 1;
  }
  return s;
}

double bench_springs(springs::SpringProperty prop, std::size_t n, int cycles) {
  NodalState nodes = chain(n);
  std::vector<Index> conn;
  std::vector<std::int64_t> ids;
  for (std::size_t e = 0; e < n; ++e) {
    conn.push_back(static_cast<Index>(e));
    conn.push_back(static_cast<Index>(e + 1));
    ids.push_back(static_cast<std::int64_t>(e + 1));
  }
  auto g = springs::make_spring_group(prop, 0, conn, ids, nodes);
  GroupStepResult r;
  StepContext sc{1, 0.0, 1.5e-3, 1.5e-3};
  g->compute_forces(sc, nodes, r);  // warm-up
  const double t0 = cpu_seconds();
  for (int c = 0; c < cycles; ++c) {
    sc.cycle = c + 2;
    for (std::size_t i = 0; i <= n; i += 7) nodes.x.x[i] += 1e-5;  // keep the laws moving
    g->compute_forces(sc, nodes, r);
  }
  const double s = cpu_seconds() - t0;
  return 1e9 * s / (static_cast<double>(cycles) * static_cast<double>(n));
}

springs::SpringProperty property(springs::SpringType type) {
  springs::SpringProperty p;
  p.type = type;
  p.dofs.resize(type == springs::SpringType::Axial ? 1 : 6);
  for (auto& d : p.dofs) { d.K = 10.0; d.C = 0.01; }
  p.inertia = 0.1;
  return p;
}

// `bodies` rigid bodies of `per_body` secondaries each; returns ns per body-cycle.
double bench_rigid(std::size_t bodies, std::size_t per_body, int cycles) {
  const std::size_t nb = per_body + 1;
  NodalState nodes;
  nodes.resize(bodies * nb);
  std::vector<std::unique_ptr<rigid::RigidBody>> rb;
  for (std::size_t b = 0; b < bodies; ++b) {
    auto body = std::make_unique<rigid::RigidBody>();
    for (std::size_t k = 0; k < per_body; ++k) {
      const std::size_t i = b * nb + k;
      nodes.x0.x[i] = nodes.x.x[i] = 100.0 * static_cast<double>(b) + 10.0 * static_cast<double>(k % 3);
      nodes.x0.y[i] = nodes.x.y[i] = 10.0 * static_cast<double>((k / 3) % 3) + 0.1 * static_cast<double>(k);
      nodes.x0.z[i] = nodes.x.z[i] = 10.0 * static_cast<double>(k / 9) + 0.05 * static_cast<double>(k % 5);
      nodes.mass0[i] = nodes.mass[i] = 0.01;
      nodes.v.x[i] = 0.1 * static_cast<double>(k % 2);
      nodes.v.y[i] = -0.1 * static_cast<double>(k % 3);
      body->secondary.push_back(static_cast<Index>(i));
    }
    body->main = static_cast<Index>(b * nb + per_body);
    body->assemble(nodes, 0.0, Eigen::Matrix3d::Zero(), true, false);
    rb.push_back(std::move(body));
  }
  nodes.mass = nodes.mass0;
  StepContext sc{0, 0.0, 0.0, 1.5e-3};
  auto cycle = [&] {
    for (auto& b : rb) b->gather_forces(sc, nodes);
    for (auto& b : rb) b->impose_velocities(sc, nodes);
    for (auto& b : rb) b->impose_dependent(sc, nodes);
    sc.dt_prev = sc.dt_next;
    ++sc.cycle;
  };
  cycle();
  const double t0 = cpu_seconds();
  for (int c = 0; c < cycles; ++c) {
    for (std::size_t i = 0; i < nodes.n_nodes; i += 5) nodes.force.x[i] = 1e-3;  // some load
    cycle();
  }
  const double s = cpu_seconds() - t0;
  return 1e9 * s / (static_cast<double>(cycles) * static_cast<double>(bodies));
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? static_cast<std::size_t>(std::atol(argv[1])) : 100000;
  const int cycles = 50;
  std::printf("springs and rigid bodies bench (%zu springs, %d cycles; process CPU time, so run with\n"
              "OMP_NUM_THREADS=1 for per-core figures)\n", n, cycles);
  std::printf("  TYPE4 linear            %8.1f ns per spring-cycle\n",
              bench_springs(property(springs::SpringType::Axial), n, cycles));
  {
    static const std::vector<double> x{-10.0, -0.2, 0.2, 10.0}, y{-5.9, -1.0, 1.0, 5.9};
    auto p = property(springs::SpringType::Axial);
    p.dofs[0].f1 = {x.data(), y.data(), x.size()};
    p.dofs[0].H = springs::Hardening::Isotropic;
    std::printf("  TYPE4 nonlinear H=1     %8.1f ns per spring-cycle\n", bench_springs(p, n, cycles));
  }
  std::printf("  TYPE8 general 6-DOF     %8.1f ns per spring-cycle\n",
              bench_springs(property(springs::SpringType::General), n, cycles));
  std::printf("  TYPE13 beam-type        %8.1f ns per spring-cycle\n",
              bench_springs(property(springs::SpringType::Beam), n, cycles));
  const std::size_t bodies = std::max<std::size_t>(1, n / 10);
  std::printf("  RBODY, 8 secondaries    %8.1f ns per rigid-body-cycle (%zu bodies)\n",
              bench_rigid(bodies, 8, cycles), bodies);
  const double big = bench_rigid(1, n, cycles);
  std::printf("  RBODY, %zu secondaries %8.1f ns per rigid-body-cycle = %.2f ns per secondary node-cycle\n",
              n, big, big / static_cast<double>(n));
  return 0;
}
