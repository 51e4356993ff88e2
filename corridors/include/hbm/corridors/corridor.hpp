// SPDX-License-Identifier: GPL-3.0-or-later
// Published corridors: loading a corridor from a CSV file of corridors/data (header lines
// starting with '#' name the source and are kept for the report), its upper and lower
// bounds and optional test mean as polylines, the closed corridor polygon (upper bound
// followed by the reversed lower bound) and the inside-corridor fraction of a model curve.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace hbm::corridors {

struct Polyline {
  std::vector<double> x, y;
  bool empty() const { return x.empty(); }
};

/// Which columns of a wide CSV hold individual tests: one (x column, y column) pair per test
/// (test_curves.hpp). Their average is then the corridor's mean.
struct TestCurvesSpec {
  std::filesystem::path file;                               ///< resolved path; empty: none
  std::vector<std::pair<std::string, std::string>> curves;  ///< (x column, y column) per test
  std::string case_file;                                    ///< for error messages
  long case_line = 0;
  bool empty() const { return file.empty(); }
};

/// Which rows and columns of a corridor CSV make up one corridor (from the case file).
struct CorridorSpec {
  std::filesystem::path file;            ///< resolved path of the corridor CSV
  std::string curve_column = "curve";    ///< column naming the curve of each row
  std::string x_column, y_column;        ///< abscissa and ordinate columns
  std::string upper_label = "upper", lower_label = "lower", mean_label;  ///< mean optional
  TestCurvesSpec tests;  ///< optional: the mean is the average of these tests (same units)
  std::map<std::string, std::string> where;  ///< extra row filters: column = value
  std::string x_unit, y_unit;            ///< units of the numbers in the file
  std::string case_file;                 ///< for error messages
  long case_line = 0;
};

struct Corridor {
  std::string file;
  std::vector<std::string> source_lines;  ///< the '#' header lines, without '#'
  Polyline upper, lower, mean;            ///< mean empty when the file has none
  std::string mean_name = "test mean";    ///< what the mean is, for plots and reports
  std::string x_unit, y_unit;
  bool has_mean() const { return !mean.empty(); }
};

/// Loads the corridor; throws InputError (case file:line when the spec is wrong, corridor
/// file:line when the data are malformed).
Corridor load_corridor(const CorridorSpec& spec);

/// Closed polygon: upper bound in file order, then the lower bound reversed.
Polyline corridor_polygon(const Corridor& c);

/// Even-odd point-in-polygon test (points on an edge count as inside).
bool point_in_polygon(const Polyline& polygon, double px, double py);

/// Fraction of the points (x[i], y[i]) inside the polygon; 0 for no points.
double inside_fraction(const Polyline& polygon, const std::vector<double>& x,
                       const std::vector<double>& y);

/// Value of a polyline with non-decreasing x at xq (linear; at a repeated x the later point
/// wins); NaN outside [x.front(), x.back()].
double polyline_value(const Polyline& p, double xq);

/// Lowest and highest y where the vertical line x = xq cuts the polygon; false when it
/// misses the polygon.
bool polygon_vertical_extent(const Polyline& polygon, double xq, double& ymin, double& ymax);

/// Mid-line of the corridor polygon on the grid xq: the middle of the polygon's vertical
/// extent at each x (so a lower bound that starts later or ends earlier than the upper one
/// is closed by the polygon edge); NaN outside the polygon's x range.
std::vector<double> corridor_midline(const Corridor& c, const std::vector<double>& xq);

/// Loading branch of a curve given in traversal order: the points up to the largest x,
/// keeping only points whose x exceeds every earlier x (so x is strictly increasing).
Polyline loading_branch(const Polyline& p);

/// Multiplies x and y of every curve (unit conversion).
void scale_corridor(Corridor& c, double x_factor, double y_factor);

}  // namespace hbm::corridors
