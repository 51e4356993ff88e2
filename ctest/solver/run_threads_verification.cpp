// SPDX-License-Identifier: GPL-3.0-or-later
// Results do not depend on the thread count: the frontal hub impact deck
// (decks/hub_frontal_6p7 with the body model decks/hbm50/hbm50.inc: LAW1 and LAW34 bricks,
// shells, springs, rigid bodies, /INTER/TYPE7 contact, many element groups) run for
// 0.45 ms (300 cycles of 1.5e-3 ms; the impactor touches the skin at about 0.3 ms, so
// the last 100 cycles carry contact forces) with 1 thread, 2 threads and the thread count
// chosen during the run (ThreadChooser: it switches between 2 and 1 thread after 21
// cycles). Every /TH CSV file is bitwise identical between the three runs.
#include "example_deck_runner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>

using hbm::solver::testing::read_text;
using hbm::solver::testing::read_th;
using hbm::solver::testing::ThTable;

namespace fs = std::filesystem;

namespace {

constexpr const char* kCase = "hub_frontal_6p7";
constexpr double kEndTime = 0.45;  // ms

// Copies the hub deck and the body model it includes (../hbm50/hbm50.inc) under ./decks/
// and writes its engine file with /RUN ending at kEndTime and no /ANIM output. Returns the
// starter's path.
fs::path short_hub_deck() {
  const fs::path src = fs::path(HBM_SOURCE_DIR) / "decks";
  const fs::path dst = fs::current_path() / "decks";
  fs::remove_all(dst);
  fs::create_directories(dst / kCase);
  fs::create_directories(dst / "hbm50");
  fs::copy_file(src / "hbm50" / "hbm50.inc", dst / "hbm50" / "hbm50.inc");
  const std::string stem = std::string(kCase);
  fs::copy_file(src / kCase / (stem + "_0000.rad"), dst / kCase / (stem + "_0000.rad"));
  std::string engine = read_text(src / kCase / (stem + "_0001.rad"));
  // /RUN/<name>/1: its data line (the end time) replaced; every /ANIM card (and the data
  // line of /ANIM/DT) dropped.
  const std::size_t run = engine.find("\n/RUN/");
  const std::size_t time_line = run == std::string::npos ? run : engine.find('\n', run + 1);
  const std::size_t time_end = time_line == std::string::npos ? time_line : engine.find('\n', time_line + 1);
  if (time_end == std::string::npos) {
    ADD_FAILURE() << "no /RUN card with an end time in the hub engine deck";
    return {};
  }
  engine.replace(time_line + 1, time_end - time_line - 1, std::to_string(kEndTime));
  engine = std::regex_replace(engine, std::regex("/ANIM/DT\\n[^\\n]*\\n"), "");
  engine = std::regex_replace(engine, std::regex("/ANIM/[^\\n]*\\n"), "");
  EXPECT_NE(engine.find("/RUN/" + stem + "/1\n" + std::to_string(kEndTime) + "\n"), std::string::npos) << engine;
  EXPECT_EQ(engine.find("/ANIM"), std::string::npos) << engine;
  std::ofstream(dst / kCase / (stem + "_0001.rad")) << engine;
  return dst / kCase / (stem + "_0000.rad");
}

std::set<std::string> csv_files(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".csv") names.insert(e.path().filename().string());
  return names;
}

// Runs hbm-solver on `starter` with the command-line arguments `args` (and the
// environment settings `env` before the command) into ./out_hub<tag>/; returns the folder
// (empty on failure). The deck's warnings (rigid-body elements deactivated, ...) go to
// the log ./out_hub<tag>.log.
fs::path run_solver(const fs::path& starter, const std::string& env, const std::string& args, const std::string& tag) {
#ifndef HBM_SOLVER_EXE
  ADD_FAILURE() << "hbm-solver was not built";
  return {};
#else
  const fs::path out = fs::current_path() / ("out_hub" + tag);
  fs::remove_all(out);
  const std::string cmd = env + " '" + HBM_SOLVER_EXE + "' '" + starter.string() + "' --out '" + out.string() + "' " +
                          args + " > '" + out.string() + ".log' 2>&1";
  const int rc = std::system(cmd.c_str());
  EXPECT_EQ(rc, 0) << cmd;
  return rc == 0 ? out : fs::path{};
#endif
}

// The listing line that starts with `key` (e.g. "  threads "), without its line break.
std::string listing_line(const std::string& listing, const std::string& key) {
  const std::size_t p = listing.find("\n" + key);
  if (p == std::string::npos) return {};
  return listing.substr(p + 1, listing.find('\n', p + 1) - p - 1);
}

}  // namespace

TEST(EngineThreads, HubDeckTimeHistoriesAreBitwiseIdenticalWith1And2AndChosenThreads) {
  const fs::path starter = short_hub_deck();
  ASSERT_FALSE(starter.empty());
  const std::string listing_name = std::string(kCase) + "_0001.out";
  const fs::path one = run_solver(starter, "", "--threads 1", "_t1");
  const fs::path two = run_solver(starter, "", "--threads 2", "_t2");
  // No --threads: the chooser times 2 (OMP_NUM_THREADS) against 1 thread and switches.
  const fs::path chosen = run_solver(starter, "OMP_NUM_THREADS=2", "", "_chosen");
  ASSERT_FALSE(one.empty() || two.empty() || chosen.empty());

  // The deck has many element groups of several kinds (else the test says little).
  const std::string listing = read_text(one / listing_name);
  std::printf("hub deck:%s\n", listing_line(listing, "  nodes ").c_str());
  std::size_t n_groups = 0;
  std::set<std::string> kinds;
  for (std::size_t p = listing.find("\n  group "); p != std::string::npos; p = listing.find("\n  group ", p + 1)) {
    ++n_groups;
    const std::size_t k = p + 9;
    kinds.insert(listing.substr(k, listing.find(' ', k) - k));
  }
  EXPECT_GE(n_groups, 20u);
  for (const char* k : {"/BRICK", "/SHELL", "/SH3N", "/SPRING"}) EXPECT_EQ(kinds.count(k), 1u) << k;
  // The chosen-threads run did run cycles on 1 and on 2 threads.
  const std::string threads = listing_line(read_text(chosen / listing_name), "  threads ");
  std::printf("chosen run:%s\n", threads.c_str());
  EXPECT_NE(threads.find("chosen per stretch"), std::string::npos) << threads;
  EXPECT_EQ(threads.find(" 0 cycles on 1,"), std::string::npos) << threads;
  EXPECT_EQ(threads.find(", 0 on 2"), std::string::npos) << threads;

  const auto files = csv_files(one);
  EXPECT_EQ(files.size(), 4u);
  EXPECT_EQ(files, csv_files(two));
  EXPECT_EQ(files, csv_files(chosen));
  for (const auto& f : files) {
    const std::string a = read_text(one / f);
    EXPECT_GT(a.size(), 1000u) << f;
    EXPECT_TRUE(a == read_text(two / f)) << f << " differs between 1 and 2 threads";
    EXPECT_TRUE(a == read_text(chosen / f)) << f << " differs between 1 thread and the chosen count";
  }
  // Contact has started: the impactor/skin normal force has risen above zero (the skin
  // nodes it first meets are struck off and met again, so the force at one sample can be 0).
  const ThTable inter = read_th(one / (std::string(kCase) + "_TH_INTER_31003.csv"));
  ASSERT_FALSE(inter.rows.empty());
  const auto fns = inter.column("FN");
  const double t_end = inter.column("time").back(), fn = *std::max_element(fns.begin(), fns.end());
  std::printf("impactor contact FN, largest sample to %.3f ms: %.4g kN\n", t_end, fn);
  EXPECT_NEAR(t_end, kEndTime, 1e-9);
  EXPECT_GT(fn, 0.1);
}
