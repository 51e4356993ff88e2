// SPDX-License-Identifier: GPL-3.0-or-later
// Source loading: reads the main deck and every #include'd file (path relative to the
// including file), keeps the include chain, detects include cycles, and yields the lines
// of all files in reading order with their locations. Comment lines (# in column 1) are
// dropped here; #include lines are replaced by the included file's lines.
#pragma once

#include "hbm/deck/deck.hpp"
#include "hbm/deck/io.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hbm::deck::detail {

struct SourceLine {
  std::string_view text;  // without the line terminator
  SourceLoc loc;
};

struct Sources {
  std::vector<std::unique_ptr<std::string>> buffers;  // file contents (stable addresses)
  std::vector<SourceLine> lines;
};

// Loads `text` as file 0 named `name` (already registered in deck.files), following
// includes. Problems (missing file, cycle, depth) go to `diags`.
void load_sources(std::string_view text, Deck& deck, Sources& out, std::vector<Diagnostic>& diags);

// Reads a whole file; false if it cannot be read.
bool read_file(const std::filesystem::path& p, std::string& out);

}  // namespace hbm::deck::detail
