// SPDX-License-Identifier: GPL-3.0-or-later
// /MAT/LAW2 (Johnson-Cook) card -> PlasticityLaw, read the same way for solids and shells,
// as OpenRadioss reads it (hm_read_mat02_jc.F90, m2law.F): a, b, n, EPS_p_max, SIG_max0;
// the rate term c ln(eps_dot / EPS_DOT_0); ICC 0 or 1 scales SIG_max0 with the rate term, 2
// does not; with F_cut > 0 the strain rate is filtered at F_cut (hardening.hpp). Yield and
// UTS input (Iflag != 0) and thermal softening (T_melt and rho0Cp both given) are refused.
#pragma once

#include "hbm/deck/deck.hpp"
#include "hbm/solver/build_context.hpp"
#include "hbm/solver/material/hardening.hpp"

namespace hbm::solver {

// Fills pl (kind JohnsonCook) from the card; false with an error recorded when unusable.
bool read_law2_hardening(BuildContext& ctx, const hbm::deck::Card& m, PlasticityLaw& pl);

}  // namespace hbm::solver
