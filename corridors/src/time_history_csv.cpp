// SPDX-License-Identifier: GPL-3.0-or-later
// Time-history CSV reader (see time_history_csv.hpp).
#include "hbm/corridors/time_history_csv.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>

#include "csv_fields.hpp"
#include "hbm/corridors/input_error.hpp"

namespace hbm::corridors {
namespace {

using csv::trim;
using csv::split_line;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool parse_double(const std::string& s, double& v) {
  if (s.empty()) return false;
  const char* b = s.data();
  const char* e = s.data() + s.size();
  if (*b == '+') ++b;
  auto [ptr, ec] = std::from_chars(b, e, v);
  return ec == std::errc() && ptr == e && std::isfinite(v);  // "nan" and "inf" are refused
}

}  // namespace

void split_header(std::string_view header, std::string& name, std::string& unit) {
  std::string h = trim(header);
  unit.clear();
  if (!h.empty() && h.back() == ']') {
    const auto open = h.rfind('[');
    if (open != std::string::npos) {
      unit = trim(std::string_view(h).substr(open + 1, h.size() - open - 2));
      h = trim(std::string_view(h).substr(0, open));
    }
  }
  name = h;
}

TimeHistoryTable read_time_history_csv(const std::filesystem::path& path) {
  TimeHistoryTable t;
  t.path = path.string();
  std::ifstream in(path);
  if (!in) throw InputError(t.path, 0, "cannot open time-history file");
  std::string line;
  long line_no = 0;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string tl = trim(line);
    if (tl.empty()) continue;
    if (!have_header) {
      if (tl[0] == '#') continue;
      t.headers = split_line(tl);
      t.header_line = line_no;
      for (const auto& h : t.headers) {
        std::string n, u;
        split_header(h, n, u);
        if (n.empty())
          throw InputError(t.path, line_no, "empty column name in header '" + h + "'");
        t.names.push_back(n);
        t.units.push_back(u);
      }
      t.columns.assign(t.headers.size(), {});
      // time column: "time..." else "t"
      long tc = -1;
      for (std::size_t i = 0; i < t.names.size() && tc < 0; ++i)
        if (lower(t.names[i]).rfind("time", 0) == 0) tc = static_cast<long>(i);
      for (std::size_t i = 0; i < t.names.size() && tc < 0; ++i)
        if (lower(t.names[i]) == "t") tc = static_cast<long>(i);
      if (tc < 0)
        throw InputError(t.path, line_no,
                         "no time column in header (expected a column named 'time [ms]' or "
                         "starting with 'time'); header is: " + tl);
      t.time_column = static_cast<std::size_t>(tc);
      have_header = true;
      continue;
    }
    if (tl[0] == '#') continue;
    const auto fields = split_line(tl);
    if (fields.size() != t.headers.size())
      throw InputError(t.path, line_no,
                       "expected " + std::to_string(t.headers.size()) + " comma-separated values "
                       "(as in the header), found " + std::to_string(fields.size()));
    for (std::size_t i = 0; i < fields.size(); ++i) {
      double v = 0.0;
      if (!parse_double(fields[i], v))
        throw InputError(t.path, line_no,
                         "column " + std::to_string(i + 1) + " ('" + t.headers[i] +
                         "'): '" + fields[i] + "' is not a finite number");
      t.columns[i].push_back(v);
    }
    const auto& tcol = t.columns[t.time_column];
    if (tcol.size() >= 2 && tcol.back() < tcol[tcol.size() - 2])
      throw InputError(t.path, line_no, "time decreases (" + fields[t.time_column] + " after " +
                                            std::to_string(tcol[tcol.size() - 2]) + ")");
  }
  if (!have_header) throw InputError(t.path, 0, "no header line (file is empty)");
  if (t.n_rows() < 2) throw InputError(t.path, 0, "fewer than 2 data rows");
  return t;
}

long find_column(const TimeHistoryTable& table, std::string_view key) {
  const std::string k = trim(key);
  for (std::size_t i = 0; i < table.headers.size(); ++i)
    if (table.headers[i] == k || table.names[i] == k) return static_cast<long>(i);
  const std::string kl = lower(k);
  std::vector<std::size_t> hits;
  for (std::size_t i = 0; i < table.names.size(); ++i)
    if (lower(table.names[i]).find(kl) != std::string::npos) hits.push_back(i);
  if (hits.empty()) return -1;
  if (hits.size() > 1) {
    std::string msg = "column key '" + k + "' is ambiguous in " + table.path + "; it matches:";
    for (auto i : hits) msg += "\n  " + table.headers[i];
    throw InputError(table.path, table.header_line, msg);
  }
  return static_cast<long>(hits[0]);
}

std::string list_columns(const TimeHistoryTable& table) {
  std::string s;
  for (const auto& h : table.headers) s += "\n  " + h;
  return s;
}

}  // namespace hbm::corridors
