// SPDX-License-Identifier: GPL-3.0-or-later
// Individual test curves and their average as a rating's reference (test_curves.hpp): the
// average of piecewise-linear curves is exact at the union of their abscissae and covers only
// the range every test covers; the wide CSV reader takes tests of unequal length and names
// file and line for bad cells; case files pair tests_file with tests and refuse a mean beside
// them; the shipped Viano tests load with their source lines.
#include <gtest/gtest.h>

#include <filesystem>

#include "hbm/corridors/case_definition.hpp"
#include "hbm/corridors/corridor.hpp"
#include "hbm/corridors/input_error.hpp"
#include "corridors_test_support.hpp"
#include "hbm/corridors/test_curves.hpp"

namespace fs = std::filesystem;
using namespace hbm::corridors;

namespace {

using test_support::data_dir;
using test_support::error_of;
using test_support::temp_file;

Polyline line(std::vector<double> x, double slope, double offset) {
  Polyline p;
  p.x = std::move(x);
  for (double v : p.x) p.y.push_back(slope * v + offset);
  return p;
}

}  // namespace

TEST(TestAverage, MeanOfLinesIsTheLineOfMeansOverTheCommonRange) {
  // y = x on [0, 10] and y = 2x + 1 on [1, 12]: the mean is 1.5 x + 0.5 on [1, 10] only
  const Polyline a = line({0, 5, 10}, 1.0, 0.0), b = line({1, 4, 12}, 2.0, 1.0);
  const Polyline m = test_average({a, b});
  ASSERT_EQ(m.x, (std::vector<double>{1, 4, 5, 10}));  // the range ends and the union inside
  for (std::size_t i = 0; i < m.x.size(); ++i) EXPECT_NEAR(m.y[i], 1.5 * m.x[i] + 0.5, 1e-12);
}

TEST(TestAverage, KinkedCurvesAverageExactlyAtEveryBreakpoint) {
  // a tent (0,0)-(2,4)-(4,0) and a ramp (0,0)-(4,8): at x = 2 the mean is (4 + 4)/2, at x = 1
  // (no breakpoint of either) the linear pieces give (2 + 2)/2 = 2 by interpolating the mean
  Polyline tent{{0, 2, 4}, {0, 4, 0}}, ramp{{0, 4}, {0, 8}};
  const Polyline m = test_average({tent, ramp});
  ASSERT_EQ(m.x, (std::vector<double>{0, 2, 4}));
  EXPECT_NEAR(m.y[1], 4.0, 1e-12);
  EXPECT_NEAR(m.y[2], 4.0, 1e-12);  // (0 + 8) / 2
  EXPECT_NEAR(polyline_value(m, 1.0), 2.0, 1e-12);
}

TEST(TestAverage, DisjointTestsHaveNoAverage) {
  EXPECT_TRUE(test_average({line({0, 1}, 1, 0), line({2, 3}, 1, 0)}).empty());
  EXPECT_TRUE(test_average({}).empty());
}

TEST(TestCurves, WideColumnsOfUnequalLength) {
  const auto p = temp_file("tests.csv",
                           "# Source: constructed\n"
                           "A_t,A_f,B_t,B_f\n"
                           "0,0,0,0\n"
                           "1,2,2,2\n"
                           "3,2,,\n"  // B has ended
                           "4,0\n");  // trailing cells left out
  TestCurvesSpec s;
  s.file = p;
  s.curves = {{"A_t", "A_f"}, {"B_t", "B_f"}};
  const TestCurves t = load_test_curves(s);
  ASSERT_EQ(t.curves.size(), 2u);
  EXPECT_EQ(t.curves[0].x, (std::vector<double>{0, 1, 3, 4}));
  EXPECT_EQ(t.curves[1].x, (std::vector<double>{0, 2}));
  EXPECT_EQ(t.source_lines, (std::vector<std::string>{"Source: constructed"}));
  const Polyline m = test_average(t.curves);
  EXPECT_EQ(m.x.back(), 2.0);             // where B ends
  EXPECT_NEAR(m.y.back(), 2.0, 1e-12);    // A(2) = 2, B(2) = 2
  EXPECT_NEAR(m.y[1], (2.0 + 1.0) / 2, 1e-12);  // x = 1: A 2, B 1
}

TEST(TestCurves, BadCellsNameFileAndLine) {
  struct Bad {
    std::string rows;
    int line;
    std::string words;
  };
  const std::vector<Bad> bad{
      {"0,0\n1,x\n", 4, "'x' in column 'A_f' is not a number"},
      {"0,0\n1,\n", 4, "without its partner"},
      {"0,0\n1,1\n1,2\n", 5, "does not increase"},
      {"0,0\n1,1,7\n", 4, "more values"},
  };
  for (const auto& b : bad) {
    const auto p = temp_file("bad_tests.csv", "# src\nA_t,A_f\n" + b.rows);
    TestCurvesSpec s;
    s.file = p;
    s.curves = {{"A_t", "A_f"}};
    const std::string msg = error_of([&] { load_test_curves(s); });
    SCOPED_TRACE(msg);
    EXPECT_NE(msg.find("bad_tests.csv:" + std::to_string(b.line) + ":"), std::string::npos);
    EXPECT_NE(msg.find(b.words), std::string::npos);
  }
  TestCurvesSpec s;
  s.file = temp_file("short_tests.csv", "A_t,A_f\n0,0\n");
  s.curves = {{"A_t", "A_f"}};
  EXPECT_NE(error_of([&] { load_test_curves(s); }).find("fewer than 2 points"), std::string::npos);
  s.curves = {{"A_t", "A_g"}};
  s.case_file = "case.toml";
  s.case_line = 12;
  const std::string msg = error_of([&] { load_test_curves(s); });
  EXPECT_NE(msg.find("case.toml:12:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'A_g' is not a column"), std::string::npos) << msg;
}

TEST(TestCurves, CaseFileKeysGoTogether) {
  temp_file("corr.csv", "curve,x,y\nupper,0,1\nupper,1,1\nlower,0,0\nlower,1,0\nmean,0,0.5\nmean,1,0.5\n");
  temp_file("t.csv", "A_t,A_f\n0,0\n1,1\n");
  const std::string head =
      "[case]\nname = \"t\"\n\n[[signal]]\nname = \"f\"\ncolumn = \"impactor AX\"\n\n"
      "[[rating]]\nname = \"r\"\nkind = \"time\"\nsignal = \"f\"\n[rating.corridor]\n"
      "file = \"corr.csv\"\nx_column = \"x\"\ny_column = \"y\"\nx_unit = \"ms\"\ny_unit = \"kN\"\n";  // lines 1-17
  test_support::expect_case_errors(head, {
      {"tests_file = \"t.csv\"\n", 18, "go together"},
      {"tests = [[\"A_t\", \"A_f\"]]\n", 18, "go together"},
      {"mean = \"mean\"\ntests_file = \"t.csv\"\ntests = [[\"A_t\", \"A_f\"]]\n", 19, "not both"},
      {"tests_file = \"t.csv\"\ntests = [\"A_t\", \"A_f\"]\n", 19, "pairs"},
      {"tests_file = \"none.csv\"\ntests = [[\"A_t\", \"A_f\"]]\n", 18, "not found"},
  });
  const auto good = temp_file("good.toml", head + "tests_file = \"t.csv\"\ntests = [[\"A_t\", \"A_f\"]]\n");
  const auto cd = load_case(good);
  const Corridor c = load_corridor(cd.ratings.at(0).corridor);
  EXPECT_EQ(c.mean_name, "average of 1 tests");
  EXPECT_EQ(c.mean.x, (std::vector<double>{0, 1}));
}

TEST(TestCurves, ShippedVianoCasesAverageTheirTests) {
  // corridors/cases: force-time ratings of the Viano cases use the individual tests of the
  // SAFER catalogue (copied byte for byte into corridors/data); each average starts at 0 ms
  // (first contact) and ends where the shortest test ends, inside every test's range.
  struct Expect {
    std::string file;
    std::size_t n;
  };
  const std::vector<Expect> expect{{"viano1989_thorax_oblique_4p4.toml", 4},
                                   {"viano1989_thorax_oblique_6p5.toml", 3},
                                   {"viano1989_thorax_oblique_9p5.toml", 5},
                                   {"viano1989_pelvis_lateral_5p2.toml", 4}};
  for (const auto& e : expect) {
    SCOPED_TRACE(e.file);
    const auto cd = load_case(std::string(HBM_CORRIDORS_SOURCE_DIR) + "/cases/" + e.file);
    const RatingDef& r = cd.ratings.at(0);
    ASSERT_EQ(r.kind, "time");
    ASSERT_EQ(r.corridor.tests.curves.size(), e.n);
    const TestCurves t = load_test_curves(r.corridor.tests);
    const Corridor c = load_corridor(r.corridor);
    EXPECT_EQ(c.mean_name, "average of " + std::to_string(e.n) + " tests");
    double end = 1e300;
    for (const auto& tc : t.curves) {
      EXPECT_LE(tc.x.front(), c.mean.x.front());
      end = std::min(end, tc.x.back());
    }
    EXPECT_EQ(c.mean.x.back(), end);
    EXPECT_NEAR(c.mean.x.front(), 0.0, 0.11);  // the pelvis tests start 0.05-0.1 ms early
    EXPECT_NE(t.source_lines.at(0).find("SAFER"), std::string::npos);
    // the corridor's source lines name the tests after its own
    bool named = false;
    for (const auto& l : c.source_lines) named = named || l.find("Reference: the average of") == 0;
    EXPECT_TRUE(named);
  }
}
