// SPDX-License-Identifier: GPL-3.0-or-later
// /DT/BRICK/CST in an engine deck, end to end with hbm-solver on the planted-failure deck
// decks/examples/inverted_element (one soft 1 mm brick whose top face is driven down),
// here slowed to 10 mm/ms for 0.15 ms (1.5 times its height):
//  - without the switch the run stops with an inverted element;
//  - with /DT/BRICK/CST/1 and VDEF_min 0.3 the brick switches to small strain and the run
//    ends normally with the top face at least 1.5 mm down, below the fixed bottom face;
//  - Tmin 0 or an ASP_min (not supported) is a deck error naming the engine file, the
//    keyword and the field, exit code 1;
//  - on a deck with tetrahedra (which keep the large strain formulation) the run says so.
#include "example_deck_runner.hpp"

#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

// Copies inverted_element into ./<tag>/ with the crush slowed to 10 mm/ms for 0.15 ms and
// `cst` inserted after /PRINT in the engine deck; returns the starter path.
fs::path deck_with(const std::string& tag, const std::string& cst) {
  const fs::path src = hbm::solver::testing::example_deck("inverted_element").parent_path();
  const fs::path dir = fs::current_path() / ("cst_" + tag + hbm::solver::testing::per_process_suffix());
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string starter = hbm::solver::testing::read_text(src / "inverted_element_0000.rad");
  const std::string fast = "-1.000000000000E+02", slow = "-1.000000000000E+01";
  const auto vpos = starter.find(fast);
  EXPECT_NE(vpos, std::string::npos);
  if (vpos != std::string::npos) starter.replace(vpos, fast.size(), slow);
  std::ofstream(dir / "inverted_element_0000.rad") << starter;
  std::string engine = hbm::solver::testing::read_text(src / "inverted_element_0001.rad");
  const auto rpos = engine.find("\n0.05\n");
  EXPECT_NE(rpos, std::string::npos);
  if (rpos != std::string::npos) engine.replace(rpos, 6, "\n0.15\n");
  const auto pos = engine.find("/PRINT/-10\n");
  EXPECT_NE(pos, std::string::npos);
  engine.insert(pos + std::string("/PRINT/-10\n").size(), cst);
  std::ofstream(dir / "inverted_element_0001.rad") << engine;
  return dir / "inverted_element_0000.rad";
}

int run_solver(const fs::path& starter, std::string& output) {
  return hbm::solver::testing::run_solver(starter, output);
}

}  // namespace

TEST(SmallStrainSwitchDeck, CrushedBrickRunsToTheEnd) {
  const fs::path starter = deck_with("vdef", "/DT/BRICK/CST/1\n0.9 1e-9\n0 0.3\n");
  std::string out;
  ASSERT_EQ(run_solver(starter, out), 0) << out;
  const auto th = hbm::solver::testing::read_th(starter.parent_path() / "out" / "inverted_element_TH_NODE_1.csv");
  ASSERT_FALSE(th.rows.empty());
  const std::size_t t = th.col("time"), dz = th.col("DZ");
  const double t_end = th.rows.back()[t];
  EXPECT_GE(t_end, 0.15);
  EXPECT_NEAR(th.rows.back()[dz], -10.0 * t_end, 1e-6) << "the top face went 0.5 mm below the fixed bottom face";
  const std::string listing =
      hbm::solver::testing::read_text(starter.parent_path() / "out" / "inverted_element_0001.out");
  EXPECT_NE(listing.find("ELEMENTS SWITCHED TO SMALL STRAIN (first and last switch, ms)\n  /BRICK part 1 'cube': 1 of 1, at "),
            std::string::npos)
      << listing;
  // The top face at -10 t with its corners free sideways: V/V0 >= 1 + DZ, so VDEF_min 0.3
  // cannot be reached before DZ = -0.7 mm (t = 0.07 ms). The listing's time is a cycle's time
  // (every cycle is written to the time history here: steps of 4-18 us, interval 1 us).
  const double ts = hbm::solver::testing::switch_time_in_listing(listing, "/BRICK part 1 'cube': 1 of 1");
  EXPECT_GE(ts, 0.07 - 5e-4) << listing;
  EXPECT_LT(ts, t_end) << listing;
  bool at_a_cycle = false;
  for (const auto& row : th.rows) at_a_cycle = at_a_cycle || std::abs(row[t] - ts) <= 5e-4;  // printed to 1 us
  EXPECT_TRUE(at_a_cycle) << ts;
}

TEST(SmallStrainSwitchDeck, WithoutTheSwitchTheSlowCrushInverts) {
  std::string out;
  EXPECT_EQ(run_solver(deck_with("none", ""), out), 3) << out;
  EXPECT_NE(out.find("inverted"), std::string::npos) << out;
}

// Tmin 0 as in OpenRadioss (no /DT Tmin to fall back on): the time step never switches the
// brick, so the slow crush inverts it as without the card (a warning says so); with Iflag 1
// the volume criterion still switches it and the run ends normally.
TEST(SmallStrainSwitchDeck, TminZeroLeavesOnlyTheVolumeCriterion) {
  std::string out;
  EXPECT_EQ(run_solver(deck_with("tmin0", "/DT/BRICK/CST/0\n0.9 0\n"), out), 3) << out;
  EXPECT_NE(out.find("inverted"), std::string::npos) << out;
  EXPECT_NE(out.find("Tmin = 0: the time step never switches a brick"), std::string::npos) << out;
  EXPECT_EQ(run_solver(deck_with("tmin0_vdef", "/DT/BRICK/CST/1\n0.9 0\n0 0.3\n"), out), 0) << out;
}

TEST(SmallStrainSwitchDeck, AspectRatioSwitchIsNotSupported) {
  std::string out;
  EXPECT_EQ(run_solver(deck_with("asp", "/DT/BRICK/CST/1\n0.9 1e-4\n2 0\n"), out), 1);
  EXPECT_NE(out.find("inverted_element_0001.rad:"), std::string::npos) << out;
  EXPECT_NE(out.find("ASP_min"), std::string::npos) << out;
  EXPECT_NE(out.find("not supported"), std::string::npos) << out;
}

