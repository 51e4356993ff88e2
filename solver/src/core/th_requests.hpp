// SPDX-License-Identifier: GPL-3.0-or-later
// Build phase: turns the /TH/... cards into ThGroups of probes. /TH/NODE and /TH/PART
// are answered here; other kinds are asked of the groups, interactions and constraints.
//   /TH/NODE variables: DX DY DZ (displacement), VX VY VZ (velocity at t^n),
//     AX AY AZ, X Y Z (position); DEF = DX DY DZ VX VY VZ AX AY AZ.
//   /TH/PART variables: IE (internal), HE (hourglass), KE (kinetic, element-lumped
//     masses), AM (added mass), M (mass incl. added), ER (deleted elements);
//     DEF = IE KE HE AM.
#pragma once

#include "hbm/solver/build_context.hpp"

namespace hbm::solver {

void build_th_groups(BuildContext& ctx);

}  // namespace hbm::solver
