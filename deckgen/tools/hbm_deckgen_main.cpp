// SPDX-License-Identifier: GPL-3.0-or-later
// hbm-deckgen: generates the 50th percentile male driver model deck from geometry/.
#include "hbm/deckgen/body_mesher.hpp"
#include "hbm/deckgen/geometry_sources.hpp"
#include "hbm/deckgen/model_checks.hpp"
#include "hbm/deckgen/table.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"hbm-deckgen: 50th percentile male driver model deck from geometry sources"};
  std::string geometry = "geometry";
  app.add_option("-g,--geometry", geometry, "geometry sources directory");
  CLI11_PARSE(app, argc, argv);
  try {
    auto g = hbm::deckgen::load_geometry(geometry);
    hbm::deckgen::MesherOptions o;
    hbm::deckgen::ModelLandmarks lm;
    auto m = hbm::deckgen::build_body_model(g, o, &lm);
    hbm::deckgen::assign_rigid_body_masses(m, g);
    using namespace hbm::deckgen;
    print_budget(std::cout, element_budget(m), 10000, 12000);
    print_time_step(std::cout, time_step_check(m), 0.005);
    print_quality(std::cout, quality_check(m));
    print_mass(std::cout, mass_check(m, g, lm), 0.10, 15);
  } catch (const std::exception& e) {
    std::cerr << "hbm-deckgen: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
