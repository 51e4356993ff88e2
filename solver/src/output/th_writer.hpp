// SPDX-License-Identifier: GPL-3.0-or-later
// Time-history CSV of one /TH group: header naming each column with object, id, title,
// variable and unit; global energy and mass columns first; one row per /TFILE time,
// flushed, so a killed run leaves a valid file up to its last full row.
#pragma once

#include "hbm/solver/cycle.hpp"
#include "hbm/solver/model.hpp"

#include <filesystem>
#include <fstream>
#include <string>

namespace hbm::solver {

class ThWriter {
 public:
  bool open(const std::filesystem::path& file, const ThGroup& group, const hbm::deck::Units& units,
            std::string& error);
  void write_row(double time, const GlobalEnergies& e);
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  const ThGroup* group_ = nullptr;
  std::string row_;  // the row being written (kept: its capacity is reused)
};

// File name of a group: <run>_TH_<KIND>_<id>.csv, e.g. impact_TH_NODE_1.csv.
std::string th_file_name(const std::string& run_name, const ThGroup& g);

}  // namespace hbm::solver
