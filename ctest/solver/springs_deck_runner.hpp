// SPDX-License-Identifier: GPL-3.0-or-later
// Runs a verification deck of decks/examples/ through hbm-solver into the test's working
// directory and reads its /TH CSV files back (header names -> columns). Used by
// springs_decks_verification.cpp and rigid_decks_verification.cpp.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace hbm::solver::testing {

struct ThTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  // Column whose header contains `key` (first match); fails the test if none.
  std::vector<double> column(const std::string& key) const {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c].find(key) != std::string::npos) {
        std::vector<double> out;
        for (const auto& r : rows) out.push_back(r[c]);
        return out;
      }
    ADD_FAILURE() << "no column containing '" << key << "'";
    return std::vector<double>(rows.size(), 0.0);
  }
};

inline ThTable read_th(const std::filesystem::path& path) {
  ThTable t;
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot open " << path;
  std::string line;
  if (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) t.header.push_back(cell);
  }
  while (std::getline(in, line)) {
    std::vector<double> r;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) r.push_back(std::strtod(cell.c_str(), nullptr));
    if (r.size() == t.header.size()) t.rows.push_back(std::move(r));
  }
  return t;
}

// Run decks/examples/<name>/<name>_0000.rad (extra command-line arguments `args`, output
// folder suffix `tag`); returns the output folder (empty on failure).
inline std::filesystem::path run_deck(const std::string& name, const std::string& args = "",
                                      const std::string& tag = "") {
#ifndef HBM_SOLVER_EXE
  ADD_FAILURE() << "hbm-solver was not built";
  return {};
#else
  const std::filesystem::path out = std::filesystem::current_path() / ("out_" + name + tag);
  std::filesystem::remove_all(out);
  const std::string cmd = std::string(HBM_SOLVER_EXE) + " " + HBM_SOURCE_DIR + "/decks/examples/" + name + "/" +
                          name + "_0000.rad --out " + out.string() + " " + args + " > " + out.string() +
                          ".log 2>&1";
  const int rc = std::system(cmd.c_str());
  EXPECT_EQ(rc, 0) << cmd << " (see " << out.string() << ".log)";
  return rc == 0 ? out : std::filesystem::path{};
#endif
}

}  // namespace hbm::solver::testing
