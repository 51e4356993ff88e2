// SPDX-License-Identifier: GPL-3.0-or-later
// The explicit central-difference cycle (order in docs/cycle.md). Each phase is one
// function with its formula; no strings, maps or allocations except on rare events.
#include "hbm/solver/cycle.hpp"

#include "core/parallel_loop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <ctime>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace hbm::solver {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// CPU time of the calling thread [s]: with other processes on the cores it stays the
// cost of the work, where the wall time also counts the time the thread waited.
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Per-group and per-phase CPU time is sampled on one cycle in this many (see
// compute_element_forces): the thread CPU clock is a system call (0.5-1 us in a VM).
constexpr std::int64_t kCpuSampleCycles = 16;

// Wall and calling-thread CPU time of one phase, added to PhaseTimes on stop(): the wall
// clock (vDSO, no system call) every cycle, the thread CPU clock on one cycle in
// kCpuSampleCycles, scaled (two system calls per phase and cycle were 18 per cycle).
// Phases are sampled half a period after the groups, so that the element forces phase
// does not carry the groups' clock reads.
class PhaseTimer {
 public:
  explicit PhaseTimer(const CycleState& c)
      : wall0_(Clock::now()), sample_(c.step.cycle % kCpuSampleCycles == kCpuSampleCycles / 2),
        cpu0_(sample_ ? thread_cpu_seconds() : 0.0) {}
  void stop(double& wall, double& cpu) const {
    wall += seconds_since(wall0_);
    if (sample_) cpu += static_cast<double>(kCpuSampleCycles) * (thread_cpu_seconds() - cpu0_);
  }

 private:
  Clock::time_point wall0_;
  bool sample_;
  double cpu0_;
};

// Nodal sums (node_sum) cost about a ns per node; a parallel region costs microseconds
// when both cores are free and milliseconds when another process holds one of the 2
// cores (docs/engine-design.md section 14). They run on one thread below this size;
// results do not depend on it (fixed chunks). The nodal updates and the assembly run
// over the thread partition's node ranges whenever several threads run (for_node_ranges).
constexpr std::size_t kParallelNodes = std::size_t{1} << 18;

// Element groups without force stages and with fewer chunks than this run whole on one
// thread (their owner in the ThreadPartition), side by side in the cycle's element region;
// inside compute_forces the groups use the same bound for their own chunk loops.
constexpr std::size_t kSmallGroupChunks = 8;


int max_threads() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

// body(i0, i1) over the node ranges of the thread partition when several threads run,
// else once over all nodes (every node is updated alone: the same bits either way).
template <class F>
void for_node_ranges(const Model& m, const CycleState& c, F&& body) {
  if (c.partition.active_for(max_threads()))
    parallel_ranges(c.partition.node_begin, body);
  else
    body(std::size_t{0}, m.nodes.n_nodes);
}

// Deterministic parallel sum over nodes: fixed chunks, partials summed in chunk order.
template <class F>
double node_sum(std::size_t n, std::vector<double>& scratch, F&& per_node) {
  const std::size_t nch = n_chunks(n);
  scratch.assign(nch, 0.0);
  parallel_loop(nch, n >= kParallelNodes, [&](std::size_t ch) {
    double s = 0.0;
    const std::size_t end = std::min(n, (ch + 1) * kChunk);
    for (std::size_t i = ch * kChunk; i < end; ++i) s += per_node(i);
    scratch[ch] = s;
  });
  double total = 0.0;
  for (double s : scratch) total += s;
  return total;
}

}  // namespace

std::pair<double, double> half_step_kinetic(const NodalState& n, std::vector<double>& scratch) {
  const double ke = node_sum(n.n_nodes, scratch, [&](std::size_t i) {
    if (n.is_secondary[i]) return 0.0;
    return 0.5 * n.mass[i] * (n.v.x[i] * n.v.x[i] + n.v.y[i] * n.v.y[i] + n.v.z[i] * n.v.z[i]);
  });
  double ker = 0.0;
  for (std::size_t i = 0; i < n.n_nodes; ++i)
    if (n.has_rotation[i] && !n.is_secondary[i])
      ker += 0.5 * n.inertia[i] *
             (n.omega.x[i] * n.omega.x[i] + n.omega.y[i] * n.omega.y[i] + n.omega.z[i] * n.omega.z[i]);
  return {ke, ker};
}

double GlobalEnergies::energy_error() const {
  const double den = initial_total + external_work;
  const double num = kinetic + rotational + internal + hourglass + contact;
  if (std::abs(den) < 1e-300) return 0.0;
  return num / den - 1.0;
}

// Each group: slot forces f_e = -f_int + hourglass + viscous at t^n from x^n, v^{n-1/2}.
// Large groups run one after the other, each parallel over its own chunks; small groups
// (one thread each inside) are shared out between the threads in one parallel region.
// A group's results never depend on which thread ran it.
void compute_element_forces(Model& m, CycleState& c) {
  const PhaseTimer t0(c);
  const std::size_t ng = m.groups.size();
  c.group_results.assign(ng, GroupStepResult{});
  if (c.group_seconds.size() != ng) c.group_seconds.assign(ng, 0.0);
  if (c.group_cpu_seconds.size() != ng) c.group_cpu_seconds.assign(ng, 0.0);
  // The thread CPU clock is a system call (about 0.5 us): per group it is read on one
  // cycle in kCpuSampleCycles only and scaled (the wall clock is read every cycle).
  const bool sample_cpu = c.step.cycle % kCpuSampleCycles == 0;
  auto run_group = [&](std::size_t g) {
    const auto w0 = Clock::now();
    const double cpu0 = sample_cpu ? thread_cpu_seconds() : 0.0;
    m.groups[g]->compute_forces(c.step, m.nodes, c.group_results[g]);
    c.group_seconds[g] += seconds_since(w0);
    if (sample_cpu) c.group_cpu_seconds[g] += kCpuSampleCycles * (thread_cpu_seconds() - cpu0);
  };
  const int threads = max_threads();
  if (threads > 1 && !c.partition.built_for(threads)) {
    c.run_whole.assign(ng, 0);
    for (std::size_t g = 0; g < ng; ++g)
      c.run_whole[g] = !m.groups[g]->has_force_stages() && n_chunks(m.groups[g]->n_elements) < kSmallGroupChunks;
    c.partition.build(m, threads, c.run_whole);
  } else if (threads > 1 && c.partition.active_for(threads) && !c.partition.measured &&
             c.step.cycle >= ThreadPartition::kMeasureCycles) {
    c.partition.build(m, threads, c.run_whole, c.group_seconds);
  }
  if (!c.partition.active_for(threads)) {
    for (std::size_t g = 0; g < ng; ++g)
      if (!m.groups[g]->all_deactivated()) run_group(g);  // else: zero slots, nothing to do
  } else {
    // Groups with force stages (solids, shells) run chunk by chunk on the owning threads
    // and small groups without them whole on their owner, all in one parallel region;
    // large groups without stages run before it, each parallel over its own chunks.
    std::vector<std::size_t>& small = c.small_groups;
    std::vector<std::size_t>& staged = c.staged_groups;
    small.clear();
    staged.clear();
    for (std::size_t g = 0; g < ng; ++g) {
      ElementGroup& grp = *m.groups[g];
      if (grp.all_deactivated()) continue;
      if (c.run_whole[g]) {
        small.push_back(g);
      } else if (grp.has_force_stages()) {
        grp.begin_forces(c.step, m.nodes);
        staged.push_back(g);
      } else {
        run_group(g);
      }
    }
    c.thread_group_seconds.assign(static_cast<std::size_t>(threads) * ng, 0.0);
    c.thread_group_cpu_seconds.assign(static_cast<std::size_t>(threads) * ng, 0.0);
#ifdef _OPENMP
    // Nested regions inside a group run on the calling thread.
    omp_set_max_active_levels(1);
#pragma omp parallel if (small.size() + staged.size() > 1)
#endif
    {
#ifdef _OPENMP
      const auto team = static_cast<unsigned>(omp_get_num_threads());
      const auto self = static_cast<unsigned>(omp_get_thread_num());
#else
      const unsigned team = 1, self = 0;
#endif
      for (const std::size_t g : small)
        if (c.partition.group_thread[g] % team == self) run_group(g);
      double* wall = c.thread_group_seconds.data() + self * ng;
      double* cpu = c.thread_group_cpu_seconds.data() + self * ng;
      for (const std::size_t g : staged) {
        ElementGroup& grp = *m.groups[g];
        const auto w0 = Clock::now();
        const double cpu0 = sample_cpu ? thread_cpu_seconds() : 0.0;
        const std::size_t nch = grp.n_force_chunks();
        for (std::size_t ch = 0; ch < nch; ++ch)
          if (grp.chunk_thread[ch] % team == self) grp.force_chunk(ch, c.step, m.nodes);
        wall[g] += seconds_since(w0);
        if (sample_cpu) cpu[g] += kCpuSampleCycles * (thread_cpu_seconds() - cpu0);
      }
    }
    for (const std::size_t g : staged) {
      m.groups[g]->end_forces(c.group_results[g]);
      for (std::size_t t = 0; t < static_cast<std::size_t>(threads); ++t) {
        c.group_seconds[g] += c.thread_group_seconds[t * ng + g];
        c.group_cpu_seconds[g] += c.thread_group_cpu_seconds[t * ng + g];
      }
    }
  }
  for (std::size_t g = 0; g < ng; ++g) {
    ElementGroup& grp = *m.groups[g];
    for (Index e : grp.newly_eroded) {
      const Part& p = m.parts[static_cast<std::size_t>(grp.part)];
      c.events.push_back("element " + std::to_string(grp.element_id[static_cast<std::size_t>(e)]) +
                         " of part " + std::to_string(p.id) + " '" + p.title + "' deleted at t = " +
                         std::to_string(c.step.time));
    }
    grp.newly_eroded.clear();
  }
  t0.stop(c.times.element_forces, c.cpu_times.element_forces);
}

bool AssemblyPlan::built_for(const Model& m) const {
  return n_groups == m.groups.size() && start.size() == m.incidence_start.size() &&
         n_incidence == m.incidence_slot.size();
}

void AssemblyPlan::build(const Model& m) {
  const std::size_t nn = m.incidence_start.empty() ? 0 : m.incidence_start.size() - 1;
  n_groups = m.groups.size();
  n_incidence = m.incidence_slot.size();
  start.assign(nn + 1, 0);
  rot_start.assign(nn + 1, 0);
  entries.clear();
  rot_entries.clear();
  entries.reserve(m.incidence_slot.size());
  for (std::size_t i = 0; i < nn; ++i) {
    for (std::int64_t j = m.incidence_start[i]; j < m.incidence_start[i + 1]; ++j) {
      const Entry e{static_cast<std::uint32_t>(m.incidence_group[static_cast<std::size_t>(j)]),
                    static_cast<std::uint32_t>(m.incidence_slot[static_cast<std::size_t>(j)])};
      if (m.groups[e.group]->all_deactivated()) continue;  // zero slots
      entries.push_back(e);
      if (m.groups[e.group]->has_rotation_slots()) rot_entries.push_back(e);
    }
    start[i + 1] = static_cast<std::uint32_t>(entries.size());
    rot_start[i + 1] = static_cast<std::uint32_t>(rot_entries.size());
  }
}

// f_i = sum over the slots of node i in (group, element) order; same for M_i, k_n, k_r.
// One thread: scatter, group after group, slot after slot: the slot buffers are read
// in memory order and the nodal arrays stay in cache; each node receives its slots in
// (group, element) order, the order of the gather, so the sums are the same bits.
// Several threads: node-ordered gather through the packed plan, each thread over the
// node range it owns (ThreadPartition; each node summed by one thread). Groups whose
// elements all lie inside rigid bodies (zero slots) are left out of both.
void assemble_nodal_forces(Model& m, CycleState& c) {
  const PhaseTimer t0(c);
  NodalState& n = m.nodes;
  const std::size_t nn = n.n_nodes;
  double* __restrict fxo = n.force.x.data();
  double* __restrict fyo = n.force.y.data();
  double* __restrict fzo = n.force.z.data();
  double* __restrict ko = n.stiffness.data();
  double* __restrict mxo = n.moment.x.data();
  double* __restrict myo = n.moment.y.data();
  double* __restrict mzo = n.moment.z.data();
  double* __restrict kro = n.rot_stiffness.data();
  const int threads = max_threads();
  if (!c.partition.active_for(threads)) {
    for (double* a : {fxo, fyo, fzo, ko, mxo, myo, mzo, kro}) std::fill(a, a + nn, 0.0);
    for (const auto& gp : m.groups) {
      const ElementGroup& g = *gp;
      if (g.all_deactivated()) continue;  // zero slots (inside rigid bodies)
      const Index* conn = g.connectivity.data();
      const std::size_t ns = g.connectivity.size();
      const double *gfx = g.slot_force.x.data(), *gfy = g.slot_force.y.data(), *gfz = g.slot_force.z.data(),
                   *gk = g.slot_stiffness.data();
      for (std::size_t s = 0; s < ns; ++s) {
        const auto i = static_cast<std::size_t>(conn[s]);
        fxo[i] += gfx[s];
        fyo[i] += gfy[s];
        fzo[i] += gfz[s];
        ko[i] += gk[s];
      }
      if (!g.has_rotation_slots()) continue;
      const double *gmx = g.slot_moment.x.data(), *gmy = g.slot_moment.y.data(), *gmz = g.slot_moment.z.data(),
                   *gkr = g.slot_rot_stiffness.data();
      for (std::size_t s = 0; s < ns; ++s) {
        const auto i = static_cast<std::size_t>(conn[s]);
        mxo[i] += gmx[s];
        myo[i] += gmy[s];
        mzo[i] += gmz[s];
        kro[i] += gkr[s];
      }
    }
  } else {
    AssemblyPlan& plan = c.assembly;
    if (!plan.built_for(m)) plan.build(m);
    // Slot buffers of every group (stable within a cycle).
    auto& ptr = c.slot_pointers;
    ptr.resize(m.groups.size());
    for (std::size_t g = 0; g < m.groups.size(); ++g) {
      const ElementGroup& grp = *m.groups[g];
      ptr[g] = {grp.slot_force.x.data(), grp.slot_force.y.data(), grp.slot_force.z.data(),
                grp.slot_stiffness.data(), grp.slot_moment.x.data(), grp.slot_moment.y.data(),
                grp.slot_moment.z.data(), grp.slot_rot_stiffness.data()};
    }
    const SlotPointers* P = ptr.data();
    const std::uint32_t* start = plan.start.data();
    const AssemblyPlan::Entry* ent = plan.entries.data();
    const std::uint32_t* rstart = plan.rot_start.data();
    const AssemblyPlan::Entry* rent = plan.rot_entries.data();
    parallel_ranges(c.partition.node_begin, [&](std::size_t i0, std::size_t i1) {
      for (std::size_t i = i0; i < i1; ++i) {
        double fx = 0.0, fy = 0.0, fz = 0.0, k = 0.0;
        for (std::uint32_t j = start[i]; j < start[i + 1]; ++j) {
          const SlotPointers& p = P[ent[j].group];
          const std::uint32_t s = ent[j].slot;
          fx += p.fx[s];
          fy += p.fy[s];
          fz += p.fz[s];
          k += p.k[s];
        }
        fxo[i] = fx;
        fyo[i] = fy;
        fzo[i] = fz;
        ko[i] = k;
        double mx = 0.0, my = 0.0, mz = 0.0, kr = 0.0;
        for (std::uint32_t j = rstart[i]; j < rstart[i + 1]; ++j) {
          const SlotPointers& p = P[rent[j].group];
          const std::uint32_t s = rent[j].slot;
          mx += p.mx[s];
          my += p.my[s];
          mz += p.mz[s];
          kr += p.kr[s];
        }
        mxo[i] = mx;
        myo[i] = my;
        mzo[i] = mz;
        kro[i] = kr;
      }
    });
  }
  for (Vec3Soa* v : {&n.force_ext, &n.contact_force}) {
    std::fill(v->x.begin(), v->x.end(), 0.0);
    std::fill(v->y.begin(), v->y.end(), 0.0);
    std::fill(v->z.begin(), v->z.end(), 0.0);
  }
  t0.stop(c.times.assembly, c.cpu_times.assembly);
}

// Contacts, walls, gravity and loads add into f, M, k_n in registration order.
void add_interaction_forces(Model& m, CycleState& c) {
  const PhaseTimer t0(c);
  for (auto& i : m.interactions) i->add_forces(c.step, m.nodes);
  t0.stop(c.times.interactions, c.cpu_times.interactions);
}

// Stage 1 of the constraints: rigid bodies move f, M, k_n of secondaries to the main node.
void gather_constraint_forces(Model& m, CycleState& c) {
  const PhaseTimer t0(c);
  for (auto& k : m.constraints) k->gather_forces(c.step, m.nodes);
  t0.stop(c.times.constraints, c.cpu_times.constraints);
}

// dt^{n+1/2}. /DT/NODA/CST: dt = Tmin and, where Tsca sqrt(2 m / k_n) < Tmin,
// m = k_n / 2 (Tmin / Tsca)^2 (never decreasing); same for rotations with k_r and I.
// Otherwise dt = Tsca * min(element critical steps, interaction critical steps).
// dt^n = (dt^{n-1/2} + dt^{n+1/2}) / 2.
void choose_time_step(Model& m, CycleState& c) {
  const PhaseTimer t0(c);
  const RunControl& rc = m.control;
  NodalState& n = m.nodes;
  if (rc.nodal_cst) {
    c.step.dt_next = rc.dt_min;
    const double coef = 0.5 * (rc.dt_min / rc.dt_scale) * (rc.dt_min / rc.dt_scale);
    for (std::size_t i = 0; i < n.n_nodes; ++i) {
      if (n.is_secondary[i]) continue;
      const double need = n.stiffness[i] * coef;
      if (need > n.mass[i]) {
        const double added = need - n.mass[i];
        n.mass[i] = need;
        n.added_mass[i] = need - n.mass0[i];
        // Attribute to the stiffest element at the node.
        double kmax = -1.0;
        std::int64_t best = -1;
        for (std::int64_t j = m.incidence_start[i]; j < m.incidence_start[i + 1]; ++j) {
          const ElementGroup& g = *m.groups[static_cast<std::size_t>(m.incidence_group[j])];
          const double k = g.slot_stiffness[static_cast<std::size_t>(m.incidence_slot[j])];
          if (k > kmax) {
            kmax = k;
            best = j;
          }
        }
        if (best >= 0) {
          const auto gi = static_cast<std::size_t>(m.incidence_group[best]);
          const ElementGroup& g = *m.groups[gi];
          if (c.element_added_mass.size() < m.groups.size()) c.element_added_mass.resize(m.groups.size());
          auto& log = c.element_added_mass[gi];
          if (log.empty()) log.assign(g.n_elements, 0.0);
          const auto e = static_cast<std::size_t>(m.incidence_slot[best]) / g.nodes_per_element;
          log[e] += added;
          m.parts[static_cast<std::size_t>(g.part)].added_mass += added;
        }
      }
      if (n.has_rotation[i] && n.rot_stiffness[i] > 0.0) {
        const double need_i = n.rot_stiffness[i] * coef;
        if (need_i > n.inertia[i]) n.inertia[i] = need_i;
      }
    }
  } else {
    double dt = std::numeric_limits<double>::infinity();
    c.dt_group = c.dt_element = kNoIndex;
    for (std::size_t g = 0; g < c.group_results.size(); ++g)
      if (c.group_results[g].dt_min < dt) {
        dt = c.group_results[g].dt_min;
        c.dt_group = static_cast<Index>(g);
        c.dt_element = c.group_results[g].dt_element;
      }
    for (auto& i : m.interactions) dt = std::min(dt, i->critical_step());
    c.step.dt_next = rc.dt_scale * dt;
    // No element limits the step (e.g. the only element inverted): keep the last one.
    if (!std::isfinite(c.step.dt_next) && c.step.dt_prev > 0.0) c.step.dt_next = c.step.dt_prev;
  }
  c.dt_mid = 0.5 * (c.step.dt_prev + c.step.dt_next);
  t0.stop(c.times.time_step, c.cpu_times.time_step);
}

// a^n = f^n / m;  v^{n+1/2} = v^{n-1/2} + dt^n a^n;  omega likewise with M / I.
void update_velocities(Model& m, CycleState& c) {
  const PhaseTimer t0(c);
  NodalState& n = m.nodes;
  const double dt = c.dt_mid;
  for_node_ranges(m, c, [&](std::size_t i0, std::size_t i1) {
    for (std::size_t i = i0; i < i1; ++i) {
      if (n.is_secondary[i] || !(n.mass[i] > 0.0)) continue;
      const double inv_m = 1.0 / n.mass[i];
      const double ax = n.force.x[i] * inv_m, ay = n.force.y[i] * inv_m, az = n.force.z[i] * inv_m;
      n.a.x[i] = ax;
      n.a.y[i] = ay;
      n.a.z[i] = az;
      n.v.x[i] += dt * ax;
      n.v.y[i] += dt * ay;
      n.v.z[i] += dt * az;
    }
    for (std::size_t i = i0; i < i1; ++i) {
      if (!n.has_rotation[i] || n.is_secondary[i] || !(n.inertia[i] > 0.0)) continue;
      const double inv = 1.0 / n.inertia[i];
      n.omega.x[i] += dt * n.moment.x[i] * inv;
      n.omega.y[i] += dt * n.moment.y[i] * inv;
      n.omega.z[i] += dt * n.moment.z[i] * inv;
    }
  });
  t0.stop(c.times.nodal_update, c.cpu_times.nodal_update);
}

// Stage 2 (rigid rotation, /BCS, /IMPVEL, walls) then stage 3 (rigid secondaries).
void impose_constraints(Model& m, CycleState& c) {
  const PhaseTimer t0(c);
  StepContext s = c.step;
  for (auto& k : m.constraints) k->impose_velocities(s, m.nodes);
  for (auto& k : m.constraints) k->impose_dependent(s, m.nodes);
  t0.stop(c.times.constraints, c.cpu_times.constraints);
}

// Energies through t^n: internal and hourglass from the groups, contact and external
// work from the interactions and constraints. Kinetic energies come from
// update_velocities (before constraints; the constrained nodes are corrected here).
void account_energies(Model& m, CycleState& c) {
  const PhaseTimer t0(c);
  GlobalEnergies& E = c.energies;
  E.internal = E.hourglass = E.contact = 0.0;
  double wext = 0.0;
  for (const auto& g : m.groups) {
    E.internal += g->energy.internal;
    E.hourglass += g->energy.hourglass;
  }
  for (const auto& i : m.interactions) {
    if (i->work_kind() == WorkKind::Contact)
      E.contact -= i->work();
    else
      wext += i->work();
  }
  for (const auto& k : m.constraints) wext += k->reaction_work();
  E.external_work = wext;
  // Kinetic energy at t^n consistent with the trapezoidal work of the forces
  // (0.5 (f^{n-1} + f^n) . v^{n-1/2} dt summed over the steps telescopes to it):
  //   E_kin(t^n) = 0.5 m |v^{n-1/2}|^2 + 0.5 dt^n m a^n . v^{n-1/2},
  // with a^n the acceleration after constraints and v^{n-1/2} = v^{n+1/2} - dt^n a^n.
  // Rotational: mean of the half-step values. Rigid-body secondaries are carried by their
  // main node and not counted. One pass over the nodes: the translational sums by fixed
  // chunks (as node_sum), the rotational and added-mass sums in node order.
  const NodalState& nd = m.nodes;
  const double dt = c.dt_mid;
  const std::size_t nn = nd.n_nodes;
  double corr = 0.0, ke = 0.0, ker = 0.0, added = 0.0;
  for (std::size_t ch = 0; ch < n_chunks(nn); ++ch) {
    double s_corr = 0.0, s_ke = 0.0;
    const std::size_t end = std::min(nn, (ch + 1) * kChunk);
    for (std::size_t i = ch * kChunk; i < end; ++i) {
      if (nd.is_secondary[i]) continue;
      const double ax = nd.a.x[i], ay = nd.a.y[i], az = nd.a.z[i];
      const double vx = nd.v.x[i], vy = nd.v.y[i], vz = nd.v.z[i];
      s_corr += 0.5 * dt * nd.mass[i] * (ax * (vx - dt * ax) + ay * (vy - dt * ay) + az * (vz - dt * az));
      s_ke += 0.5 * nd.mass[i] * (vx * vx + vy * vy + vz * vz);
      added += nd.added_mass[i];
      if (nd.has_rotation[i])
        ker += 0.5 * nd.inertia[i] *
               (nd.omega.x[i] * nd.omega.x[i] + nd.omega.y[i] * nd.omega.y[i] + nd.omega.z[i] * nd.omega.z[i]);
    }
    corr += s_corr;
    ke += s_ke;
  }
  // At t^0 the initial kinetic energy itself (forces of a velocity jump at t^0 have
  // done no work yet).
  E.kinetic = c.step.cycle == 0 ? c.kinetic_half_prev : c.kinetic_half_prev + corr;
  E.rotational = 0.5 * (c.rotational_half_prev + ker);
  c.kinetic_half_prev = ke;
  c.rotational_half_prev = ker;
  E.added_mass = added;
  t0.stop(c.times.energies, c.cpu_times.energies);
}

// x^{n+1} = x^n + dt^{n+1/2} v^{n+1/2};  t^{n+1} = t^n + dt^{n+1/2}.
void update_positions(Model& m, CycleState& c) {
  const PhaseTimer t0(c);
  NodalState& n = m.nodes;
  const double dt = c.step.dt_next;
  for_node_ranges(m, c, [&](std::size_t i0, std::size_t i1) {
    for (std::size_t i = i0; i < i1; ++i) {
      n.x.x[i] += dt * n.v.x[i];
      n.x.y[i] += dt * n.v.y[i];
      n.x.z[i] += dt * n.v.z[i];
    }
  });
  c.step.time += dt;
  c.step.dt_prev = dt;
  ++c.step.cycle;
  t0.stop(c.times.nodal_update, c.cpu_times.nodal_update);
}

void run_cycle(Model& m, CycleState& c) {
  compute_element_forces(m, c);
  assemble_nodal_forces(m, c);
  add_interaction_forces(m, c);
  gather_constraint_forces(m, c);
  choose_time_step(m, c);
  update_velocities(m, c);
  impose_constraints(m, c);
  account_energies(m, c);
  update_positions(m, c);
}

}  // namespace hbm::solver
