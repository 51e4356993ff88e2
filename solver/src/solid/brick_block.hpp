// SPDX-License-Identifier: GPL-3.0-or-later
// A structured block of 8-node bricks built in code (no deck): used by the bench and by
// unit tests of the cycle. Nodes i + (nx+1) (j + (ny+1) k), lumped masses added.
#pragma once

#include "hbm/solver/model.hpp"
#include "solid/solid_group.hpp"

namespace hbm::solver {

struct BrickBlock {
  int nx = 10, ny = 10, nz = 10;
  double lx = 10, ly = 10, lz = 10;  // [length]
  SolidMaterial material;
  HourglassForm hourglass = HourglassForm::Viscous;
};

// Fills model.nodes, one part (id 1) and one SolidGroup; builds the incidence and sets
// mass = mass0. Returns the group.
SolidGroup& make_brick_block(Model& model, const BrickBlock& b);

}  // namespace hbm::solver
