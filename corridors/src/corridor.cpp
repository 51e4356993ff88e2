// SPDX-License-Identifier: GPL-3.0-or-later
// Corridor loading and geometry (see corridor.hpp).
#include "hbm/corridors/corridor.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>

#include "csv_fields.hpp"
#include "hbm/corridors/input_error.hpp"
#include "hbm/corridors/test_curves.hpp"

namespace hbm::corridors {

Corridor load_corridor(const CorridorSpec& spec) {
  Corridor c;
  c.file = spec.file.string();
  c.x_unit = spec.x_unit;
  c.y_unit = spec.y_unit;
  std::ifstream in(spec.file);
  if (!in)
    throw InputError(spec.case_file, spec.case_line,
                     "corridor file '" + spec.file.string() + "' cannot be opened");
  std::string line;
  long line_no = 0;
  std::vector<std::string> header;
  long xi = -1, yi = -1, ci = -1;
  std::vector<std::pair<long, std::string>> filters;
  while (std::getline(in, line)) {
    ++line_no;
    line = csv::trim(line);
    if (line.empty()) continue;
    if (line[0] == '#') {
      if (header.empty()) c.source_lines.push_back(csv::trim(line.substr(1)));
      continue;
    }
    if (header.empty()) {
      header = csv::split_line(line);
      auto col = [&](const std::string& name, const char* what) -> long {
        for (std::size_t i = 0; i < header.size(); ++i)
          if (header[i] == name) return static_cast<long>(i);
        std::string avail;
        for (const auto& h : header) avail += " '" + h + "'";
        throw InputError(spec.case_file, spec.case_line,
                         std::string(what) + " '" + name + "' is not a column of corridor file " +
                             spec.file.string() + " (columns:" + avail + ")");
      };
      xi = col(spec.x_column, "x_column");
      yi = col(spec.y_column, "y_column");
      ci = col(spec.curve_column, "curve_column");
      for (const auto& [k, v] : spec.where) filters.emplace_back(col(k, "where key"), v);
      continue;
    }
    const auto f = csv::split_line(line);
    if (f.size() != header.size())
      throw InputError(c.file, line_no, "expected " + std::to_string(header.size()) +
                                            " values as in the header, found " + std::to_string(f.size()));
    bool keep = true;
    for (const auto& [k, v] : filters)
      if (f[static_cast<std::size_t>(k)] != v) keep = false;
    if (!keep) continue;
    const std::string& curve = f[static_cast<std::size_t>(ci)];
    Polyline* target = nullptr;
    if (curve == spec.upper_label)
      target = &c.upper;
    else if (curve == spec.lower_label)
      target = &c.lower;
    else if (!spec.mean_label.empty() && curve == spec.mean_label)
      target = &c.mean;
    if (!target) continue;
    double xv = 0.0, yv = 0.0;
    for (auto [idx, out] : {std::pair<long, double*>{xi, &xv}, std::pair<long, double*>{yi, &yv}}) {
      const std::string& s = f[static_cast<std::size_t>(idx)];
      auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), *out);
      if (ec != std::errc() || p != s.data() + s.size() || !std::isfinite(*out))
        throw InputError(c.file, line_no, "'" + s + "' in column '" + header[static_cast<std::size_t>(idx)] +
                                              "' is not a number");
    }
    target->x.push_back(xv);
    target->y.push_back(yv);
  }
  if (header.empty()) throw InputError(c.file, 0, "corridor file has no header line");
  std::string where_txt;
  for (const auto& [k, v] : spec.where) where_txt += " " + k + "=" + v;
  if (c.upper.x.size() < 2)
    throw InputError(spec.case_file, spec.case_line,
                     "corridor file " + c.file + " has fewer than 2 rows with " + spec.curve_column +
                         "='" + spec.upper_label + "'" + where_txt);
  if (c.lower.x.size() < 2)
    throw InputError(spec.case_file, spec.case_line,
                     "corridor file " + c.file + " has fewer than 2 rows with " + spec.curve_column +
                         "='" + spec.lower_label + "'" + where_txt);
  if (!spec.mean_label.empty() && c.mean.x.size() < 2)
    throw InputError(spec.case_file, spec.case_line,
                     "corridor file " + c.file + " has fewer than 2 rows with " + spec.curve_column +
                         "='" + spec.mean_label + "'" + where_txt);
  if (!spec.tests.empty()) {
    const TestCurves t = load_test_curves(spec.tests);
    c.mean = test_average(t.curves);
    if (c.mean.x.size() < 2)
      throw InputError(spec.tests.case_file, spec.tests.case_line,
                       "the test curves of " + spec.tests.file.string() + " share no abscissa range");
    std::string names;
    for (const auto& n : t.names) names += (names.empty() ? "" : ", ") + n;
    c.mean_name = "average of " + std::to_string(t.names.size()) + " tests";
    c.source_lines.push_back("Reference: the " + c.mean_name + " (" + names + ") of " +
                             spec.tests.file.filename().string() + ", over the range all of them cover:");
    for (const auto& l : t.source_lines) c.source_lines.push_back(l);
  }
  return c;
}

Polyline corridor_polygon(const Corridor& c) {
  Polyline p = c.upper;
  for (std::size_t i = c.lower.x.size(); i-- > 0;) {
    p.x.push_back(c.lower.x[i]);
    p.y.push_back(c.lower.y[i]);
  }
  return p;
}

bool point_in_polygon(const Polyline& poly, double px, double py) {
  const std::size_t n = poly.x.size();
  if (n < 3) return false;
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const double xi = poly.x[i], yi = poly.y[i], xj = poly.x[j], yj = poly.y[j];
    // on-edge test (collinear and within the segment's box)
    const double cross = (xj - xi) * (py - yi) - (yj - yi) * (px - xi);
    const double scale = std::abs(xj - xi) + std::abs(yj - yi);
    if (std::abs(cross) <= 1e-12 * scale * (std::abs(px) + std::abs(py) + scale) &&
        px >= std::min(xi, xj) && px <= std::max(xi, xj) && py >= std::min(yi, yj) &&
        py <= std::max(yi, yj))
      return true;
    if ((yi > py) != (yj > py)) {
      const double xc = xi + (py - yi) * (xj - xi) / (yj - yi);
      if (px < xc) inside = !inside;
    }
  }
  return inside;
}

double inside_fraction(const Polyline& polygon, const std::vector<double>& x,
                       const std::vector<double>& y) {
  if (x.empty()) return 0.0;
  std::size_t k = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (point_in_polygon(polygon, x[i], y[i])) ++k;
  return static_cast<double>(k) / static_cast<double>(x.size());
}

double polyline_value(const Polyline& p, double xq) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (p.x.empty() || xq < p.x.front() || xq > p.x.back()) return nan;
  double v = nan;
  for (std::size_t i = 0; i + 1 < p.x.size(); ++i) {
    const double x0 = p.x[i], x1 = p.x[i + 1];
    if (xq >= x0 && xq <= x1) {
      if (x1 > x0) v = p.y[i] + (xq - x0) / (x1 - x0) * (p.y[i + 1] - p.y[i]);
      else v = p.y[i + 1];
      if (xq < x1) return v;  // strictly inside: done; at x1 a later segment may win
    }
  }
  return v;
}

bool polygon_vertical_extent(const Polyline& poly, double xq, double& ymin, double& ymax) {
  ymin = std::numeric_limits<double>::infinity();
  ymax = -ymin;
  const std::size_t n = poly.x.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const double x0 = poly.x[j], y0 = poly.y[j], x1 = poly.x[i], y1 = poly.y[i];
    if (xq < std::min(x0, x1) || xq > std::max(x0, x1)) continue;
    if (x1 == x0) {
      ymin = std::min({ymin, y0, y1});
      ymax = std::max({ymax, y0, y1});
    } else {
      const double yv = y0 + (xq - x0) / (x1 - x0) * (y1 - y0);
      ymin = std::min(ymin, yv);
      ymax = std::max(ymax, yv);
    }
  }
  return ymin <= ymax;
}

std::vector<double> corridor_midline(const Corridor& c, const std::vector<double>& xq) {
  const Polyline poly = corridor_polygon(c);
  std::vector<double> m(xq.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < xq.size(); ++i) {
    double lo = 0.0, hi = 0.0;
    if (polygon_vertical_extent(poly, xq[i], lo, hi)) m[i] = 0.5 * (lo + hi);
  }
  return m;
}

Polyline loading_branch(const Polyline& p) {
  Polyline out;
  if (p.x.empty()) return out;
  std::size_t imax = 0;
  for (std::size_t i = 1; i < p.x.size(); ++i)
    if (p.x[i] > p.x[imax]) imax = i;
  for (std::size_t i = 0; i <= imax; ++i) {
    if (out.x.empty() || p.x[i] > out.x.back()) {
      out.x.push_back(p.x[i]);
      out.y.push_back(p.y[i]);
    }
  }
  return out;
}

void scale_corridor(Corridor& c, double xf, double yf) {
  for (Polyline* p : {&c.upper, &c.lower, &c.mean}) {
    for (double& v : p->x) v *= xf;
    for (double& v : p->y) v *= yf;
  }
}

}  // namespace hbm::corridors
