// SPDX-License-Identifier: GPL-3.0-or-later
// What the deck library tests share: the folder of the small test decks, the diagnostics
// of a read as text (for failure messages), a file's bytes.
#pragma once

#include "hbm/deck/io.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace hbm::deck::testing {

// ctest/deck/decks: small_0000.rad, small_0001.rad, small_nodes.inc, ...
inline const std::filesystem::path kDir = HBM_DECK_TEST_DIR;

inline std::string messages(const ReadResult& r) {
  std::ostringstream os;
  print_diagnostics(os, r);
  return os.str();
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

}  // namespace hbm::deck::testing
