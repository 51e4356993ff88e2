// SPDX-License-Identifier: GPL-3.0-or-later
// Fields of one CSV line, shared by the readers of time histories, corridors and test
// curves (internal to hbm_corridors).
#pragma once

#include <cctype>
#include <string>
#include <string_view>
#include <vector>

namespace hbm::corridors::csv {

/// The text without leading and trailing white space.
inline std::string trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return std::string(s.substr(b, e - b));
}

/// Splits on commas, honouring double quotes (a quoted field may contain commas); each
/// field trimmed. An empty line is one empty field.
inline std::vector<std::string> split_line(std::string_view line) {
  std::vector<std::string> fields;
  std::string cur;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.push_back(trim(cur));
      cur.clear();
    } else {
      cur.push_back(c);
    }
  }
  fields.push_back(trim(cur));
  return fields;
}

}  // namespace hbm::corridors::csv
