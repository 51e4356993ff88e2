// SPDX-License-Identifier: GPL-3.0-or-later
// Field-level text handling shared by the reader and the writer: trimming, integer and
// real parsing (Fortran exponents 1.5E-3, 1.5D-3 and the Radioss form 1.5-3), and the
// shortest fixed-width formatting of reals that still reads back to the same double.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace hbm::deck::text {

enum class NumberStatus : std::uint8_t { Ok, NotNumber, NotInteger, OutOfRange, NotFinite };

inline std::string_view trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
  return s.substr(b, e - b);
}

// `s` is trimmed and non-empty.
NumberStatus parse_int(std::string_view s, std::int64_t& out);
NumberStatus parse_real(std::string_view s, double& out);
std::string_view describe(NumberStatus st);

// Shortest decimal text of `v` that reads back exactly, if it fits in `width`
// columns; otherwise the most precise scientific form that fits.
std::string format_real(double v, int width);
// Shortest text of a value for messages ("-1", "0.3", "2.1e+05").
std::string format_number(double v);

}  // namespace hbm::deck::text
