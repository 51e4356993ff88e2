// SPDX-License-Identifier: GPL-3.0-or-later
// Number parsing and formatting for deck fields (see text_fields.hpp). Parsing uses
// std::from_chars: no allocation, no locale, exact round trip with std::to_chars.
#include "text_fields.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <system_error>

namespace hbm::deck::text {

NumberStatus parse_int(std::string_view s, std::int64_t& out) {
  const char* b = s.data();
  const char* e = b + s.size();
  if (b < e && *b == '+') ++b;
  if (b == e) return NumberStatus::NotNumber;
  auto [p, ec] = std::from_chars(b, e, out);
  if (ec == std::errc::result_out_of_range) return NumberStatus::OutOfRange;
  if (ec == std::errc() && p == e) return NumberStatus::Ok;
  double d = 0;
  if (parse_real(s, d) == NumberStatus::Ok) return NumberStatus::NotInteger;
  return NumberStatus::NotNumber;
}

NumberStatus parse_real(std::string_view s, double& out) {
  // Copy into a small buffer, mapping Fortran D exponents to E and inserting the E of
  // the Radioss short form "1.5-3" (mantissa directly followed by a signed exponent).
  char buf[48];
  if (s.empty() || s.size() > 40) return NumberStatus::NotNumber;
  std::size_t n = 0;
  std::size_t i = 0;
  if (s[0] == '+') i = 1;
  bool seen_digit = false, seen_exp = false;
  for (; i < s.size(); ++i) {
    char c = s[i];
    if (c >= '0' && c <= '9') {
      seen_digit = true;
    } else if (c == 'D' || c == 'd' || c == 'E' || c == 'e') {
      if (!seen_digit || seen_exp) return NumberStatus::NotNumber;
      c = 'e';
      seen_exp = true;
    } else if (c == '+' || c == '-') {
      const bool at_start = (n == 0);
      const bool after_exp = n > 0 && buf[n - 1] == 'e';
      if (!at_start && !after_exp) {
        if (!seen_digit || seen_exp) return NumberStatus::NotNumber;
        buf[n++] = 'e';  // Radioss form 1.5-3
        seen_exp = true;
      }
    } else if (c != '.') {
      return NumberStatus::NotNumber;  // letters (nan, inf), blanks inside, anything else
    }
    buf[n++] = c;
  }
  if (!seen_digit) return NumberStatus::NotNumber;
  auto [p, ec] = std::from_chars(buf, buf + n, out);
  if (ec == std::errc::result_out_of_range) return NumberStatus::OutOfRange;
  if (ec != std::errc() || p != buf + n) return NumberStatus::NotNumber;
  if (!std::isfinite(out)) return NumberStatus::NotFinite;
  return NumberStatus::Ok;
}

std::string_view describe(NumberStatus st) {
  switch (st) {
    case NumberStatus::Ok: return "ok";
    case NumberStatus::NotNumber: return "not a number";
    case NumberStatus::NotInteger: return "integer expected";
    case NumberStatus::OutOfRange: return "number out of the representable range";
    case NumberStatus::NotFinite: return "not a finite number";
  }
  return "?";
}

std::string format_real(double v, int width) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  std::size_t len = static_cast<std::size_t>(r.ptr - buf);
  if (static_cast<int>(len) <= width) return std::string(buf, len);
  // Too long: round to fewer significant digits, then write the shortest text of the
  // rounded value. Writing the value read back from that text gives the same text.
  for (int prec = 16; prec >= 0; --prec) {
    r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific, prec);
    double rounded = 0;
    std::from_chars(buf, r.ptr, rounded);
    r = std::to_chars(buf, buf + sizeof buf, rounded);
    len = static_cast<std::size_t>(r.ptr - buf);
    if (static_cast<int>(len) <= width) return std::string(buf, len);
  }
  return std::string(buf, len);  // cannot fit; the caller reports it
}

std::string format_number(double v) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, static_cast<std::size_t>(r.ptr - buf));
}

}  // namespace hbm::deck::text
