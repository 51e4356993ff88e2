// SPDX-License-Identifier: GPL-3.0-or-later
// Unit text of a physical dimension in the deck's work units (/BEGIN), for CSV headers
// and the listing. kg-mm-ms gives the usual names: kN, GPa, J, kN/mm.
#pragma once

#include "hbm/deck/deck.hpp"
#include "hbm/deck/schema.hpp"

#include <string>

namespace hbm::solver {

std::string unit_text(hbm::deck::Dimension d, const hbm::deck::Units& u);

}  // namespace hbm::solver
