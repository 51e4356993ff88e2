// SPDX-License-Identifier: GPL-3.0-or-later
// Readers and checks: time-history CSV headers and column lookup, errors with file:line,
// unit conversion, case-file errors pointing at the offending line, corridor loading from
// corridors/data (source lines kept), the corridor polygon, mid-line and inside fraction.
#include <gtest/gtest.h>

#include <filesystem>

#include "hbm/corridors/case_definition.hpp"
#include "hbm/corridors/corridor.hpp"
#include "hbm/corridors/cross_plot.hpp"
#include "hbm/corridors/input_error.hpp"
#include "corridors_test_support.hpp"
#include "hbm/corridors/time_history_csv.hpp"
#include "hbm/corridors/units.hpp"

namespace fs = std::filesystem;
using namespace hbm::corridors;

namespace {

using test_support::data_dir;
using test_support::error_of;
using test_support::temp_file;

}  // namespace

TEST(TimeHistoryCsv, ReadsHeadersUnitsAndColumns) {
  const auto p = temp_file("th.csv",
                           "# comment\ntime [ms],node 1201 sternum DX [mm],part 3 ribs IE [J],no unit\n"
                           "0,0,0,1\n0.1,-0.5,0.25,2\n0.2,-1.0,1.0,3\n");
  const auto t = read_time_history_csv(p);
  EXPECT_EQ(t.headers.size(), 4u);
  EXPECT_EQ(t.names[1], "node 1201 sternum DX");
  EXPECT_EQ(t.units[1], "mm");
  EXPECT_EQ(t.units[3], "");
  EXPECT_EQ(t.time_column, 0u);
  EXPECT_EQ(t.n_rows(), 3u);
  EXPECT_EQ(find_column(t, "node 1201 sternum DX [mm]"), 1);  // exact header
  EXPECT_EQ(find_column(t, "part 3 ribs IE"), 2);             // exact name
  EXPECT_EQ(find_column(t, "sternum dx"), 1);                 // unique substring, any case
  EXPECT_EQ(find_column(t, "femur"), -1);
  EXPECT_THROW(find_column(t, "r"), InputError);  // ambiguous
}

TEST(TimeHistoryCsv, ErrorsNameFileAndLine) {
  auto p = temp_file("bad1.csv", "time [ms],a [mm]\n0,1\n0.1,x\n");
  EXPECT_NE(error_of([&] { read_time_history_csv(p); }).find("bad1.csv:3: error:"), std::string::npos);
  p = temp_file("bad2.csv", "time [ms],a [mm]\n0,1\n0.1,2,3\n");
  EXPECT_NE(error_of([&] { read_time_history_csv(p); }).find("bad2.csv:3: error:"), std::string::npos);
  p = temp_file("bad3.csv", "x [ms],a [mm]\n0,1\n0.1,2\n");
  EXPECT_NE(error_of([&] { read_time_history_csv(p); }).find("no time column"), std::string::npos);
  p = temp_file("bad4.csv", "time [ms],a [mm]\n0,1\n0.2,2\n0.1,3\n");
  EXPECT_NE(error_of([&] { read_time_history_csv(p); }).find("bad4.csv:4: error: time decreases"), std::string::npos);
}

TEST(Units, ConversionFactors) {
  EXPECT_DOUBLE_EQ(unit_conversion_factor("mm/ms2", "m/s2"), 1000.0);
  EXPECT_DOUBLE_EQ(unit_conversion_factor("kN", "N"), 1000.0);
  EXPECT_DOUBLE_EQ(unit_conversion_factor("kN*mm", "N*m"), 1.0);
  EXPECT_DOUBLE_EQ(unit_conversion_factor("mm/ms", "m/s"), 1.0);
  EXPECT_NEAR(unit_conversion_factor("m/s2", "g"), 1.0 / 9.80665, 1e-15);
  EXPECT_DOUBLE_EQ(unit_conversion_factor("cm", "mm"), 10.0);
  EXPECT_THROW(unit_conversion_factor("mm", "kN"), std::invalid_argument);
  EXPECT_THROW(unit_conversion_factor("furlong", "mm"), std::invalid_argument);
}

TEST(CaseDefinition, ShippedCasesLoad) {
  for (const auto& e : fs::directory_iterator(std::string(HBM_CORRIDORS_SOURCE_DIR) + "/cases")) {
    if (e.path().extension() != ".toml") continue;
    SCOPED_TRACE(e.path().string());
    const auto cd = load_case(e.path());
    EXPECT_FALSE(cd.ratings.empty());
    for (const auto& r : cd.ratings) EXPECT_NO_THROW(load_corridor(r.corridor));
  }
}

TEST(CaseDefinition, ErrorsPointAtTheLine) {
  const std::string head =
      "[case]\nname = \"t\"\n\n[[signal]]\nname = \"f\"\ncolumn = \"impactor AX\"\n";  // lines 1-6
  test_support::expect_case_errors(head, {
      {"cfc = 123\n", 7, "not an SAE J211 channel class"},
      {"colour = 1\n", 7, "unknown key 'colour'"},
      {"unit = \"furlong\"\n", 7, "unknown unit"},
      {"scale = \"two\"\n", 7, "must be a number"},
      {"cfc = \n", 7, ""},  // TOML syntax error
      {"\n[[criterion]]\nkind = \"hic\"\nsignal = \"g\"\n", 8, "undefined signal 'g'"},
      {"\n[[rating]]\nname = \"r\"\nkind = \"cross\"\nsignal = \"f\"\n", 8, "needs x_signal"},
  });
}

TEST(Corridor, LebarbeLoadsWithSourceLines) {
  CorridorSpec s;
  s.file = data_dir + "lebarbe2012_frontal_hub_6p7ms_force_deflection.csv";
  s.x_column = "deflection_mm";
  s.y_column = "force_N";
  s.upper_label = "upper_max";
  s.lower_label = "lower_min";
  s.mean_label = "mean";
  const auto c = load_corridor(s);
  EXPECT_EQ(c.mean.x.size(), 58u);   // rows 'mean' in the file
  EXPECT_EQ(c.upper.x.size(), 84u);  // rows 'upper_max'
  EXPECT_EQ(c.lower.x.size(), 60u);  // rows 'lower_min'
  ASSERT_FALSE(c.source_lines.empty());
  EXPECT_NE(c.source_lines[0].find("Lebarbe"), std::string::npos);
  // loading branch of the mean ends at the largest deflection, x strictly increasing
  const auto lb = loading_branch(c.mean);
  EXPECT_DOUBLE_EQ(lb.x.back(), 84.722);
  for (std::size_t i = 1; i < lb.x.size(); ++i) EXPECT_GT(lb.x[i], lb.x[i - 1]);
  // the mean lies inside its own corridor almost everywhere
  EXPECT_GT(inside_fraction(corridor_polygon(c), c.mean.x, c.mean.y), 0.9);
}

TEST(Corridor, VianoRowsSelectedByWhere) {
  CorridorSpec s;
  s.file = data_dir + "viano1989_pelvis_lateral_pendulum_5p2ms_force_time.csv";
  s.curve_column = "bound";
  s.x_column = "x";
  s.y_column = "y_kN";
  s.where = {{"impact", "pelvis"}, {"quantity", "force_vs_time"}};
  const auto c = load_corridor(s);
  EXPECT_EQ(c.upper.x.size(), 5u);
  EXPECT_EQ(c.lower.x.size(), 5u);
  // at 10 ms the polygon spans 5 kN (lower) to 8 kN (upper): mid-line 6.5 kN
  EXPECT_NEAR(corridor_midline(c, {10.0})[0], 6.5, 1e-12);
  // at 1 ms the lower bound has not started: the polygon's closing edge (0,0)-(2.5,0) bounds it
  EXPECT_NEAR(corridor_midline(c, {1.0})[0], 0.5 * (8.0 / 9.0), 1e-12);
  s.where["impact"] = "thorax";
  EXPECT_THROW(load_corridor(s), InputError);  // no rows match
}

TEST(Corridor, PolygonInsideFraction) {
  Corridor c;
  c.upper = {{0.0, 1.0}, {1.0, 1.0}};
  c.lower = {{0.0, 1.0}, {0.0, 0.0}};
  const auto poly = corridor_polygon(c);  // unit square
  EXPECT_TRUE(point_in_polygon(poly, 0.5, 0.5));
  EXPECT_TRUE(point_in_polygon(poly, 1.0, 0.5));  // on the edge
  EXPECT_FALSE(point_in_polygon(poly, 1.5, 0.5));
  EXPECT_DOUBLE_EQ(inside_fraction(poly, {0.5, 0.2, 2.0, -1.0}, {0.5, 0.9, 0.5, 0.5}), 0.5);
}

TEST(CrossPlot, LoadingParameterisationOfIdenticalCurvesIsIdentical) {
  Polyline ref{{0.0, 10.0, 20.0, 30.0, 25.0}, {0.0, 3.0, 3.5, 4.0, 1.0}};
  const auto pc = parameterise_loading(ref, ref, 101);
  EXPECT_DOUBLE_EQ(pc.abscissa.back(), 30.0);
  for (std::size_t i = 0; i < pc.reference.size(); ++i) EXPECT_DOUBLE_EQ(pc.model[i], pc.reference[i]);
  // a model that stops at 15 mm counts 0 force beyond
  Polyline short_model{{0.0, 10.0, 15.0, 12.0}, {0.0, 3.0, 3.2, 0.5}};
  const auto ps = parameterise_loading(ref, short_model, 101);
  EXPECT_DOUBLE_EQ(ps.model_reach, 15.0);
  EXPECT_DOUBLE_EQ(ps.model.back(), 0.0);
  const auto pa = parameterise_arc_length(ref, ref, 51);
  for (std::size_t i = 0; i < pa.reference.size(); ++i) EXPECT_DOUBLE_EQ(pa.model[i], pa.reference[i]);
}
