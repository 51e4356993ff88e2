// SPDX-License-Identifier: GPL-3.0-or-later
// hbm-loadcase: writes the pendulum (hub) impact validation decks on the generated body
// model: decks/<case>/<case>_0000.rad + _0001.rad, which #include decks/hbm50/hbm50.inc.
// Exit codes: 0 written; 1 bad input (the file named, nothing written); 2 usage (a bad
// command line, no --case).
#include "hbm/deckgen/loadcases/load_case.hpp"
#include "hbm/deckgen/loadcases/posed_model.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>

int main(int argc, char** argv) {
  using namespace hbm::deckgen::loadcases;
  CLI::App app{"hbm-loadcase: pendulum impact validation decks on the body model"};
  std::string model = "decks/hbm50/hbm50.inc", geometry = "geometry", decks_dir = "decks", out;
  std::vector<std::string> cases;
  double speed = 0, tstop = 0;
  bool list = false, print_corridor = false, print_posed = false;
  app.add_option("--model", model, "body model deck (included by the load-case decks)");
  app.add_option("--geometry", geometry, "geometry sources (spine and pelvis landmarks)");
  app.add_option("--case", cases, "case name(s), or 'all' (see --list)");
  app.add_option("--decks", decks_dir, "folder receiving one folder per case");
  app.add_option("--out", out, "output folder for a single case (default DECKS/NAME)");
  app.add_option("--speed", speed, "impactor speed in m/s (overrides the case's; single case only)")->check(CLI::PositiveNumber);
  app.add_option("--tstop", tstop, "end time in ms (default 60)")->check(CLI::PositiveNumber);
  app.add_flag("--list", list, "list the cases and exit");
  app.add_flag("--print-corridor-case", print_corridor,
               "print the hbm-corridors case file of each --case (path from the repository root) and exit");
  app.add_flag("--print-posed-model", print_posed,
               "print, for each --case that runs on a posed variant of the model, its path (relative to the folder "
               "holding the model's folder) and the hbm-deckgen options that pose it, on one line; and exit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help exits 0; a bad command line is a usage error: exit 2, like a missing --case
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (list) {
    for (const auto& c : catalogue())
      std::cout << c.name << "  " << c.title << "  [" << c.reference << "; " << c.corridor_case << "]\n";
    return 0;
  }
  if (cases.size() == 1 && cases[0] == "all") {
    cases.clear();
    for (const auto& c : catalogue()) cases.push_back(c.name);
  }
  if (cases.empty()) {
    std::cerr << "hbm-loadcase: give --case NAME (or all); --list shows the cases\n";
    return 2;
  }
  if ((!out.empty() || speed > 0) && cases.size() != 1) {
    std::cerr << "hbm-loadcase: --out and --speed need exactly one --case\n";
    return 2;
  }
  std::vector<LoadCaseSpec> specs;
  for (const auto& n : cases) {
    const LoadCaseSpec* s = find_case(n);
    if (!s) {
      std::cerr << "hbm-loadcase: unknown case '" << n << "'; known cases:";
      for (const auto& c : catalogue()) std::cerr << " " << c.name;
      std::cerr << "\n";
      return 2;
    }
    specs.push_back(*s);
    if (speed > 0) specs.back().speed_m_s = speed;
    if (tstop > 0) specs.back().tstop_ms = tstop;
  }
  if (print_corridor) {
    for (const auto& s : specs) std::cout << s.corridor_case << "\n";
    return 0;
  }
  if (print_posed) {
    for (const auto& s : specs)
      if (!s.posed_model.empty()) std::cout << s.posed_model << " " << s.posed_model_options << "\n";
    return 0;
  }
  try {
    const ModelView m = read_model(model);
    std::map<std::string, ModelView> posed;  // posed variants read once (posed_model.hpp)
    for (const auto& s : specs) {
      const std::filesystem::path dir = out.empty() ? std::filesystem::path(decks_dir) / s.name : std::filesystem::path(out);
      const ModelView* use = &m;
      std::filesystem::path use_path = model;
      if (!s.posed_model.empty()) {
        use_path = posed_model_path(model, s.posed_model);
        if (!std::filesystem::exists(use_path))
          throw std::runtime_error(s.name + ": no posed model " + use_path.string() + "; write it from the repository root: " +
                                   s.posed_model_command());
        auto it = posed.find(use_path.string());
        if (it == posed.end()) {
          it = posed.emplace(use_path.string(), read_model(use_path)).first;
          check_posed_model(m, it->second, s.posed_part_prefixes, s.posed_model_command());
        }
        use = &it->second;
        // relative to the current folder like --model, so the deck's #include is relative too
        if (!std::filesystem::path(model).is_absolute())
          use_path = std::filesystem::relative(use_path, std::filesystem::current_path());
      }
      const GeneratedCase g = generate_load_case(s, *use, use_path, geometry, dir);
      print_generated(std::cout, s, g);
    }
  } catch (const std::exception& e) {
    std::cerr << "hbm-loadcase: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
