// SPDX-License-Identifier: GPL-3.0-or-later
// The explicit central-difference cycle (order in docs/cycle.md). Each phase is one
// function with its formula; no strings, maps or allocations except on rare events.
#include "hbm/solver/cycle.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

namespace hbm::solver {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Deterministic parallel sum over nodes: fixed chunks, partials summed in chunk order.
template <class F>
double node_sum(std::size_t n, std::vector<double>& scratch, F&& per_node) {
  const std::size_t nch = n_chunks(n);
  scratch.assign(nch, 0.0);
#pragma omp parallel for schedule(static) if (nch > 8)
  for (std::size_t ch = 0; ch < nch; ++ch) {
    double s = 0.0;
    const std::size_t end = std::min(n, (ch + 1) * kChunk);
    for (std::size_t i = ch * kChunk; i < end; ++i) s += per_node(i);
    scratch[ch] = s;
  }
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
void compute_element_forces(Model& m, CycleState& c) {
  const auto t0 = Clock::now();
  c.group_results.assign(m.groups.size(), GroupStepResult{});
  for (std::size_t g = 0; g < m.groups.size(); ++g)
    m.groups[g]->compute_forces(c.step, m.nodes, c.group_results[g]);
  for (std::size_t g = 0; g < m.groups.size(); ++g) {
    ElementGroup& grp = *m.groups[g];
    for (Index e : grp.newly_eroded) {
      const Part& p = m.parts[static_cast<std::size_t>(grp.part)];
      c.events.push_back("element " + std::to_string(grp.element_id[static_cast<std::size_t>(e)]) +
                         " of part " + std::to_string(p.id) + " '" + p.title + "' deleted at t = " +
                         std::to_string(c.step.time));
    }
    grp.newly_eroded.clear();
  }
  c.times.element_forces += seconds_since(t0);
}

// f_i = sum over the slots of node i in (group, element) order; same for M_i, k_n, k_r.
void assemble_nodal_forces(Model& m, CycleState& c) {
  const auto t0 = Clock::now();
  NodalState& n = m.nodes;
  const std::size_t nn = n.n_nodes;
  const auto* start = m.incidence_start.data();
  const auto* grp = m.incidence_group.data();
  const auto* slot = m.incidence_slot.data();
  const auto& groups = m.groups;
#pragma omp parallel for schedule(static) if (nn > 2048)
  for (std::size_t i = 0; i < nn; ++i) {
    double fx = 0.0, fy = 0.0, fz = 0.0, k = 0.0, mx = 0.0, my = 0.0, mz = 0.0, kr = 0.0;
    for (std::int64_t j = start[i]; j < start[i + 1]; ++j) {
      const ElementGroup& g = *groups[static_cast<std::size_t>(grp[j])];
      const auto s = static_cast<std::size_t>(slot[j]);
      fx += g.slot_force.x[s];
      fy += g.slot_force.y[s];
      fz += g.slot_force.z[s];
      k += g.slot_stiffness[s];
      if (g.has_rotation_slots()) {
        mx += g.slot_moment.x[s];
        my += g.slot_moment.y[s];
        mz += g.slot_moment.z[s];
        kr += g.slot_rot_stiffness[s];
      }
    }
    n.force.x[i] = fx;
    n.force.y[i] = fy;
    n.force.z[i] = fz;
    n.stiffness[i] = k;
    n.moment.x[i] = mx;
    n.moment.y[i] = my;
    n.moment.z[i] = mz;
    n.rot_stiffness[i] = kr;
    n.force_ext.x[i] = n.force_ext.y[i] = n.force_ext.z[i] = 0.0;
    n.contact_force.x[i] = n.contact_force.y[i] = n.contact_force.z[i] = 0.0;
  }
  c.times.assembly += seconds_since(t0);
}

// Contacts, walls, gravity and loads add into f, M, k_n in registration order.
void add_interaction_forces(Model& m, CycleState& c) {
  const auto t0 = Clock::now();
  for (auto& i : m.interactions) i->add_forces(c.step, m.nodes);
  c.times.interactions += seconds_since(t0);
}

// Stage 1 of the constraints: rigid bodies move f, M, k_n of secondaries to the main node.
void gather_constraint_forces(Model& m, CycleState& c) {
  const auto t0 = Clock::now();
  for (auto& k : m.constraints) k->gather_forces(c.step, m.nodes);
  c.times.constraints += seconds_since(t0);
}

// dt^{n+1/2}. /DT/NODA/CST: dt = Tmin and, where Tsca sqrt(2 m / k_n) < Tmin,
// m = k_n / 2 (Tmin / Tsca)^2 (never decreasing); same for rotations with k_r and I.
// Otherwise dt = Tsca * min(element critical steps, interaction critical steps).
// dt^n = (dt^{n-1/2} + dt^{n+1/2}) / 2.
void choose_time_step(Model& m, CycleState& c) {
  const auto t0 = Clock::now();
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
  c.times.time_step += seconds_since(t0);
}

// a^n = f^n / m;  v^{n+1/2} = v^{n-1/2} + dt^n a^n;  omega likewise with M / I.
void update_velocities(Model& m, CycleState& c) {
  const auto t0 = Clock::now();
  NodalState& n = m.nodes;
  const double dt = c.dt_mid;
  const std::size_t nn = n.n_nodes;
#pragma omp parallel for schedule(static) if (nn > 2048)
  for (std::size_t i = 0; i < nn; ++i) {
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
  for (std::size_t i = 0; i < nn; ++i) {
    if (!n.has_rotation[i] || n.is_secondary[i] || !(n.inertia[i] > 0.0)) continue;
    const double inv = 1.0 / n.inertia[i];
    n.omega.x[i] += dt * n.moment.x[i] * inv;
    n.omega.y[i] += dt * n.moment.y[i] * inv;
    n.omega.z[i] += dt * n.moment.z[i] * inv;
  }
  c.times.nodal_update += seconds_since(t0);
}

// Stage 2 (rigid rotation, /BCS, /IMPVEL, walls) then stage 3 (rigid secondaries).
void impose_constraints(Model& m, CycleState& c) {
  const auto t0 = Clock::now();
  StepContext s = c.step;
  for (auto& k : m.constraints) k->impose_velocities(s, m.nodes);
  for (auto& k : m.constraints) k->impose_dependent(s, m.nodes);
  c.times.constraints += seconds_since(t0);
}

// Energies through t^n: internal and hourglass from the groups, contact and external
// work from the interactions and constraints. Kinetic energies come from
// update_velocities (before constraints; the constrained nodes are corrected here).
void account_energies(Model& m, CycleState& c) {
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
  // main node and not counted.
  {
    const NodalState& nd = m.nodes;
    const double dt = c.dt_mid;
    const double corr = node_sum(nd.n_nodes, c.chunk_scratch, [&](std::size_t i) {
      if (nd.is_secondary[i]) return 0.0;
      const double ax = nd.a.x[i], ay = nd.a.y[i], az = nd.a.z[i];
      return 0.5 * dt * nd.mass[i] *
             (ax * (nd.v.x[i] - dt * ax) + ay * (nd.v.y[i] - dt * ay) + az * (nd.v.z[i] - dt * az));
    });
    const auto [ke, ker] = half_step_kinetic(nd, c.chunk_scratch);
    // At t^0 the initial kinetic energy itself (forces of a velocity jump at t^0 have
    // done no work yet).
    E.kinetic = c.step.cycle == 0 ? c.kinetic_half_prev : c.kinetic_half_prev + corr;
    E.rotational = 0.5 * (c.rotational_half_prev + ker);
    c.kinetic_half_prev = ke;
    c.rotational_half_prev = ker;
  }
  const NodalState& n = m.nodes;
  double added = 0.0;
  for (std::size_t i = 0; i < n.n_nodes; ++i)
    if (!n.is_secondary[i]) added += n.added_mass[i];
  E.added_mass = added;
}

// x^{n+1} = x^n + dt^{n+1/2} v^{n+1/2};  t^{n+1} = t^n + dt^{n+1/2}.
void update_positions(Model& m, CycleState& c) {
  const auto t0 = Clock::now();
  NodalState& n = m.nodes;
  const double dt = c.step.dt_next;
  const std::size_t nn = n.n_nodes;
#pragma omp parallel for schedule(static) if (nn > 2048)
  for (std::size_t i = 0; i < nn; ++i) {
    n.x.x[i] += dt * n.v.x[i];
    n.x.y[i] += dt * n.v.y[i];
    n.x.z[i] += dt * n.v.z[i];
  }
  c.step.time += dt;
  c.step.dt_prev = dt;
  ++c.step.cycle;
  c.times.nodal_update += seconds_since(t0);
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
