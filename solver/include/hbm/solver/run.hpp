// SPDX-License-Identifier: GPL-3.0-or-later
// The run phase: time loop over a frozen model with listing, time histories and
// animation, stop criteria, timing table. And the whole program flow for a deck pair.
#pragma once

#include "hbm/solver/cycle.hpp"
#include "hbm/solver/model.hpp"

#include <filesystem>
#include <iosfwd>
#include <string>

namespace hbm::solver {

struct RunOptions {
  std::filesystem::path out_dir = ".";  // listing, CSV, VTK go here
  int threads = 0;                      // OpenMP threads; 0 = chosen during the run: 1 or
                                        //   the OpenMP maximum, whichever is faster
                                        //   (core/thread_chooser.hpp)
  std::ostream* console = nullptr;      // stdout copy of the listing (nullptr: none)
};

struct RunResult {
  int exit_code = 0;  // 0 normal termination, 1 deck/build error, 3 stopped early
  StopReason reason = StopReason::None;
  std::string message;
  GlobalEnergies energies;
  double time = 0.0;
  std::int64_t cycles = 0;
  PhaseTimes times;
};

RunResult run_model(Model& model, const RunOptions& options);

// Read NAME_0000.rad and the engine deck NAME_0001.rad beside it, build, run.
// Deck errors go to `err` (exit code 1).
RunResult run_deck(const std::filesystem::path& starter, const RunOptions& options, std::ostream& err);
// Same, building into `model` (kept for inspection by tests). `model` must be empty.
RunResult run_deck(const std::filesystem::path& starter, const RunOptions& options, std::ostream& err,
                   Model& model);

}  // namespace hbm::solver
