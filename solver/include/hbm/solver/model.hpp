// SPDX-License-Identifier: GPL-3.0-or-later
// The frozen model handed from the build phase to the time loop: nodal state, parts,
// element groups, interactions, constraints, functions and run control. After build the
// loop touches no strings or maps; ids and titles are kept only for messages and outputs.
#pragma once

#include "hbm/deck/deck.hpp"
#include "hbm/solver/constraint.hpp"
#include "hbm/solver/element_group.hpp"
#include "hbm/solver/function_curve.hpp"
#include "hbm/solver/interaction.hpp"
#include "hbm/solver/nodal_state.hpp"
#include "hbm/solver/run_control.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace hbm::solver {

struct Part {
  std::int64_t id = 0;
  std::string title;
  std::int64_t prop_id = 0, mat_id = 0;
  const hbm::deck::Card* part_card = nullptr;  // valid during build only
  const hbm::deck::Card* prop_card = nullptr;  // nullptr if prop_id = 0
  const hbm::deck::Card* mat_card = nullptr;
  std::string mat_keyword;  // e.g. "/MAT/LAW34" (listing), empty without material
  double mass0 = 0.0;        // physical mass of its elements [mass]
  double added_mass = 0.0;   // mass scaling attributed to this part (see engine-design.md)
};

// One /TH/... group: the CSV file it writes and its columns (global columns first).
struct ThGroup {
  std::string keyword;       // "/TH/NODE"
  std::int64_t id = 0;
  std::string title;
  std::vector<ThProbe> columns;
};

struct Model {
  std::string run_name;
  hbm::deck::Units units;
  NodalState nodes;
  std::vector<Part> parts;
  std::vector<std::unique_ptr<ElementGroup>> groups;       // registration order
  std::vector<std::unique_ptr<Interaction>> interactions;  // registration order
  std::vector<std::unique_ptr<Constraint>> constraints;    // registration order
  std::vector<std::unique_ptr<FunctionCurve>> functions;   // stable addresses
  std::vector<ThGroup> th_groups;
  RunControl control;
  // Step dt^{n+1/2} of the current cycle: outputs at t^n report velocities
  // v^n = v^{n+1/2} - dt^{n+1/2} a^n / 2 (set by the run loop) [time].
  double dt_output = 0.0;

  // Node -> slot incidence for deterministic assembly (CSR over nodes). Entry j of node
  // i's range refers to slot `slot[j]` of group `slot_group[j]`, in (group, element)
  // order. Built by the core after all builders ran.
  std::vector<std::int64_t> incidence_start;  // n_nodes + 1
  std::vector<std::int32_t> incidence_group;
  std::vector<std::int64_t> incidence_slot;

  double total_mass0() const;  // sum of mass0 over non-secondary nodes [mass]
};

// Build Model::incidence_* from the groups' connectivities (after all groups exist).
void build_incidence(Model& model);

}  // namespace hbm::solver
