// SPDX-License-Identifier: GPL-3.0-or-later
// `hbm-solver --check NAME_0000.rad`: read and check the starter deck and, when present,
// the engine deck NAME_0001.rad beside it; print every diagnostic (to `err`) and, for a
// valid model, the model summary (to `out`). Writes no file.
#pragma once

#include <filesystem>
#include <iosfwd>

namespace hbm::deck {

// Exit code: 0 deck valid, 1 deck errors, 2 bad command-line use (no such file, name not
// ending in _0000.rad).
int run_check(const std::filesystem::path& starter, std::ostream& out, std::ostream& err);

}  // namespace hbm::deck
