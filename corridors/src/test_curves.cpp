// SPDX-License-Identifier: GPL-3.0-or-later
// Individual test curves and their average (see test_curves.hpp).
#include "hbm/corridors/test_curves.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>

#include "csv_fields.hpp"
#include "hbm/corridors/input_error.hpp"

namespace hbm::corridors {
namespace {

using csv::trim;

// Linear value of a curve with strictly increasing x, xq inside its range.
double value_at(const Polyline& p, double xq) {
  const auto it = std::upper_bound(p.x.begin(), p.x.end(), xq);
  if (it == p.x.begin()) return p.y.front();
  if (it == p.x.end()) return p.y.back();
  const std::size_t i = static_cast<std::size_t>(it - p.x.begin());
  const double x0 = p.x[i - 1], x1 = p.x[i];
  return p.y[i - 1] + (xq - x0) / (x1 - x0) * (p.y[i] - p.y[i - 1]);
}

}  // namespace

TestCurves load_test_curves(const TestCurvesSpec& spec) {
  const std::string file = spec.file.string();
  std::ifstream in(spec.file);
  if (!in) throw InputError(spec.case_file, spec.case_line, "test curves file '" + file + "' cannot be opened");
  if (spec.curves.empty())
    throw InputError(spec.case_file, spec.case_line, "no test curves listed for " + file);
  TestCurves t;
  std::vector<std::string> header;
  std::vector<std::pair<std::size_t, std::size_t>> cols;
  t.curves.resize(spec.curves.size());
  std::string line;
  long line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    line = trim(line);
    if (line.empty()) continue;
    if (line[0] == '#') {
      if (header.empty()) t.source_lines.push_back(trim(line.substr(1)));
      continue;
    }
    if (header.empty()) {
      header = csv::split_line(line);
      auto col = [&](const std::string& name) -> std::size_t {
        for (std::size_t i = 0; i < header.size(); ++i)
          if (header[i] == name) return i;
        std::string avail;
        for (const auto& h : header) avail += " '" + h + "'";
        throw InputError(spec.case_file, spec.case_line,
                         "test column '" + name + "' is not a column of " + file + " (columns:" + avail + ")");
      };
      for (const auto& [xc, yc] : spec.curves) {
        cols.emplace_back(col(xc), col(yc));
        t.names.push_back(yc);
      }
      continue;
    }
    const auto f = csv::split_line(line);
    if (f.size() > header.size())
      throw InputError(file, line_no, "more values (" + std::to_string(f.size()) + ") than header columns (" +
                                          std::to_string(header.size()) + ")");
    auto cell = [&](std::size_t i) -> std::string { return i < f.size() ? f[i] : std::string(); };
    for (std::size_t k = 0; k < cols.size(); ++k) {
      const std::string xs = cell(cols[k].first), ys = cell(cols[k].second);
      if (xs.empty() && ys.empty()) continue;  // past this test's end
      if (xs.empty() || ys.empty())
        throw InputError(file, line_no, "test '" + t.names[k] + "': a value in '" +
                                            (xs.empty() ? spec.curves[k].second : spec.curves[k].first) +
                                            "' without its partner in '" +
                                            (xs.empty() ? spec.curves[k].first : spec.curves[k].second) + "'");
      double v[2] = {0.0, 0.0};
      const std::string* s[2] = {&xs, &ys};
      for (int j = 0; j < 2; ++j) {
        auto [p, ec] = std::from_chars(s[j]->data(), s[j]->data() + s[j]->size(), v[j]);
        if (ec != std::errc() || p != s[j]->data() + s[j]->size() || !std::isfinite(v[j]))
          throw InputError(file, line_no, "'" + *s[j] + "' in column '" +
                                              (j == 0 ? spec.curves[k].first : spec.curves[k].second) +
                                              "' is not a number");
      }
      Polyline& c = t.curves[k];
      if (!c.x.empty() && !(v[0] > c.x.back()))
        throw InputError(file, line_no, "test '" + t.names[k] + "': abscissa " + *s[0] +
                                            " does not increase (the row before has " +
                                            std::to_string(c.x.back()) + ")");
      c.x.push_back(v[0]);
      c.y.push_back(v[1]);
    }
  }
  if (header.empty()) throw InputError(file, 0, "test curves file has no header line");
  for (std::size_t k = 0; k < t.curves.size(); ++k)
    if (t.curves[k].x.size() < 2)
      throw InputError(file, 0, "test '" + t.names[k] + "' has fewer than 2 points");
  return t;
}

Polyline test_average(const std::vector<Polyline>& curves) {
  Polyline avg;
  if (curves.empty()) return avg;
  double a = -INFINITY, b = INFINITY;
  for (const auto& c : curves) {
    if (c.x.size() < 2) return avg;
    a = std::max(a, c.x.front());
    b = std::min(b, c.x.back());
  }
  if (!(b > a)) return avg;
  std::vector<double> xs{a, b};
  for (const auto& c : curves)
    for (double x : c.x)
      if (x > a && x < b) xs.push_back(x);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  const double n = static_cast<double>(curves.size());
  for (double x : xs) {
    double s = 0.0;
    for (const auto& c : curves) s += value_at(c, x);
    avg.x.push_back(x);
    avg.y.push_back(s / n);
  }
  return avg;
}

}  // namespace hbm::corridors
