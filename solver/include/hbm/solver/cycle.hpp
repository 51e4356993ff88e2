// SPDX-License-Identifier: GPL-3.0-or-later
// The explicit central-difference cycle, one named function per phase (implemented in
// solver/src/core/cycle.cpp; the order is written once in docs/cycle.md).
#pragma once

#include "hbm/solver/model.hpp"
#include "hbm/solver/thread_partition.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace hbm::solver {

// Global energies through t^n [energy] and mass bookkeeping [mass].
struct GlobalEnergies {
  double kinetic = 0, rotational = 0, internal = 0, hourglass = 0, contact = 0;
  double external_work = 0;
  double initial_total = 0;  // E_0 = E_kin(0) + E_int(0)
  double added_mass = 0, mass0 = 0;
  // (E_kin + E_rot + E_int + E_hg + E_contact) / (E_0 + W_ext) - 1; 0 when the
  // denominator is 0.
  double energy_error() const;
  double mass_ratio() const { return mass0 > 0 ? added_mass / mass0 : 0.0; }
};

// Wall-clock seconds spent per phase, for the timing table and the bench.
struct PhaseTimes {
  double element_forces = 0, interactions = 0, assembly = 0, constraints = 0,
         time_step = 0, nodal_update = 0, energies = 0, output = 0;
};

// The slot buffers of one group for the assembly (moment pointers null without
// rotational DOFs).
struct SlotPointers {
  const double *fx, *fy, *fz, *k, *mx, *my, *mz, *kr;
};

// Node-ordered gather plan of the assembly, derived from Model::incidence_* on the
// first cycle: entry (group, slot) packed in 8 bytes, and a second CSR that lists only
// the slots of groups with rotational DOFs (moments, k_r), so that the many nodes of
// translational elements read no moment slots.
struct AssemblyPlan {
  struct Entry {
    std::uint32_t group, slot;
  };
  std::vector<std::uint32_t> start;      // n_nodes + 1, all slots of node i
  std::vector<Entry> entries;
  std::vector<std::uint32_t> rot_start;  // n_nodes + 1, rotational slots of node i
  std::vector<Entry> rot_entries;
  std::size_t n_groups = 0;
  std::size_t n_incidence = 0;  // incidence entries it was built from (slots of groups
                                // whose elements are all deactivated are left out)
  bool built_for(const Model& m) const;
  void build(const Model& m);
};

// Why a cycle asks the loop to stop (None = keep going).
enum class StopReason : std::uint8_t { None, EndTime, InvertedElement, AddedMass, EnergyError, TimeStepTooSmall };

struct CycleState {
  StepContext step;
  double dt_mid = 0.0;  // dt^n = (dt^{n-1/2} + dt^{n+1/2}) / 2, the velocity-update step
  GlobalEnergies energies;
  PhaseTimes times;
  // CPU time of the calling (main) thread per phase: the robust figure on a loaded
  // machine with 1 thread (with more threads it misses the other threads' share).
  PhaseTimes cpu_times;
  StopReason stop = StopReason::None;
  std::string stop_message;  // element / part / time or parts that took the mass
  std::vector<GroupStepResult> group_results;  // one per group, this cycle
  // Wall seconds of each group's compute_forces, summed over the cycles (the listing's
  // per-formulation timing rows) [s].
  std::vector<double> group_seconds;
  // The same in CPU time of the thread that ran the group, sampled on one cycle in 16
  // and scaled (an estimate; the clock is a system call) [s].
  std::vector<double> group_cpu_seconds;
  AssemblyPlan assembly;
  std::vector<SlotPointers> slot_pointers;  // per group, refreshed every cycle
  std::vector<std::size_t> small_groups;    // groups that run whole, one per thread
  std::vector<std::uint8_t> run_whole;      // per group: 1 if it is one of them
  std::vector<std::size_t> staged_groups;   // large groups run chunk by chunk (force stages)
  // Wall and sampled CPU seconds per thread and group of the staged groups' chunks
  // (thread t, group g at t * n_groups + g), added to group_seconds after the region.
  std::vector<double> thread_group_seconds, thread_group_cpu_seconds;
  // Node ranges and element chunks per thread (built when more than one thread runs).
  ThreadPartition partition;
  // Where /DT/NODA/CST put mass: per group, per element (allocated on first use) [mass].
  std::vector<std::vector<double>> element_added_mass;
  std::vector<std::string> events;  // element deletions etc., printed by the run loop
  Index dt_group = kNoIndex;        // group and element limiting the step (element mode)
  Index dt_element = kNoIndex;
  // Half-step kinetic energies of the previous cycle (-1: not yet known) [energy].
  double kinetic_half_prev = -1.0, rotational_half_prev = 0.0;
  // Scratch for deterministic nodal reductions (one slot per node chunk).
  std::vector<double> chunk_scratch;
};

// Kinetic energies 0.5 m |v|^2 and 0.5 I |omega|^2 of the current (half-step)
// velocities, rigid-body secondaries excluded; deterministic sum.
std::pair<double, double> half_step_kinetic(const NodalState& n, std::vector<double>& scratch);

// Phases (formulas in cycle.cpp):
void compute_element_forces(Model& m, CycleState& c);   // groups -> slot buffers
void assemble_nodal_forces(Model& m, CycleState& c);    // slots -> f, M, k_n (CSR order)
void add_interaction_forces(Model& m, CycleState& c);   // contacts, walls, gravity
void gather_constraint_forces(Model& m, CycleState& c); // rigid bodies: secondaries -> main
void choose_time_step(Model& m, CycleState& c);         // dt^{n+1/2}; nodal mass scaling
void update_velocities(Model& m, CycleState& c);        // a = f/m; v += dt a; omega too
void impose_constraints(Model& m, CycleState& c);       // BCS, IMPVEL, walls, then secondaries
void account_energies(Model& m, CycleState& c);         // energies through t^n
void update_positions(Model& m, CycleState& c);         // x^{n+1} = x^n + dt v^{n+1/2}

// One full cycle in the order above (outputs are called by the run loop between
// account_energies and update_positions, so every written value is at t^n).
void run_cycle(Model& m, CycleState& c);

}  // namespace hbm::solver
