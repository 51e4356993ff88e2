// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers of the corridors reader tests: a file written into a per-process temporary
// folder, the message of the InputError a call throws, the shipped corridor data folder,
// case files that must fail at a given line.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hbm/corridors/case_definition.hpp"
#include "hbm/corridors/input_error.hpp"

namespace hbm::corridors::test_support {

/// Writes `text` to <tmp>/hbm_corridors_<pid>/<name> (one folder per test process) and
/// returns the path.
inline std::filesystem::path temp_file(const std::string& name, const std::string& text) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("hbm_corridors_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path p = dir / name;
  std::ofstream(p) << text;
  return p;
}

/// The message of the InputError `f` throws, or "(no error)".
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

inline const std::string data_dir = std::string(HBM_CORRIDORS_SOURCE_DIR) + "/data/";

/// A case file that must fail: the text after a common head, the line the error names and
/// words its message holds.
struct BadCase {
  std::string tail;
  int line;
  std::string words;
};

/// Loads head + tail of each as bad.toml and expects "bad.toml:LINE:" and the words.
inline void expect_case_errors(const std::string& head, const std::vector<BadCase>& bad) {
  for (const auto& b : bad) {
    const auto p = temp_file("bad.toml", head + b.tail);
    const std::string msg = error_of([&] { load_case(p); });
    SCOPED_TRACE(msg);
    EXPECT_NE(msg.find("bad.toml:" + std::to_string(b.line) + ":"), std::string::npos);
    EXPECT_NE(msg.find(b.words), std::string::npos);
  }
}

}  // namespace hbm::corridors::test_support
