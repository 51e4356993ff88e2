// SPDX-License-Identifier: GPL-3.0-or-later
// hbm-deckgen: generates the 50th percentile male driver model deck from geometry/.
#include "hbm/deckgen/body_mesher.hpp"
#include "hbm/deckgen/geometry_sources.hpp"
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
    auto m = hbm::deckgen::build_body_model(g, o);
    std::cout << "nodes " << m.nodes.size() << " bricks " << m.bricks.size() << " shells " << m.shells.size() << " trias "
              << m.trias.size() << " springs " << m.springs.size() << " total " << m.element_count() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "hbm-deckgen: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
