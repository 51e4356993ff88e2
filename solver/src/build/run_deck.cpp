// SPDX-License-Identifier: GPL-3.0-or-later
// Program flow for a deck pair: read NAME_0000.rad and NAME_0001.rad (same folder),
// report every deck error (exit 1, nothing written), build the frozen model, run it.
#include "hbm/deck/io.hpp"
#include "hbm/solver/build_context.hpp"
#include "hbm/solver/run.hpp"

#include <ostream>

namespace hbm::solver {

namespace {

// NAME_0000.rad -> NAME_0001.rad
std::filesystem::path engine_deck_of(const std::filesystem::path& starter) {
  std::string name = starter.filename().string();
  const auto pos = name.rfind("_0000.rad");
  if (pos == std::string::npos || pos + 9 != name.size()) return {};
  name.replace(pos, 9, "_0001.rad");
  return starter.parent_path() / name;
}

}  // namespace

RunResult run_deck(const std::filesystem::path& starter, const RunOptions& options, std::ostream& err) {
  Model model;
  return run_deck(starter, options, err, model);
}

RunResult run_deck(const std::filesystem::path& starter, const RunOptions& options, std::ostream& err,
                   Model& model) {
  RunResult res;
  res.exit_code = 1;
  const std::filesystem::path engine = engine_deck_of(starter);
  if (engine.empty()) {
    res.message = starter.string() + ": the starter deck must be named NAME_0000.rad";
    err << "error: " << res.message << "\n";
    return res;
  }
  if (!std::filesystem::exists(starter)) {
    res.message = starter.string() + ": no such file";
    err << "error: " << res.message << "\n";
    return res;
  }
  if (!std::filesystem::exists(engine)) {
    res.message = engine.string() + ": engine deck not found (expected beside the starter deck)";
    err << "error: " << res.message << "\n";
    return res;
  }
  hbm::deck::ReadResult s = hbm::deck::read_deck(starter, hbm::deck::Section::Starter);
  hbm::deck::ReadResult e = hbm::deck::read_deck(engine, hbm::deck::Section::Engine);
  hbm::deck::print_diagnostics(err, s);
  hbm::deck::print_diagnostics(err, e);
  if (!s.ok() || !e.ok()) {
    res.message = "deck errors";
    return res;
  }
  std::vector<std::string> messages;
  const bool ok = build_model(s.deck, e.deck, model, messages);
  for (const auto& m : messages) err << m << "\n";
  if (!ok) {
    res.message = "model errors";
    return res;
  }
  if (model.run_name.empty()) model.run_name = starter.stem().string().substr(0, starter.stem().string().size() - 5);
  return run_model(model, options);
}

}  // namespace hbm::solver
