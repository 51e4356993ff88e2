// SPDX-License-Identifier: GPL-3.0-or-later
// Reader for time-history CSV files: the solver's /TH output (one CSV per /TH group, first
// line a header such as `time [ms],node 1201 sternum DX [mm],part 3 ribs IE [J],...`) or any
// comma-separated file with a time column. Units sit in square brackets at the end of a
// header; a header without brackets has an empty unit (the case file then supplies it).
// Lines starting with '#' before the header are comments. Every malformed line is reported
// as FILE:LINE.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hbm::corridors {

struct TimeHistoryTable {
  std::string path;                          ///< file as given (used in messages)
  std::vector<std::string> headers;          ///< full header text of each column
  std::vector<std::string> names;            ///< header without the "[unit]" part, trimmed
  std::vector<std::string> units;            ///< unit in brackets, "" when none
  std::vector<std::vector<double>> columns;  ///< column-major data
  std::size_t time_column = 0;               ///< index of the time column
  long header_line = 1;                      ///< line number of the header
  std::size_t n_rows() const { return columns.empty() ? 0 : columns[0].size(); }
};

/// Splits "name [unit]" into name and unit (both trimmed); unit is "" when absent.
void split_header(std::string_view header, std::string& name, std::string& unit);

/// Reads a time-history CSV. The time column is the column whose name is "time" or starts
/// with "time" (case-insensitive), else "t"; the file must have one. Time must not decrease.
/// Throws InputError (file:line) on any malformed content.
TimeHistoryTable read_time_history_csv(const std::filesystem::path& path);

/// Column index for key: an exact match of the full header or of the name (without unit),
/// else a unique case-insensitive substring of the names. Returns -1 when nothing matches;
/// throws InputError listing the candidates when the substring is ambiguous.
long find_column(const TimeHistoryTable& table, std::string_view key);

/// "  col1\n  col2 ..." for error messages listing the available columns.
std::string list_columns(const TimeHistoryTable& table);

}  // namespace hbm::corridors
