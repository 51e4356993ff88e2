// SPDX-License-Identifier: GPL-3.0-or-later
// Individual test curves (one PMHS run per pair of columns of a wide CSV, as the SAFER HBM
// validation catalogue stores them) and their average, the reference curve of a rating when
// the publication gives corridors but no mean. ISO/TS 18571 compares a model signal with a
// reference signal; the average of the tests is that signal, a corridor's mid-line only
// stands in for it.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "hbm/corridors/corridor.hpp"

namespace hbm::corridors {

struct TestCurves {
  std::vector<std::string> source_lines;  ///< the file's '#' header lines, without '#'
  std::vector<std::string> names;         ///< y column of each test
  std::vector<Polyline> curves;           ///< x strictly increasing in each
};

/// Reads the tests (TestCurvesSpec in corridor.hpp; rows where both cells of a pair are
/// empty are past that test's end); throws InputError naming the file and line for a malformed cell, a cell
/// without its partner, a non-increasing abscissa or a test with fewer than two points, and
/// the case file and line for a column that is not in the file.
TestCurves load_test_curves(const TestCurvesSpec& spec);

/// Pointwise mean of the curves over the abscissa range every curve covers (from the latest
/// start to the earliest end), at the union of their abscissae there: the exact mean of the
/// piecewise-linear curves. Empty when the curves share no range.
Polyline test_average(const std::vector<Polyline>& curves);

}  // namespace hbm::corridors
