// SPDX-License-Identifier: GPL-3.0-or-later
// The whole evaluation pipeline (CSV reading, unit conversion, combinations, time zero,
// ratings, criteria) on a constructed run whose results a formula fixes:
//  - head acceleration, written in mm/ms2 as the solver does, a half-sine of 80 g over
//    10 ms: HIC15/HIC36 and a3ms equal their closed forms (see corridors_criteria_test);
//  - upper-neck Fz in kN reaching the tension intercept 6806 N with My = 0: Nij = 1;
//  - belt force and a part's failed-element count: their peaks;
//  - an impactor force equal to the Viano (1989) pelvis corridor mid-line, 5 ms after the
//    start of the record (time zero given as 5 ms): ISO/TS 18571 R = 1 to interpolation
//    error and 100 % inside the corridor.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <unistd.h>

#include "hbm/corridors/case_definition.hpp"
#include "hbm/corridors/corridor.hpp"
#include "hbm/corridors/evaluation.hpp"
#include "hbm/corridors/input_error.hpp"
#include "hbm/corridors/units.hpp"

namespace fs = std::filesystem;
using namespace hbm::corridors;

namespace {

constexpr double pi = std::numbers::pi;

double hic_half_sine(double a_g, double t_s, double window_s) {
  double lo = 0.9, hi = 1.3;  // tan u = 5u/3
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::tan(mid) - 5.0 * mid / 3.0 > 0.0 ? hi : lo) = mid;
  }
  double u = 0.5 * (lo + hi), w = 2.0 * t_s * u / pi;
  if (w > window_s) {
    w = window_s;
    u = pi * w / (2.0 * t_s);
  }
  return std::pow(2.0 * a_g * t_s / pi, 2.5) * std::pow(std::sin(u), 2.5) / std::pow(w, 1.5);
}

}  // namespace

TEST(Evaluation, CriteriaAndTimeRatingThroughThePipeline) {
  const fs::path dir = fs::temp_directory_path() / ("hbm_corridors_eval_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "run");
  const double amp_g = 80.0, dur_ms = 10.0, start_ms = 5.0, t0_ms = 5.0;
  const double g_in_mm_ms2 = standard_gravity / 1000.0;

  CorridorSpec spec;
  spec.file = std::string(HBM_CORRIDORS_SOURCE_DIR) + "/data/viano1989_pelvis_lateral_pendulum_5p2ms_force_time.csv";
  spec.curve_column = "bound";
  spec.x_column = "x";
  spec.y_column = "y_kN";
  spec.where = {{"impact", "pelvis"}, {"quantity", "force_vs_time"}};
  const Corridor pelvis = load_corridor(spec);

  std::ofstream head(dir / "run" / "head.csv"), neck(dir / "run" / "neck.csv"), misc(dir / "run" / "misc.csv");
  head << "time [ms],node 7 head CG AX [mm/ms2],node 7 head CG AY [mm/ms2],node 7 head CG AZ [mm/ms2]\n";
  neck << "time [ms],section 2 upper neck FZ [kN],section 2 upper neck MY [kN*mm]\n";
  misc << "time [ms],spring 4 belt B3 force [kN],part 3 ribs failed elements [-],rbody 900 impactor force [kN]\n";
  head.precision(12);
  neck.precision(12);
  misc.precision(12);
  for (int i = 0; i <= 1200; ++i) {  // 0 .. 60 ms every 0.05 ms
    const double t = i * 0.05;
    const double a = (t > start_ms && t < start_ms + dur_ms) ? amp_g * std::sin(pi * (t - start_ms) / dur_ms) : 0.0;
    // 0.6 of the pulse in x, 0.8 in z: the resultant is the half-sine
    head << t << ',' << 0.6 * a * g_in_mm_ms2 << ",0," << -0.8 * a * g_in_mm_ms2 << '\n';
    const double bump = (t > 10.0 && t < 30.0) ? std::sin(pi * (t - 10.0) / 20.0) : 0.0;  // peak at 20 ms
    neck << t << ',' << 6.806 * bump << ",0\n";
    const double tr = t - t0_ms;
    double f = 0.0;
    if (tr >= 0.0 && tr <= 30.0) f = corridor_midline(pelvis, {tr})[0];
    misc << t << ',' << 5.0 * bump << ',' << (t >= 25.0 ? 4 : (t >= 22.0 ? 1 : 0)) << ',' << f << '\n';
  }
  head.close();
  neck.close();
  misc.close();

  std::ofstream(dir / "case.toml") << "[case]\nname = \"pipeline\"\n\n[processing]\nrate_hz = 10000\n\n"
                                      "[time_zero]\nmethod = \"given\"\ntime_ms = 5.0\n\n"
                                      "[[signal]]\nname = \"ax\"\ncolumn = \"head CG AX\"\n"
                                      "[[signal]]\nname = \"ay\"\ncolumn = \"head CG AY\"\n"
                                      "[[signal]]\nname = \"az\"\ncolumn = \"head CG AZ\"\n"
                                      "[[signal]]\nname = \"head\"\ncombine = \"resultant\"\nof = [\"ax\", \"ay\", \"az\"]\nto_unit = \"g\"\n"
                                      "[[signal]]\nname = \"fz\"\ncolumn = \"upper neck FZ\"\nto_unit = \"N\"\n"
                                      "[[signal]]\nname = \"my\"\ncolumn = \"upper neck MY\"\n"
                                      "[[signal]]\nname = \"belt\"\ncolumn = \"belt B3\"\n"
                                      "[[signal]]\nname = \"ribs\"\ncolumn = \"ribs failed\"\n"
                                      "[[signal]]\nname = \"impactor\"\ncolumn = \"impactor force\"\n\n"
                                      "[[rating]]\nname = \"pelvis\"\nkind = \"time\"\nsignal = \"impactor\"\n"
                                      "[rating.corridor]\nfile = \"" + spec.file.string() + "\"\ncurve_column = \"bound\"\n"
                                      "x_column = \"x\"\ny_column = \"y_kN\"\nx_unit = \"ms\"\ny_unit = \"kN\"\n"
                                      "where = { impact = \"pelvis\", quantity = \"force_vs_time\" }\n\n"
                                      "[[criterion]]\nkind = \"hic\"\nsignal = \"head\"\nwindow_ms = 15\n"
                                      "[[criterion]]\nkind = \"hic\"\nsignal = \"head\"\nwindow_ms = 36\n"
                                      "[[criterion]]\nkind = \"a3ms\"\nsignal = \"head\"\n"
                                      "[[criterion]]\nkind = \"nij\"\nfz = \"fz\"\nmy = \"my\"\n"
                                      "[[criterion]]\nkind = \"belt_force\"\nsignal = \"belt\"\n"
                                      "[[criterion]]\nkind = \"failed_elements\"\nsignals = [\"ribs\"]\nlimit = 7\n";
  const auto cd = load_case(dir / "case.toml");
  const auto r = evaluate_case(cd, dir / "run");
  EXPECT_DOUBLE_EQ(r.t0_ms, t0_ms);
  EXPECT_EQ(r.signal("head").unit, "g");
  ASSERT_EQ(r.criteria.size(), 6u);

  const double hic15 = hic_half_sine(amp_g, dur_ms * 1e-3, 15e-3);
  EXPECT_NEAR(r.criteria[0].value, hic15, 5e-3 * hic15);  // 10 kHz sampling
  EXPECT_NEAR(0.5 * (r.criteria[0].t1_ms + r.criteria[0].t2_ms), start_ms - t0_ms + 0.5 * dur_ms, 0.1);
  EXPECT_DOUBLE_EQ(r.criteria[0].limit, 700.0);
  EXPECT_GE(r.criteria[0].risk, 0.0);
  const double hic36 = hic_half_sine(amp_g, dur_ms * 1e-3, 36e-3);
  EXPECT_NEAR(r.criteria[1].value, hic36, 5e-3 * hic36);
  const double a3 = amp_g * std::sin(pi * (dur_ms - 3.0) / (2.0 * dur_ms));
  EXPECT_NEAR(r.criteria[2].value, a3, amp_g * pi / dur_ms * 0.11);
  EXPECT_NEAR(r.criteria[3].value, 1.0, 1e-9);  // Fz at the tension intercept, My = 0
  EXPECT_NEAR(r.criteria[3].t1_ms, 20.0 - t0_ms, 1e-9);
  EXPECT_NEAR(r.criteria[4].value, 5.0, 1e-9);
  EXPECT_DOUBLE_EQ(r.criteria[4].limit, 6.9);
  EXPECT_DOUBLE_EQ(r.criteria[5].value, 4.0);

  ASSERT_EQ(r.ratings.size(), 1u);
  const auto& pr = r.ratings[0];
  EXPECT_FALSE(pr.reference_is_mean);
  EXPECT_GT(pr.iso.overall, 0.99);
  EXPECT_EQ(pr.iso.shift, 0);
  EXPECT_DOUBLE_EQ(pr.inside_fraction, 1.0);
  EXPECT_NEAR(pr.model_peak, 6.5, 1e-6);  // mid-line of the 5..8 kN plateau
  fs::remove_all(dir);
}

// sum_columns: a signal that adds every column whose name matches a pattern, as the thorax
// cases count the deleted elements of all twelve rib parts ("part N rib_NN ER"). Three rib
// parts deleting 1, 2 and 4 elements at 10, 20 and 30 ms give the count 7 from 30 ms on;
// a part that is not a rib (its 5 deletions) and a rib's internal energy are left out. No
// match, or sum_columns beside combine, is an error naming the case line.
TEST(Evaluation, SumColumnsAddsEveryMatchingColumn) {
  const fs::path dir = fs::temp_directory_path() / ("hbm_corridors_sum_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "run");
  {
    std::ofstream th(dir / "run" / "parts.csv");
    th << "time [ms],part 35 rib_01 ER [-],part 35 rib_01 IE [J],part 37 rib_02 ER [-],part 41 rib_06 ER [-],"
          "part 2 skin_thorax ER [-]\n";
    for (int i = 0; i <= 400; ++i) {
      const double t = i * 0.1;
      th << t << ',' << (t >= 10 ? 1 : 0) << ',' << t << ',' << (t >= 20 ? 2 : 0) << ',' << (t >= 30 ? 4 : 0) << ','
         << (t >= 5 ? 5 : 0) << '\n';
    }
  }
  const std::string head = "[case]\nname = \"sum\"\n\n[processing]\nrate_hz = 10000\n\n[time_zero]\nmethod = \"given\"\ntime_ms = 0\n\n";
  std::ofstream(dir / "case.toml") << head
                                   << "[[signal]]\nname = \"ribs\"\ncolumn = \"*rib_?? ER\"\nsum_columns = true\n\n"
                                      "[[criterion]]\nkind = \"failed_elements\"\nname = \"failed rib elements\"\n"
                                      "signals = [\"ribs\"]\nlimit = 7\n";
  const auto r = evaluate_case(load_case(dir / "case.toml"), dir / "run");
  const auto& s = r.signal("ribs");
  ASSERT_EQ(s.y.size(), r.time_ms.size());
  for (std::size_t i = 0; i < s.y.size(); i += 500) {
    const double t = r.time_ms[i];
    const double expect = (t >= 10 ? 1 : 0) + (t >= 20 ? 2 : 0) + (t >= 30 ? 4 : 0);
    if (std::abs(t - 10) > 0.2 && std::abs(t - 20) > 0.2 && std::abs(t - 30) > 0.2) {
      EXPECT_DOUBLE_EQ(s.y[i], expect) << t;
    }
  }
  ASSERT_EQ(r.criteria.size(), 1u);
  EXPECT_DOUBLE_EQ(r.criteria[0].value, 7.0);
  EXPECT_NE(s.source.find("sum of 3 columns"), std::string::npos) << s.source;

  std::ofstream(dir / "nomatch.toml") << head << "[[signal]]\nname = \"ribs\"\ncolumn = \"*costal ER\"\nsum_columns = true\n"
                                                  "[[criterion]]\nkind = \"failed_elements\"\nsignals = [\"ribs\"]\n";
  try {
    (void)evaluate_case(load_case(dir / "nomatch.toml"), dir / "run");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nomatch.toml:11: error: signal 'ribs': no column name matches"), std::string::npos)
        << e.what();
  }
  std::ofstream(dir / "both.toml") << head
                                   << "[[signal]]\nname = \"a\"\ncolumn = \"rib_01 ER\"\n[[signal]]\nname = \"b\"\ncolumn = \"rib_02 ER\"\n"
                                      "[[signal]]\nname = \"ribs\"\ncombine = \"sum\"\nof = [\"a\", \"b\"]\nsum_columns = true\n";
  try {
    (void)load_case(dir / "both.toml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("both.toml:21: error: signal 'ribs': sum_columns sums CSV columns"), std::string::npos)
        << e.what();
  }
  fs::remove_all(dir);
}
