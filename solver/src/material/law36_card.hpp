// SPDX-License-Identifier: GPL-3.0-or-later
// /MAT/LAW36 card -> tabulated hardening, read the same way for solids and shells: yield
// curves, their scales and strain rates, EPS_p_max, and the strain-rate filter of
// OpenRadioss (hm_read_mat36.F): with two or more curves the equivalent strain rate is an
// exponential average with cutoff F_cut (0 -> 10 kHz in the work time unit), none with one
// curve (rate independent). Vp = 1 (plastic strain rate) is refused.
#pragma once

#include "hbm/deck/deck.hpp"
#include "hbm/solver/build_context.hpp"
#include "hbm/solver/material/hardening.hpp"

namespace hbm::solver {

// Fills pl (kind Tabulated) from the card; false with an error recorded when unusable.
bool read_law36_hardening(BuildContext& ctx, const hbm::deck::Card& m, PlasticityLaw& pl);

}  // namespace hbm::solver
