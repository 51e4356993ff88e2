// SPDX-License-Identifier: GPL-3.0-or-later
// /DT/SHELL/CST in an engine deck, end to end with hbm-solver on
// decks/examples/shell_fold_small_strain (one 37 x 6.5 mm soft quad, three corners fixed,
// corner 3 driven across edge 1-2 at 10 mm/ms):
//  - without the switch the nodal mass scaling chases the collapsing step and the run stops
//    on added mass (exit code 3);
//  - with /DT/SHELL/CST (Tsca 0.9, Tmin 1.5 us) the quad switches where
//    0.9 A / l_max / c = Tmin, an instant fixed by its geometry, from then on the added mass
//    stays constant, the run ends normally with the energy balance closed, and the
//    listing names the part with the switched element;
//  - Tmin 0 is a deck error naming the engine file, the keyword and the field, exit code 1;
//  - 3-node shells are not concerned (OpenRadioss' Eltyp SHELL is the 4-node shell): a deck of
//    triangles runs as without the card, with no warning;
//  - /DT/SH_3N/CST does the same for a triangle (decks/examples/shell_fold_small_strain_tria,
//    corner 3 driven across edge 1-2 at 2 mm/ms): switch where 0.9 x 2A / l_max / c = Tmin,
//    constant added mass after it, normal end; without it the run stops on added mass.
#include "example_deck_runner.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
namespace t = hbm::solver::testing;

// Copies shell_fold_small_strain into ./<tag>/ with `cst` appended to the engine deck;
// returns the starter path.
fs::path deck_with(const std::string& tag, const std::string& cst,
                   const std::string& name = "shell_fold_small_strain") {
  const fs::path src = t::example_deck(name).parent_path();
  const fs::path dir = fs::current_path() / ("shell_cst_" + tag + t::per_process_suffix());
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(src / (name + "_0000.rad"), dir / (name + "_0000.rad"));
  std::ofstream(dir / (name + "_0001.rad")) << t::read_text(src / (name + "_0001.rad")) << cst;
  return dir / (name + "_0000.rad");
}

// Time at which the quad's step reaches Tmin / Tsca: side 3-4 is the longest,
// l = sqrt(37^2 + s^2), A = 37 (13 - s) / 2 with s = v t, c = sqrt(E / (rho (1 - nu^2))).
double switch_time(double tsca, double tmin) {
  const double c = std::sqrt(1e-3 / (1e-6 * (1 - 0.3 * 0.3))), v = 10.0;
  double lo = 0, hi = 1.3;  // the step falls monotonically to 0 at t = 1.3 ms
  for (int it = 0; it < 200; ++it) {
    const double tm = 0.5 * (lo + hi), s = v * tm;
    const double dt = 37 * (13 - s) / 2 / std::sqrt(37.0 * 37.0 + s * s) / c;
    (tsca * dt > tmin ? lo : hi) = tm;
  }
  return 0.5 * (lo + hi);
}

// Same for the triangle (0, 0), (37, 0), (37, 6.5 - v t), v = 2 mm/ms: side 3-1 is the
// longest, 2 A / l_max = 37 y3 / sqrt(37^2 + y3^2).
double switch_time_tria(double tsca, double tmin) {
  const double c = std::sqrt(1e-3 / (1e-6 * (1 - 0.3 * 0.3))), v = 2.0;
  double lo = 0, hi = 3.25;
  for (int it = 0; it < 200; ++it) {
    const double tm = 0.5 * (lo + hi), y3 = 6.5 - v * tm;
    const double lc = 37 * y3 / std::sqrt(37.0 * 37.0 + y3 * y3);  // 2 A / l_max
    const double dt = std::min(lc, lc * lc / 1.0) / c;  // flexural bound once l_c < t = 1 mm
    (tsca * dt > tmin ? lo : hi) = tm;
  }
  return 0.5 * (lo + hi);
}

// First output time at which column `col` has its final value.
double first_time_at_final(const t::ThTable& th, std::size_t col) {
  const double last = th.rows.back()[col];
  for (const auto& row : th.rows)
    if (std::abs(row[col] - last) <= 1e-12 * std::abs(last)) return row[th.col("time")];
  return -1;
}

}  // namespace

TEST(ShellSmallStrainSwitchDeck, FoldedQuadRunsToTheEndWithConstantAddedMass) {
  const fs::path starter = deck_with("on", "/DT/SHELL/CST\n0.9 1.5E-3\n");
  std::string out;
  ASSERT_EQ(t::run_solver(starter, out), 0) << out;
  const auto th = t::read_th(starter.parent_path() / "out" / "shell_fold_small_strain_TH_NODE_1.csv");
  ASSERT_FALSE(th.rows.empty());
  const std::size_t ct = th.col("time"), cr = th.col("mass ratio"), ce = th.col("energy error"),
                    cdy = th.col("node 3 driven DY");
  const auto& last = th.rows.back();
  EXPECT_NEAR(last[ct], 1.5, 1e-9);
  EXPECT_NEAR(last[cdy], -15.0, 1e-9) << "corner 3 driven 2 mm past edge 1-2";
  EXPECT_GT(last[cr], 0.0);
  EXPECT_LT(last[cr], 0.1);
  // First output at which the added mass has its final value: the switch, one output
  // interval (15 us) after the instant the geometry fixes at the latest.
  const double t_const = first_time_at_final(th, cr);
  const double ts = switch_time(0.9, 1.5e-3);
  EXPECT_GT(ts, 1.28);
  EXPECT_GE(t_const, ts - 1e-9);
  EXPECT_LE(t_const, ts + 0.015 + 1e-9);
  // Energy balance: within 0.5 % through the cycles around the switch (forces ~1/A change
  // steeply from one cycle to the next), closed at the end (the frozen sliver stores what
  // the driven corner puts in).
  for (const auto& row : th.rows) EXPECT_LT(std::abs(row[ce]), 5e-3) << "t = " << row[ct];
  EXPECT_LT(std::abs(last[ce]), 1e-4);
  const std::string listing = t::read_text(starter.parent_path() / "out" / "shell_fold_small_strain_0001.out");
  EXPECT_NE(listing.find("ELEMENTS SWITCHED TO SMALL STRAIN (first and last switch, ms)\n  /SHELL part 1 'skin': 1 of 1, at "),
            std::string::npos)
      << listing;
  // The listing's switch time: the first time-history sample (15 us apart) at or after it.
  const double tl = t::switch_time_in_listing(listing, "/SHELL part 1 'skin': 1 of 1");
  EXPECT_GE(tl, ts - 1e-9) << listing;
  EXPECT_LE(tl, ts + 0.015 + 1e-9) << listing;
}

TEST(ShellSmallStrainSwitchDeck, WithoutTheSwitchTheAddedMassStopsTheRun) {
  std::string out;
  EXPECT_EQ(t::run_solver(deck_with("off", ""), out), 3) << out;
  EXPECT_NE(out.find("exceeds DMmax"), std::string::npos) << out;
  EXPECT_NE(out.find("part 1 'skin'"), std::string::npos) << out;
}

// Tmin 0 is read as OpenRadioss does (no /DT Tmin to fall back on): no element switches, so
// the run ends as without the card, and a warning says so.
TEST(ShellSmallStrainSwitchDeck, TminZeroSwitchesNothingAsInOpenRadioss) {
  std::string out;
  EXPECT_EQ(t::run_solver(deck_with("tmin0", "/DT/SHELL/CST\n0.9 0\n"), out), 3) << out;
  EXPECT_NE(out.find("exceeds DMmax"), std::string::npos) << out;
  EXPECT_NE(out.find("Tmin = 0: no element switches to small strain under /DT/SHELL/CST"), std::string::npos) << out;
}

TEST(ShellSmallStrainSwitchDeck, TrianglesKeepTheirFormulationWithoutWarning) {
  // /DT/SHELL/CST is OpenRadioss' Eltyp SHELL (4-node shells); 3-node shells have their own
  // Eltyp SH_3N, so a deck of triangles runs as without the card, and says nothing of it.
  // Tmin 1 ms lies above every element's step: applied to the triangles, it would switch
  // them all at the first cycle (checked: with /DT/SH_3N/CST instead this test fails).
  const fs::path src = t::example_deck("shell_pull_failure_tria").parent_path();
  const fs::path dir = fs::current_path() / ("shell_cst_tria" + t::per_process_suffix());
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(src / "shell_pull_failure_tria_0000.rad", dir / "shell_pull_failure_tria_0000.rad");
  std::ofstream(dir / "shell_pull_failure_tria_0001.rad")
      << t::read_text(src / "shell_pull_failure_tria_0001.rad") << "/DT/SHELL/CST\n0.9 1.0\n";
  std::string out;
  EXPECT_EQ(t::run_solver(dir / "shell_pull_failure_tria_0000.rad", out), 0) << out;
  EXPECT_EQ(out.find("/DT/SHELL/CST"), std::string::npos) << out;
  EXPECT_EQ(t::read_text(dir / "out" / "shell_pull_failure_tria_0001.out").find("SWITCHED TO SMALL STRAIN"),
            std::string::npos);
}

TEST(ShellSmallStrainSwitchDeck, FoldedTriangleRunsToTheEndWithConstantAddedMass) {
  const std::string name = "shell_fold_small_strain_tria";
  const fs::path starter = deck_with("tria_on", "/DT/SH_3N/CST\n0.9 1.5E-3\n", name);
  std::string out;
  ASSERT_EQ(t::run_solver(starter, out), 0) << out;
  const auto th = t::read_th(starter.parent_path() / "out" / (name + "_TH_NODE_1.csv"));
  ASSERT_FALSE(th.rows.empty());
  const std::size_t cr = th.col("mass ratio"), ce = th.col("energy error"), cdy = th.col("node 3 driven DY");
  const auto& last = th.rows.back();
  EXPECT_NEAR(last[cdy], -2.0 * last[th.col("time")], 1e-9);
  EXPECT_LT(last[cdy], -8.0 + 0.05) << "corner 3 driven 1.5 mm past edge 1-2";
  EXPECT_GT(last[cr], 0.0);
  EXPECT_LT(last[cr], 0.1);
  const double ts = switch_time_tria(0.9, 1.5e-3), t_const = first_time_at_final(th, cr);
  EXPECT_GT(ts, 3.1);
  EXPECT_GE(t_const, ts - 1e-9);
  EXPECT_LE(t_const, ts + 0.02 + 1e-9);
  for (const auto& row : th.rows) EXPECT_LT(std::abs(row[ce]), 5e-3) << "t = " << row[0];
  const std::string listing = t::read_text(starter.parent_path() / "out" / (name + "_0001.out"));
  EXPECT_NE(listing.find("ELEMENTS SWITCHED TO SMALL STRAIN (first and last switch, ms)\n  /SH3N part 1 'skin': 1 of 1, at "),
            std::string::npos)
      << listing;
  const double tl = t::switch_time_in_listing(listing, "/SH3N part 1 'skin': 1 of 1");
  EXPECT_GE(tl, ts - 1e-9) << listing;
  EXPECT_LE(tl, ts + 0.02 + 1e-9) << listing;
}

TEST(ShellSmallStrainSwitchDeck, WithoutTheSwitchTheTriangleStopsTheRun) {
  std::string out;
  EXPECT_EQ(t::run_solver(deck_with("tria_off", "", "shell_fold_small_strain_tria"), out), 3) << out;
  EXPECT_NE(out.find("exceeds DMmax"), std::string::npos) << out;
}

TEST(ShellSmallStrainSwitchDeck, TriangleTminZeroSwitchesNothingAsInOpenRadioss) {
  std::string out;
  EXPECT_EQ(t::run_solver(deck_with("tria_tmin0", "/DT/SH_3N/CST\n0.9 0\n", "shell_fold_small_strain_tria"), out), 3)
      << out;
  EXPECT_NE(out.find("exceeds DMmax"), std::string::npos) << out;
  EXPECT_NE(out.find("Tmin = 0: no element switches to small strain under /DT/SH_3N/CST"), std::string::npos) << out;
}
