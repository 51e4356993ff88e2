// SPDX-License-Identifier: GPL-3.0-or-later
// Runs a verification deck of decks/examples/<name>/ and reads its outputs back: the /TH
// CSV files (header names -> columns), the listing, and VTK frames through a Python script
// run with VTK's own reader. Two ways to run:
//  - run_deck: the hbm-solver executable (HBM_SOLVER_EXE), outputs in
//    ./out_<name><tag><per-process suffix>/, its console in the same name + .log (any test area);
//  - run_in_process: hbm::solver::run_deck in the test process, keeping the frozen model
//    for inspection (tests linked with the whole engine: run_* and shelldecks_*).
//  - run_solver / run_modified_deck: hbm-solver on a deck whose run is expected to fail
//    (deck errors): exit code and console text, for the message checks.
// Used by the deck verifications of the engine, shells, springs, rigid bodies and contact.
#pragma once

#include "hbm/solver/run.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <vector>
#include <sys/wait.h>

namespace hbm::solver::testing {

// CTest runs every test case of a file as its own process (gtest_discover_tests), so the
// fixtures of one suite run the same deck at the same time: each process writes into a
// folder named after its --gtest_filter (empty for a whole-file run).
inline std::string per_process_suffix() {
  const std::string f = ::testing::GTEST_FLAG(filter);
  if (f.empty() || f == "*") return "";
  std::string s = "_";
  for (char c : f) s += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return s;
}

inline std::filesystem::path example_deck(const std::string& name) {
  return std::filesystem::path(HBM_SOURCE_DIR) / "decks" / "examples" / name / (name + "_0000.rad");
}

// One /TH CSV file: the header line, then rows of numbers.
struct ThTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  // Index of the first column whose header contains `key`; fails the test if none.
  std::size_t col(const std::string& key) const {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c].find(key) != std::string::npos) return c;
    ADD_FAILURE() << "no column containing '" << key << "'";
    return 0;
  }
  std::vector<double> column(std::size_t c) const {
    std::vector<double> out;
    out.reserve(rows.size());
    for (const auto& r : rows) out.push_back(r.at(c));
    return out;
  }
  std::vector<double> column(const std::string& key) const { return column(col(key)); }
};

// Reads a CSV written by the engine; a row whose number of cells differs from the
// header's fails the test (and is left out).
inline ThTable read_th(const std::filesystem::path& path) {
  ThTable t;
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot open " << path;
  std::string line;
  if (std::getline(in, line)) {
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) t.header.push_back(cell);
  }
  for (std::size_t n = 2; std::getline(in, line); ++n) {
    std::vector<double> r;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) r.push_back(std::strtod(cell.c_str(), nullptr));
    if (r.size() == t.header.size()) {
      t.rows.push_back(std::move(r));
    } else {
      ADD_FAILURE() << path << ":" << n << ": " << r.size() << " cells, header has " << t.header.size();
    }
  }
  return t;
}

// Whole text of a file (the listing <name>_0001.out, a console log).
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot open " << path;
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The listing's ELEMENTS SWITCHED TO SMALL STRAIN line of a part, e.g. "  /SHELL part 1
// 'skin': 1 of 1": the time after ", at " (all its elements switched at one sampling time)
// or after ", from " (the first); NaN if the line or the time is missing.
inline double switch_time_in_listing(const std::string& listing, const std::string& part_line) {
  const auto at = listing.find(part_line);
  if (at == std::string::npos) return std::nan("");
  const std::string line = listing.substr(at, listing.find('\n', at) - at);
  for (const char* key : {", at ", ", from "}) {
    const auto k = line.find(key);
    if (k != std::string::npos) return std::strtod(line.c_str() + k + std::strlen(key), nullptr);
  }
  return std::nan("");
}

// Run hbm-solver on decks/examples/<name>/<name>_0000.rad (extra command-line arguments
// `args`, output folder suffix `tag`); returns the output folder (empty on failure).
inline std::filesystem::path run_deck(const std::string& name, const std::string& args = "",
                                      const std::string& tag = "") {
#ifndef HBM_SOLVER_EXE
  ADD_FAILURE() << "hbm-solver was not built";
  return {};
#else
  const std::filesystem::path out = std::filesystem::current_path() / ("out_" + name + tag + per_process_suffix());
  std::filesystem::remove_all(out);
  const std::string cmd = std::string("'") + HBM_SOLVER_EXE + "' '" + example_deck(name).string() + "' --out '" +
                          out.string() + "' " + args + " > '" + out.string() + ".log' 2>&1";
  const int rc = std::system(cmd.c_str());
  EXPECT_EQ(rc, 0) << cmd << " (see " << out.string() << ".log)";
  return rc == 0 ? out : std::filesystem::path{};
#endif
}

// hbm-solver on `starter` with its outputs in <starter folder>/out; returns the exit code
// and sets `output` to the console text (both streams).
inline int run_solver(const std::filesystem::path& starter, std::string& output) {
#ifndef HBM_SOLVER_EXE
  ADD_FAILURE() << "hbm-solver was not built";
  return -1;
#else
  const std::filesystem::path dir = starter.parent_path(), log = dir / "log.txt";
  const std::string cmd = std::string("'") + HBM_SOLVER_EXE + "' '" + starter.string() + "' --out '" +
                          (dir / "out").string() + "' > '" + log.string() + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  output = read_text(log);
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
#endif
}

// The folder run_modified_deck uses for `tag` (its outputs are in <folder>/out).
inline std::filesystem::path modified_deck_dir(const std::string& tag) {
  return std::filesystem::current_path() / ("bad_" + tag + per_process_suffix());
}

// Copies decks/examples/<name>/ into ./bad_<tag><per-process suffix>/ with the first `from`
// replaced by `to` in the starter deck (the engine deck as it is) and runs hbm-solver on it:
// exit code and console text, as run_solver.
inline int run_modified_deck(const std::string& name, const std::string& tag, const std::string& from,
                             const std::string& to, std::string& output) {
  const std::filesystem::path src = example_deck(name).parent_path();
  const std::filesystem::path dir = modified_deck_dir(tag);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::string starter = read_text(src / (name + "_0000.rad"));
  const auto pos = starter.find(from);
  EXPECT_NE(pos, std::string::npos) << "pattern not in deck: " << from;
  if (pos != std::string::npos) starter.replace(pos, from.size(), to);
  std::ofstream(dir / (name + "_0000.rad")) << starter;
  std::filesystem::copy_file(src / (name + "_0001.rad"), dir / (name + "_0001.rad"));
  return run_solver(dir / (name + "_0000.rad"), output);
}

// A run in the test process: the model as it was at the end, the result, the output folder.
struct InProcessRun {
  Model model;
  RunResult result;
  std::filesystem::path out;
};

// Runs `starter` (default: the example deck `name`) with `threads` (0: the default) into
// ./out_<name>[_t<threads>]/; anything written to the error stream fails the test.
inline std::unique_ptr<InProcessRun> run_in_process(const std::string& name, std::filesystem::path starter = {},
                                                    int threads = 0) {
  auto r = std::make_unique<InProcessRun>();
  r->out = std::filesystem::current_path() /
           ("out_" + name + (threads ? "_t" + std::to_string(threads) : "") + per_process_suffix());
  std::filesystem::remove_all(r->out);
  RunOptions opt;
  opt.out_dir = r->out;
  opt.threads = threads;
  std::ostringstream err;
  r->result = hbm::solver::run_deck(starter.empty() ? example_deck(name) : starter, opt, err, r->model);
  EXPECT_TRUE(err.str().empty()) << err.str();
  return r;
}

// Writes `code` to ./<script_name> and runs it with the Python that has VTK (HBM_PYTHON),
// arguments `args`; returns the exit status (0: the script's assertions held).
inline int run_python(const std::string& script_name, const std::string& code, const std::string& args) {
#ifndef HBM_PYTHON
  ADD_FAILURE() << "no Python with VTK configured";
  return -1;
#else
  const std::filesystem::path script = std::filesystem::current_path() / script_name;
  std::ofstream(script) << code;
  const std::string cmd = std::string(HBM_PYTHON) + " '" + script.string() + "' " + args;
  const int rc = std::system(cmd.c_str());
  EXPECT_EQ(rc, 0) << cmd;
  return rc;
#endif
}

}  // namespace hbm::solver::testing
