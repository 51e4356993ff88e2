// SPDX-License-Identifier: GPL-3.0-or-later
// FeModel -> Radioss block-format cards through the deck library (hbm_deck): the model
// include file (nodes, parts, properties, materials, elements, rigid bodies, contacts;
// no /BEGIN or /END) and the standalone drop-test deck pair that #includes it.
// Ids: node = index + 1; elements numbered 1.. over bricks, shells, SH3N, springs; part and
// material ids from the model; properties 1 (solids), 1000 + part id (shells), 2000 + n
// (springs); node groups 10000 + rigid body id and 30000 + interface id; surfaces 20000 +
// interface id. Output is deterministic: the same model writes the same bytes.
#pragma once

#include "hbm/deckgen/fe_model.hpp"

#include "hbm/deck/deck.hpp"

#include <filesystem>
#include <string>

namespace hbm::deckgen {

hbm::deck::Deck model_cards(const FeModel& m, const std::string& title);

struct DropTest {
  double speed = 5.0;          // m/s = mm/ms, downwards (-z)
  double end_time = 20.0;      // ms
  double floor_clearance = 1.0;  // mm below the lowest node
  double tsca = 0.9, tmin = 1.5e-3;  // /DT/NODA/CST, /DT/SHELL/CST
  // /DT/BRICK/CST/1: Tmin a little below the fixed step, so that only bricks whose step
  // deformation has lowered switch (the undeformed abdominal organ bricks' own estimate,
  // 1.65 us, is within Tsca of 1.5 us; docs/engine-design.md 12.8), and VDEF_min.
  double brick_tmin = 1.4e-3, brick_vdef_min = 0.3;
  double dm_max = 0.01;        // /STOP added-mass ratio
};

// Writes `dir/NAME.inc` (model). Temporary file + rename: complete or absent.
void write_model_include(const std::filesystem::path& file, const FeModel& m, const std::string& title);
// Writes `dir/NAME_drop_0000.rad` (#include of the model file name) and `_0001.rad`.
void write_drop_decks(const std::filesystem::path& dir, const std::string& name, const std::string& include_name,
                      const FeModel& m, const DropTest& t);
// Writes text to `file` through a temporary name renamed when complete.
void write_file_atomically(const std::filesystem::path& file, const std::string& text);

}  // namespace hbm::deckgen
