// SPDX-License-Identifier: GPL-3.0-or-later
// Strain-rate dependent plasticity read and run as OpenRadioss does, end to end (label
// verification). LAW36 with yield curves at several strain rates: the rate between the
// curves is the element's equivalent strain rate low-pass filtered at F_cut
// (hm_read_mat36.F: two or more curves, F_cut 0 -> 10 kHz; mstrain_rate.F / mulawc.F:
// r_n = a r + (1 - a) r_{n-1}, a = min(1, 2 pi F_cut dt)), on solids and shells. LAW2
// (Johnson-Cook) with c > 0 and F_cut > 0: the same filter (hm_read_mat02_jc.F90, m2law.F).
// Each case pulls an example deck made rate-dependent with F_cut = 0.2 /ms (time constant
// 0.8 ms) to 1 ms: the stress is the yield at the filtered rate r the element holds, which
// lags the rate of the pull so much that the unfiltered yield would be clearly higher.
#include "example_deck_runner.hpp"
#include "shells/shell_element_group.hpp"
#include "solid/solid_group.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;
using namespace hbm::solver;
using namespace hbm::solver::testing;

namespace {

const std::string e0 = "  0.000000000000E+00";

// decks/examples/<name> copied to ./<tag>/ with end time `tstop` and each `from` of the
// starter deck replaced by its `to`; the starter's path.
fs::path modified_copy(const std::string& name, const std::string& tag, double tstop,
                       const std::vector<std::pair<std::string, std::string>>& edits) {
  const fs::path dir = fs::current_path() / (tag + per_process_suffix());
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string starter = read_text(example_deck(name));
  for (const auto& [from, to] : edits) {
    const auto pos = starter.find(from);
    EXPECT_NE(pos, std::string::npos) << "pattern not in deck: " << from;
    if (pos != std::string::npos) starter.replace(pos, from.size(), to);
  }
  std::ofstream(dir / (name + "_0000.rad")) << starter;
  std::ifstream in(example_deck(name).replace_filename(name + "_0001.rad"));
  std::ofstream out(dir / (name + "_0001.rad"));
  std::string line;
  bool next = false;
  while (std::getline(in, line)) {
    out << (next ? std::to_string(tstop) : line) << "\n";
    next = line.rfind("/RUN/", 0) == 0;
  }
  return dir / (name + "_0000.rad");
}

const SolidGroup& solid(const InProcessRun& r) { return dynamic_cast<const SolidGroup&>(*r.model.groups.at(0)); }

// law36_rate_filter's curves line with F_cut 0 (OpenRadioss: 10 kHz).
std::pair<std::string, std::string> fcut_zero() {
  return {"         2         0" + e0 + "  2.000000000000E-01" + e0, "         2         0" + e0 + e0 + e0};
}

}  // namespace

TEST(StrainRateFilter, Law36BrickUsesTheFilteredRate) {
  // decks/examples/law36_rate_filter: law36_erosion's brick and curve with the two rate curves.
  auto r = run_in_process("law36_rate_filter");
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const SolidGroup& g = solid(*r);
  EXPECT_DOUBLE_EQ(g.material.plasticity.rate_filter, 2.0 * M_PI * 0.2);
  ASSERT_EQ(g.eps_rate.size(), 1u);
  const double R = 0.05, rate = g.eps_rate[0];
  const ThTable th = read_th(r->out / "law36_rate_filter_TH_NODE_1.csv");
  const double L = 1.0 + th.rows.back()[th.col("DX")];
  const double pull_rate = 1.263157894737E-02 / L;  // v / L after the ramp
  double sig[6];
  g.stress(0, sig);
  const double ep = g.eps_p[0];
  ASSERT_GT(ep, 0.005);
  const double f = 3e-4 + 2e-3 * ep;
  std::printf("brick: filtered rate %.5f /ms, pull %.5f /ms; stress %.6f, filtered yield %.6f, unfiltered %.6f GPa\n",
              rate, pull_rate, sig[0], f * (1.0 + rate / R), f * (1.0 + pull_rate / R));
  EXPECT_NEAR(sig[0], f * (1.0 + rate / R), 0.005 * sig[0]);
  EXPECT_GT(rate, 0.3 * pull_rate);
  EXPECT_GT(f * (1.0 + pull_rate / R), 1.05 * sig[0]) << "the filter did not lag";
}

// shell_pull_failure_quad (strip 50 x 10 x 1 mm pulled at 1 mm/ms: 0.02 /ms) with its LAW2
// card replaced by LAW36: f = 0.3 + 0.2 eps_p GPa at rate 0, 2 f at R = 0.08 /ms, no failure.
// In uniaxial plastic flow (eyy = -exx / 2) the element rate sqrt(4/3 (exx^2 + eyy^2 +
// exx eyy)) / dt is the pull's strain rate.
TEST(StrainRateFilter, Law36ShellUsesTheFilteredElementRate) {
  const std::string law2 =
      "/MAT/LAW2/1\nsteel JC\n  7.850000000000E-06\n  2.100000000000E+02  3.000000000000E-01         0\n"
      "  3.000000000000E-01  2.000000000000E-01  5.000000000000E-01  1.000000000000E-01" + e0 + "\n";
  const std::string law36 =
      "/MAT/LAW36/1\nsteel tabulated\n  7.850000000000E-06\n  2.100000000000E+02  3.000000000000E-01" + e0 +
      e0 + e0 + "\n         2         0" + e0 + "  2.000000000000E-01" + e0 + "\n\n         9         9\n"
      "  1.000000000000E+00  2.000000000000E+00\n" + e0 + "  8.000000000000E-02\n"
      "/FUNCT/9\nyield\n" + e0 + "  3.000000000000E-01\n  1.000000000000E+00  5.000000000000E-01\n";
  const fs::path starter = modified_copy("shell_pull_failure_quad", "law36_rate_shell", 1.0, {{law2, law36}});
  auto r = run_in_process("law36_rate_shell", starter);
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const auto& g = dynamic_cast<const shells::ShellElementGroup&>(*r->model.groups.at(0)).data;
  EXPECT_DOUBLE_EQ(g.mat.plasticity.rate_filter, 2.0 * M_PI * 0.2);
  ASSERT_EQ(g.eps_rate.size(), g.n);
  const double R = 0.08, pull_rate = 1.0 / 50.0;
  const auto np = static_cast<std::size_t>(g.sec.n_points);
  int checked = 0;
  for (std::size_t e = 0; e < g.n; ++e) {
    const double ep = g.epsp[e * np];
    if (ep <= 0.005) continue;
    const double rate = g.eps_rate[e];
    const double* s = &g.stress[e * np * 3];
    const double vm = std::sqrt(s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3 * s[2] * s[2]);
    const double f = 0.3 + 0.2 * ep;
    if (e == 0)
      std::printf("shell 1: filtered rate %.5f /ms, pull %.5f /ms; von Mises %.5f, filtered yield %.5f, unfiltered %.5f GPa\n",
                  rate, pull_rate, vm, f * (1.0 + rate / R), f * (1.0 + pull_rate / R));
    EXPECT_NEAR(vm, f * (1.0 + rate / R), 0.005 * vm) << "element " << e;
    EXPECT_GT(rate, 0.3 * pull_rate) << "element " << e;
    EXPECT_GT(f * (1.0 + pull_rate / R), 1.05 * vm) << "element " << e << ": the filter did not lag";
    ++checked;
  }
  EXPECT_GE(checked, 10);
}

// Options read as OpenRadioss reads them: F_cut 0 with two or more curves filters at 10 kHz
// (10 /ms in kg-mm-ms, 1e4 /s in kg-mm-s); one curve is rate independent (no filter); Vp 1 (plastic strain rate)
// and options this engine does not model (here Chard, kinematic hardening, which solids used
// to ignore) stop the run with an error naming the field.
TEST(StrainRateFilter, Law36OptionsAsOpenRadiossReadsThem) {
  {
    auto r = run_in_process("law36_erosion");
    ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
    EXPECT_EQ(solid(*r).material.plasticity.rate_filter, 0.0);
    EXPECT_TRUE(solid(*r).eps_rate.empty());
  }
  {
    const fs::path starter = modified_copy("law36_rate_filter", "law36_fcut_default", 0.1, {fcut_zero()});
    auto r = run_in_process("law36_fcut_default", starter);
    ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
    EXPECT_DOUBLE_EQ(solid(*r).material.plasticity.rate_filter, 2.0 * M_PI * 10.0);
  }
  const std::string curves = "         1         0" + e0 + e0 + e0;
  std::string log;
  {  // The default in a deck of seconds: 10 kHz = 1e4 per work time unit.
    std::vector<std::pair<std::string, std::string>> edits{fcut_zero()};
    const std::string ms = "                  kg                  mm                  ms\n";
    const std::string s = "                  kg                  mm                   s\n";
    edits.push_back({ms + ms, s + s});
    auto r = run_in_process("law36_fcut_seconds", modified_copy("law36_rate_filter", "law36_fcut_seconds", 0.1, edits));
    ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
    EXPECT_DOUBLE_EQ(solid(*r).material.plasticity.rate_filter, 2.0 * M_PI * 1.0e4);
  }
  EXPECT_NE(run_modified_deck("law36_erosion", "law36_vp1", curves, curves + std::string(10, ' ') + "         1", log), 0);
  EXPECT_NE(log.find("Vp"), std::string::npos) << log;
  EXPECT_NE(log.find("plastic strain rate"), std::string::npos) << log;
  EXPECT_NE(run_modified_deck("law36_erosion", "law36_chard", curves,
                              "         1         0  5.000000000000E-01" + e0 + e0, log), 0);
  EXPECT_NE(log.find("Chard"), std::string::npos) << log;
  EXPECT_NE(log.find("kinematic hardening is not supported"), std::string::npos) << log;
}

// uniaxial_law2 (one brick, a = 3e-4, b = 5e-4 GPa, n = 0.5, pulled at 1.05e-2 mm/ms after a
// ramp) with c = 0.1, EPS_DOT_0 = 1e-3 /ms, F_cut = 0.2 /ms, to 1 ms: sigma = (a + b eps_p^n)
// (1 + c ln(r / EPS_DOT_0)) at the filtered rate r (0.5 %), 3 % or more below the yield at the
// pull's rate.
TEST(StrainRateFilter, JohnsonCookBrickUsesTheFilteredRate) {
  const std::string hardening =
      "  3.000000000000E-04  5.000000000000E-04  5.000000000000E-01" + e0 + e0 + "\n";
  const std::string rate_line = "  1.000000000000E-01  1.000000000000E-03         0         0  2.000000000000E-01\n";
  const fs::path starter =
      modified_copy("uniaxial_law2", "law2_rate_brick", 1.0, {{hardening, hardening + rate_line}});
  auto r = run_in_process("law2_rate_brick", starter);
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const SolidGroup& g = solid(*r);
  EXPECT_DOUBLE_EQ(g.material.plasticity.rate_filter, 2.0 * M_PI * 0.2);
  ASSERT_EQ(g.eps_rate.size(), 1u);
  const double rate = g.eps_rate[0];
  const ThTable th = read_th(r->out / "uniaxial_law2_TH_NODE_1.csv");
  const double L = 1.0 + th.rows.back()[th.col("DX")];
  const double pull_rate = 1.052631578947E-02 / L;
  double sig[6];
  g.stress(0, sig);
  const double ep = g.eps_p[0];
  ASSERT_GT(ep, 0.001);
  const double s0 = 3e-4 + 5e-4 * std::sqrt(ep);
  auto yield = [&](double rr) { return s0 * (1.0 + 0.1 * std::log(rr / 1e-3)); };
  std::printf("JC brick: filtered rate %.5f /ms, pull %.5f /ms; stress %.6f, filtered yield %.6f, unfiltered %.6f GPa\n",
              rate, pull_rate, sig[0], yield(rate), yield(pull_rate));
  EXPECT_NEAR(sig[0], yield(rate), 0.005 * sig[0]);
  EXPECT_GT(yield(pull_rate), 1.03 * sig[0]) << "the filter did not lag";
}

// LAW2 options: c > 0 with F_cut 0 runs with the rate of each step and a warning saying what
// OpenRadioss does; thermal softening (T_melt and rho0Cp given) stops the run naming T_melt.
TEST(StrainRateFilter, JohnsonCookOptions) {
  const std::string hardening =
      "  3.000000000000E-04  5.000000000000E-04  5.000000000000E-01" + e0 + e0 + "\n";
  std::string log;
  EXPECT_EQ(run_modified_deck("uniaxial_law2", "law2_fcut0", hardening,
                              hardening + "  1.000000000000E-01  1.000000000000E-03\n", log), 0) << log;
  EXPECT_NE(log.find("F_cut = 0 with c > 0"), std::string::npos) << log;
  EXPECT_NE(run_modified_deck("uniaxial_law2", "law2_thermal", hardening,
                              hardening + e0 + e0 + "\n  1.000000000000E+00  1.800000000000E+03  3.500000000000E-03\n",
                              log), 0);
  EXPECT_NE(log.find("T_melt"), std::string::npos) << log;
  EXPECT_NE(log.find("thermal softening"), std::string::npos) << log;
}
