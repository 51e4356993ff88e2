// SPDX-License-Identifier: GPL-3.0-or-later
// CSV tables of geometry/: '#' comment lines (sources), one header line, then data rows.
// Every access that fails (missing column, empty or non-numeric field, value out of range)
// throws SourceError naming file, line and field, so a malformed source stops deckgen with
// a message the user can act on.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace hbm::deckgen {

// An error in a geometry source: "file:line: field: message"; line 0 (an error of the
// file as a whole, such as a missing row or an unreadable surface) gives "file: field: message".
class SourceError : public std::runtime_error {
 public:
  SourceError(const std::filesystem::path& file, int line, std::string field, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  std::string file_;
  int line_;
};

class Table {
 public:
  struct Row {
    int line = 0;  // 1-based line in the file
    std::vector<std::string> cells;
  };

  static Table read(const std::filesystem::path& path);
  // Parse text already in memory (`path` is used in messages).
  static Table parse(const std::string& text, const std::filesystem::path& path);

  const std::filesystem::path& path() const { return path_; }
  const std::vector<std::string>& header() const { return header_; }
  const std::vector<Row>& rows() const { return rows_; }
  bool has_column(const std::string& name) const;

  // Field accessors; `name` must be a header column (else SourceError at the header line).
  std::string text(const Row& r, const std::string& name) const;
  double number(const Row& r, const std::string& name) const;
  // Number with a valid range [lo, hi]; blank allowed only if `fallback` is given.
  double number_in(const Row& r, const std::string& name, double lo, double hi) const;
  double number_or(const Row& r, const std::string& name, double fallback) const;
  int integer(const Row& r, const std::string& name) const;
  bool blank(const Row& r, const std::string& name) const;
  [[noreturn]] void fail(const Row& r, const std::string& field, const std::string& message) const;

 private:
  std::size_t column(const std::string& name) const;
  std::filesystem::path path_;
  int header_line_ = 0;
  std::vector<std::string> header_;
  std::vector<Row> rows_;
};

}  // namespace hbm::deckgen
