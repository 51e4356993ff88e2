// SPDX-License-Identifier: GPL-3.0-or-later
// Model summary of a checked starter deck (hbm-solver --check): element counts per type
// and part, materials, total mass, and the smallest element time step per part.
#pragma once

#include "hbm/deck/deck.hpp"

#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace hbm::deck {

struct PartSummary {
  std::int64_t part_id = 0;
  std::string title;
  std::string property;                        // "/PROP/TYPE14/1"
  std::string material;                        // "/MAT/LAW1/1", empty if none
  std::map<std::string, std::size_t> elements;  // element keyword -> count
  double mass = 0;                             // rho * volume (solids), rho * area * thickness (shells), spring masses
  double dt_min = 0;                           // smallest element time step (0 if unknown)
  std::int64_t dt_element = 0;                 // element giving dt_min
  std::string dt_note;                         // how dt was estimated, or why it is unknown
};

struct ModelSummary {
  std::size_t nodes = 0;
  std::map<std::string, std::size_t> elements;  // element keyword -> count
  std::vector<PartSummary> parts;               // in /PART order
  double element_mass = 0;
  double rbody_mass = 0;                        // added masses of /RBODY
  double total_mass() const { return element_mass + rbody_mass; }
  double dt_min = 0;
  std::int64_t dt_part = 0;
};

// Computes the summary of a starter deck that passed the checks (references resolved).
ModelSummary summarize(const Deck& starter);
void print_model_summary(std::ostream& os, const Deck& starter);

}  // namespace hbm::deck
