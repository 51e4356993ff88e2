// SPDX-License-Identifier: GPL-3.0-or-later
// CSV reader for the geometry sources (see table.hpp). Quoted cells are not used by the
// sources; a cell is the text between commas with surrounding blanks removed.
#include "hbm/deckgen/table.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace hbm::deckgen {

namespace {

// "file:line: field: message"; without the line for 0 (the file as a whole), without the
// field when it is empty.
std::string source_error_text(const std::string& file, int line, const std::string& field, const std::string& message) {
  std::string s = file;
  if (line > 0) {
    s += ':';
    s += std::to_string(line);
  }
  s += ": ";
  if (!field.empty()) s += field + ": ";
  return s + message;
}

}  // namespace

SourceError::SourceError(const std::filesystem::path& file, int line, std::string field,
                         const std::string& message)
    : std::runtime_error(source_error_text(file.string(), line, field, message)), file_(file.string()), line_(line) {}

namespace {

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t' || s[a] == '\r')) ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t' || s[b - 1] == '\r')) --b;
  return std::string(s.substr(a, b - a));
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = line.find(',', start);
    out.push_back(trim(std::string_view(line).substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace

Table Table::read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SourceError(path, 0, "", "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse(ss.str(), path);
}

Table Table::parse(const std::string& text, const std::filesystem::path& path) {
  Table t;
  t.path_ = path;
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    std::string s = trim(line);
    if (s.empty() || s[0] == '#') continue;
    if (t.header_.empty()) {
      t.header_ = split(s);
      t.header_line_ = n;
      for (std::size_t i = 0; i < t.header_.size(); ++i) {
        if (t.header_[i].empty()) throw SourceError(path, n, "", "empty column name in the header");
        for (std::size_t k = 0; k < i; ++k)
          if (t.header_[k] == t.header_[i]) throw SourceError(path, n, t.header_[i], "duplicate column");
      }
      continue;
    }
    Row r;
    r.line = n;
    r.cells = split(s);
    if (r.cells.size() != t.header_.size())
      throw SourceError(path, n, "", std::to_string(r.cells.size()) + " fields, the header has " +
                                         std::to_string(t.header_.size()));
    t.rows_.push_back(std::move(r));
  }
  if (t.header_.empty()) throw SourceError(path, n, "", "no header line (file empty or only comments)");
  if (t.rows_.empty()) throw SourceError(path, n, "", "no data rows");
  return t;
}

bool Table::has_column(const std::string& name) const {
  for (const auto& h : header_)
    if (h == name) return true;
  return false;
}

std::size_t Table::column(const std::string& name) const {
  for (std::size_t i = 0; i < header_.size(); ++i)
    if (header_[i] == name) return i;
  throw SourceError(path_, header_line_, name, "missing column");
}

void Table::fail(const Row& r, const std::string& field, const std::string& message) const {
  throw SourceError(path_, r.line, field, message);
}

std::string Table::text(const Row& r, const std::string& name) const { return r.cells[column(name)]; }

bool Table::blank(const Row& r, const std::string& name) const { return r.cells[column(name)].empty(); }

double Table::number(const Row& r, const std::string& name) const {
  const std::string& s = r.cells[column(name)];
  if (s.empty()) fail(r, name, "empty field, a number is required");
  double v = 0;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v))
    fail(r, name, "'" + s + "' is not a number");
  return v;
}

double Table::number_in(const Row& r, const std::string& name, double lo, double hi) const {
  double v = number(r, name);
  if (v < lo || v > hi) {
    std::ostringstream m;
    m << "value " << v << " outside [" << lo << ", " << hi << "]";
    fail(r, name, m.str());
  }
  return v;
}

double Table::number_or(const Row& r, const std::string& name, double fallback) const {
  return blank(r, name) ? fallback : number(r, name);
}

int Table::integer(const Row& r, const std::string& name) const {
  double v = number(r, name);
  if (v != std::floor(v) || std::abs(v) > 1e9) fail(r, name, "not an integer");
  return static_cast<int>(v);
}

}  // namespace hbm::deckgen
