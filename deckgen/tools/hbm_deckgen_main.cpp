// SPDX-License-Identifier: GPL-3.0-or-later
// hbm-deckgen: generates the 50th percentile male driver model deck (NAME.inc) and its
// drop-test deck pair from the geometry sources, printing the budget, time-step, quality
// and mass-property checks. Bad input: file:line message, exit 1, nothing written. Failed
// checks: exit 2, nothing written (unless --force).
#include "hbm/deckgen/body_mesher.hpp"
#include "hbm/deckgen/deck_export.hpp"
#include "hbm/deckgen/geometry_sources.hpp"
#include "hbm/deckgen/model_checks.hpp"
#include "hbm/deckgen/organ_variants.hpp"
#include "hbm/deckgen/surface_io.hpp"
#include "hbm/deckgen/table.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>

namespace dg = hbm::deckgen;

int main(int argc, char** argv) {
  CLI::App app{"hbm-deckgen: 50th percentile male driver model deck from geometry sources"};
  std::string geometry = "geometry", out = "decks/hbm50", name = "hbm50", export_surface, import_envelope;
  std::vector<std::string> joints;
  bool check_only = false, force = false, no_drop = false;
  app.add_option("-g,--geometry", geometry, "geometry sources directory")->capture_default_str();
  app.add_option("-o,--out", out, "output directory for NAME.inc and NAME_drop_000[01].rad")->capture_default_str();
  app.add_option("-n,--name", name, "model name")->capture_default_str();
  app.add_option("--joint", joints, "NAME=ANGLE (deg): rotate a rigid limb about its joint (shoulder_r, elbow_l, hip_r, knee_l, ...)");
  app.add_option("--export-surface", export_surface, "write the outer surface (skin and rigid envelopes) as STL/OBJ/PLY (assimp)");
  app.add_option("--import-envelope", import_envelope,
                 "compare the generated outer surface with a reference surface (STL/OBJ/PLY, assimp): volume and extents");
  app.add_flag("--check-only", check_only, "build and check the model, write nothing");
  app.add_flag("--force", force, "write the decks even if a check fails");
  app.add_flag("--no-drop", no_drop, "do not write the drop-test deck pair");
  bool flesh_bricks = false;
  app.add_flag("--flesh-bricks", flesh_bricks,
               "torso flesh as two rings of one-point bricks (the layout before 2026-11-24; docs/engine-design.md section 12.10)");
  double rib_fracture_age = -1;
  app.add_option("--rib-fracture", rib_fracture_age,
                 "AGE (years): elastoplastic ribs deleted at the median failure strain of that age (rib fracture model; "
                 "default: elastic ribs)");
  bool pleura = false;
  app.add_flag("--pleura", pleura,
               "variant: the thoracic organ block slides on the chest wall (frictionless contact; default: shared nodes)");
  bool no_abdominal_wall = false;
  app.add_flag("--no-abdominal-wall", no_abdominal_wall,
               "variant: no abdominal wall membrane (materials.csv abdominal_wall): the trunk wall of flesh and skin alone, "
               "the default model before 2026-11-25");
  bool undifferentiated = false;
  app.add_flag("--undifferentiated-organs", undifferentiated,
               "variant: the seed's undifferentiated, air-filled thoracic organ block (materials.csv thoracic_organs) "
               "instead of the lungs and a water-like mediastinum (thoracic_organs.csv)");
  double mediastinum = 0;
  app.add_option("--mediastinum", mediastinum,
                 "HALF_WIDTH (mm): the water-like mediastinum's half width (default thoracic_organs.csv); with "
                 "--undifferentiated-organs a water-like band of that half width over the block's whole height");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help exits 0; a bad command line is bad input: exit 1 (docs/deckgen.md), as CLI11's
    // own codes (105-114) would not tell a script so
    return app.exit(e) == 0 ? 0 : 1;
  }
  const auto t0 = std::chrono::steady_clock::now();
  try {
    dg::GeometrySources g = dg::load_geometry(geometry);
    for (const std::string& j : joints) {
      auto eq = j.find('=');
      if (eq == std::string::npos) throw std::invalid_argument("--joint '" + j + "': expected NAME=ANGLE (degrees)");
      std::string jn = j.substr(0, eq);
      double deg = 0;
      try {
        std::size_t used = 0;
        deg = std::stod(j.substr(eq + 1), &used);
        if (used != j.size() - eq - 1) throw std::invalid_argument("trailing text");
      } catch (const std::exception&) {
        throw std::invalid_argument("--joint '" + j + "': ANGLE is not a number");
      }
      bool rigid_limb = false;
      for (const char* p : {"shoulder_", "elbow_", "hip_", "knee_"})
        if (jn.rfind(p, 0) == 0) rigid_limb = true;
      if (!rigid_limb)
        throw std::invalid_argument("--joint " + jn + ": only the rigid-limb joints shoulder_r/l, elbow_r/l, hip_r/l, knee_r/l can be set");
      g.skeleton.set_joint(jn, deg * M_PI / 180);
    }
    dg::MesherOptions o;
    o.flesh_tetra = !flesh_bricks;
    if (app.count("--mediastinum")) {
      if (!(mediastinum > 0) || !std::isfinite(mediastinum)) {
        std::ostringstream msg;
        msg << "--mediastinum: the half width must be a positive number of mm (got " << mediastinum << ")";
        throw std::invalid_argument(msg.str());
      }
      o.mediastinum_half_width = mediastinum;
    }
    o.lungs = !undifferentiated;
    o.abdominal_wall = !no_abdominal_wall;
    if (app.count("--rib-fracture")) {
      const auto& b = g.rib_bone;
      if (!(rib_fracture_age >= b.age_min && rib_fracture_age <= b.age_max)) {
        std::ostringstream msg;
        msg << "--rib-fracture " << rib_fracture_age << ": the failure strain fit of " << (g.dir / "rib_fracture.csv").string()
            << " covers ages " << b.age_min << " to " << b.age_max << " years";
        throw std::invalid_argument(msg.str());
      }
      o.rib_fracture_age = rib_fracture_age;
    }
    dg::ModelLandmarks lm;
    dg::FeModel m = dg::build_body_model(g, o, &lm);
    dg::assign_rigid_body_masses(m, g, lm);
    m.notes.push_back("hbm-deckgen: 50th percentile male driver model from geometry sources " + g.dir.filename().string() + "/ (units kg mm ms)");
    if (o.rib_fracture_age >= 0)
      m.notes.push_back("rib fracture model: elastoplastic ribs deleted at the median failure strain at " +
                        std::to_string(std::lround(o.rib_fracture_age)) + " years (--rib-fracture)");
    if (app.count("--mediastinum") && undifferentiated) dg::add_mediastinum(m, mediastinum);  // the block's whole height
    if (pleura) dg::add_pleura(m);
    std::cout << "hbm-deckgen: " << m.nodes.size() << " nodes, " << m.element_count() << " elements, " << m.parts.size() << " parts, "
              << m.rigid_bodies.size() << " rigid bodies, " << m.interfaces.size() << " contact interfaces\n\n";
    bool ok = dg::print_budget(std::cout, dg::element_budget(m), 10000, 12000);
    std::cout << "\n";
    ok = dg::print_time_step(std::cout, dg::time_step_check(m), 0.005) && ok;
    std::cout << "\n";
    ok = dg::print_quality(std::cout, dg::quality_check(m)) && ok;
    std::cout << "\n";
    ok = dg::print_mass(std::cout, dg::mass_check(m, g, lm), 0.10, 15.0) && ok;
    std::cout << "\n";
    ok = dg::print_surface_check(std::cout, m) && ok;
    if (!import_envelope.empty()) dg::compare_with_envelope(std::cout, m, import_envelope);
    if (!ok && !force) {
      std::cerr << "hbm-deckgen: a check failed (see above); nothing written (use --force to write anyway)\n";
      return 2;
    }
    if (!export_surface.empty()) dg::export_outer_surface(m, export_surface);
    if (!check_only) {
      std::filesystem::create_directories(out);
      dg::write_model_include(std::filesystem::path(out) / (name + ".inc"), m, name + ": 50th percentile male seated driver");
      if (!no_drop) dg::write_drop_decks(out, name + "_drop", name + ".inc", m, dg::DropTest{});
      std::cout << "wrote " << (std::filesystem::path(out) / (name + ".inc")).string()
                << (no_drop ? "" : " and " + (std::filesystem::path(out) / (name + "_drop_000[01].rad")).string()) << "\n";
    }
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "generation time " << std::round(secs * 100) / 100 << " s\n";
  } catch (const std::exception& e) {
    std::cerr << "hbm-deckgen: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
