// SPDX-License-Identifier: GPL-3.0-or-later
// Former name of example_deck_runner.hpp (run an example deck, read its /TH CSV files),
// kept while rigid_rwall_verification.cpp and springs_deck_errors_test.cpp include it;
// new tests include example_deck_runner.hpp.
#pragma once

#include "example_deck_runner.hpp"
