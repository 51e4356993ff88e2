// SPDX-License-Identifier: GPL-3.0-or-later
// hbm-corridors-synthetic-hub: writes a synthetic "run" of a frontal thorax hub impact in the
// solver's time-history CSV format, from a closed-form physical model, so that hbm-corridors
// can be demonstrated and tested end to end without a finite-element run.
//
// Model: a rigid impactor (mass m, speed v0) strikes a Kelvin-Voigt thorax (spring k in
// parallel with damper c) backed by the body mass M, free in space (the PMHS sat without
// back support). With the deflection x = u_impactor - u_spine and the reduced mass
// mu = m M / (m + M):   mu x'' + c x' + k x = 0,  x(0) = 0, x'(0) = v0,
//   x(t) = v0 / wd exp(-zeta wn t) sin(wd t),  wn = sqrt(k/mu), zeta = c / (2 sqrt(k mu)),
//   wd = wn sqrt(1 - zeta^2);  contact force F = k x + c x' (compressive, >= 0).
// The centre of mass moves at vc = m v0 / (m + M), so u_impactor = vc t + M/(m+M) x and
// u_spine = vc t - m/(m+M) x. When F would turn tensile the impactor leaves the chest and
// both bodies fly on at constant speed. Default parameters: m = 23.4 kg, v0 = 6.7 m/s
// (Kroell / Lebarbe & Petit 2012 hub), k = 26.3 kN/m, c = 0.52 kN s/m and M = 27.2 kg, the
// chest-wall spring, damper and back mass of the Lobdell et al. (1973) thorax model as
// recalled [check]; the skin spring, sternum mass and Maxwell element of that model are
// left out so that the solution stays closed-form.
//
// Output (units in the headers, mm, ms, kg, kN as the solver writes them):
//   impactor.csv  time, rbody 900 impactor DX/VX/AX, contact force (impactor moving along -X;
//                 --axis Y writes DY/VY/AY for the lateral and oblique cases)
//   nodes.csv     time, node 3208 T8 DX, node 1201 sternum DX
//   global.csv    time, kinetic, internal, damping energy, energy error
//   parts.csv     time, deleted elements of the twelve rib parts (/TH/PART ER, as the
//                 load-case decks write them): 0, the closed-form thorax does not break
// With --corridor-out it also writes a corridor CSV built from the model's own closed-form
// force-deflection curve (mean, and bounds at +/- 20 % of the peak force), used by the
// end-to-end test: a run rated against its own curve must score close to 1.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace fs = std::filesystem;

namespace {

struct HubModel {
  double m = 23.4, big_m = 27.2, v0 = 6.7, k = 26.3, c = 0.52;  // kg, kg, m/s, kN/m, kN s/m
  double mu() const { return m * big_m / (m + big_m); }
  double wn() const { return std::sqrt(k * 1e3 / mu()); }                   // rad/s
  double zeta() const { return c * 1e3 / (2.0 * std::sqrt(k * 1e3 * mu())); }
  double wd() const { return wn() * std::sqrt(1.0 - zeta() * zeta()); }
  /// deflection [m] and rate [m/s] at time t [s] after contact (closed form)
  void state(double t, double& x, double& v) const {
    const double a = zeta() * wn(), w = wd();
    const double e = std::exp(-a * t);
    x = v0 / w * e * std::sin(w * t);
    v = v0 * e * (std::cos(w * t) - a / w * std::sin(w * t));
  }
  double force_kN(double x, double v) const { return (k * x + c * v); }  // kN/m * m = kN
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes a synthetic thorax hub-impact run (closed-form Kelvin-Voigt thorax) as time-history CSVs"};
  HubModel hm;
  std::string out_dir, corridor_out;
  double dt_ms = 0.05, t_end_ms = 80.0, t_contact_ms = 2.0;
  app.add_option("--out", out_dir, "run folder to write")->required();
  app.add_option("--speed", hm.v0, "impactor speed [m/s]");
  app.add_option("--impactor-mass", hm.m, "impactor mass [kg]");
  app.add_option("--body-mass", hm.big_m, "effective body (spine) mass [kg]");
  app.add_option("--stiffness", hm.k, "thorax spring [kN/m]");
  app.add_option("--damping", hm.c, "thorax damper [kN s/m]");
  app.add_option("--dt", dt_ms, "output interval [ms]");
  app.add_option("--t-end", t_end_ms, "end time [ms]");
  app.add_option("--t-contact", t_contact_ms, "time of first contact [ms]");
  app.add_option("--corridor-out", corridor_out, "also write a corridor CSV made from the model's own curve");
  std::string axis = "X";
  app.add_option("--axis", axis, "global axis the impactor travels along, in the negative direction (X: frontal "
                                 "cases, Y: the Viano lateral/oblique cases)")
      ->check(CLI::IsMember({"X", "Y", "Z"}));
  CLI11_PARSE(app, argc, argv);
  if (!(hm.zeta() < 1.0)) {
    std::cerr << "hbm-corridors-synthetic-hub: error: damping ratio " << hm.zeta() << " >= 1 (closed form is for the underdamped case)\n";
    return 1;
  }
  fs::create_directories(out_dir);
  std::ofstream imp(fs::path(out_dir) / "impactor.csv"), nod(fs::path(out_dir) / "nodes.csv"),
      glo(fs::path(out_dir) / "global.csv"), prt(fs::path(out_dir) / "parts.csv");
  imp << "time [ms],rbody 900 impactor D" << axis << " [mm],rbody 900 impactor V" << axis << " [mm/ms],rbody 900 impactor A"
      << axis << " [mm/ms^2],contact 5 impactor-thorax F" << axis << " [kN]\n";
  nod << "time [ms],node 3208 T8 D" << axis << " [mm],node 1201 sternum D" << axis << " [mm]\n";
  glo << "time [ms],kinetic energy [J],internal energy [J],damping energy [J],energy error [-]\n";
  prt << "time [ms]";
  for (int r = 1; r <= 12; ++r) prt << ",part " << 34 + r << " rib_" << (r < 10 ? "0" : "") << r << " ER [-]";
  prt << "\n";
  const double mt = hm.m + hm.big_m, vc = hm.m * hm.v0 / mt;
  bool separated = false;
  double ts = 0.0, xs = 0.0, vs = 0.0, e_damp = 0.0, v_prev = hm.v0;
  const double e0 = 0.5 * hm.m * hm.v0 * hm.v0;
  const auto n = static_cast<long>(std::llround(t_end_ms / dt_ms));
  char line[512];
  for (long i = 0; i <= n; ++i) {
    const double t_ms = static_cast<double>(i) * dt_ms;
    const double tau = (t_ms - t_contact_ms) * 1e-3;  // s after contact
    double x = 0.0, v = 0.0, f = 0.0;                   // m, m/s, kN
    if (tau > 0.0) {
      if (!separated) {
        hm.state(tau, x, v);
        f = hm.force_kN(x, v);
        if (f < 0.0 && x > 0.0) {
          separated = true;
          ts = tau;
          xs = x;
          vs = v;
        }
      }
      if (separated) {
        x = xs + vs * (tau - ts);
        v = vs;
        f = 0.0;
      }
    } else {
      v = hm.v0;
    }
    // damping work by trapezoid on c v^2 (J): kN s/m * (m/s)^2 * s = kJ -> * 1e3
    if (tau > 0.0 && !separated) e_damp += 0.5 * (hm.c * (v * v + v_prev * v_prev)) * dt_ms * 1e-3 * 1e3;
    v_prev = v;
    const double t_after = std::max(tau, 0.0);
    const double u_imp = (tau > 0.0 ? vc * t_after + hm.big_m / mt * x : hm.v0 * tau) * 1e3;  // mm
    const double u_sp = (tau > 0.0 ? vc * t_after - hm.m / mt * x : 0.0) * 1e3;
    const double v_imp = tau > 0.0 ? vc + hm.big_m / mt * v : hm.v0;  // m/s = mm/ms
    const double v_sp = tau > 0.0 ? vc - hm.m / mt * v : 0.0;
    const double a_imp = -f / hm.m;  // kN/kg = mm/ms^2
    const double ke = 0.5 * hm.m * v_imp * v_imp + 0.5 * hm.big_m * v_sp * v_sp;
    const double ie = separated ? 0.0 : 0.5 * hm.k * 1e3 * x * x;
    const double err = (ke + ie + e_damp - e0) / e0;
    // the impactor travels along -X (SAE J211 occupant axes: +X forward, so rearward into
    // the chest): displacements, velocities and accelerations change sign on output; the
    // contact force on the impactor then points along +X
    std::snprintf(line, sizeof line, "%.5f,%.9g,%.9g,%.9g,%.9g\n", t_ms, -u_imp, -v_imp, -a_imp, f);
    imp << line;
    std::snprintf(line, sizeof line, "%.5f,%.9g,%.9g\n", t_ms, -u_sp, -u_imp);
    nod << line;
    std::snprintf(line, sizeof line, "%.5f,%.9g,%.9g,%.9g,%.6g\n", t_ms, ke, ie, e_damp, separated ? 0.0 : err);
    glo << line;
    std::snprintf(line, sizeof line, "%.5f", t_ms);
    prt << line;
    for (int r = 0; r < 12; ++r) prt << ",0";
    prt << '\n';
  }
  if (!imp || !nod || !glo || !prt) {
    std::cerr << "hbm-corridors-synthetic-hub: error: cannot write to " << out_dir << "\n";
    return 1;
  }
  // closed-form peak deflection: tan(wd t) = wd / (zeta wn)
  const double tp = std::atan2(hm.wd(), hm.zeta() * hm.wn()) / hm.wd();
  double xp = 0.0, vp = 0.0;
  hm.state(tp, xp, vp);
  std::cout << "synthetic hub run: mu = " << hm.mu() << " kg, wn = " << hm.wn() << " rad/s, zeta = " << hm.zeta()
            << "\n  peak deflection " << xp * 1e3 << " mm at " << tp * 1e3 << " ms after contact, force there "
            << hm.force_kN(xp, 0.0) << " kN, initial force c v0 = " << hm.c * hm.v0 << " kN\n";
  if (!corridor_out.empty()) {
    std::ofstream cf(corridor_out);
    cf << "# SYNTHETIC corridor, not test data: the closed-form force-deflection curve of hbm-corridors-synthetic-hub\n"
       << "# (Kelvin-Voigt thorax k = " << hm.k << " kN/m, c = " << hm.c << " kN s/m, impactor " << hm.m << " kg at " << hm.v0
       << " m/s, body " << hm.big_m << " kg) as mean; bounds at mean +/- 20 % of the peak force.\n"
       << "# x = deflection (impactor disp. relative to spine) [mm], y = impactor force [N]. Loading branch only.\n"
       << "curve,point,deflection_mm,force_N\n";
    const int np = 120;
    double fmax = 0.0;
    for (int j = 0; j <= np; ++j) {
      double x, v;
      hm.state(tp * j / np, x, v);
      fmax = std::max(fmax, hm.force_kN(x, v) * 1e3);
    }
    for (const char* curve : {"mean", "upper", "lower"}) {
      const double off = std::string(curve) == "upper" ? 0.2 * fmax : (std::string(curve) == "lower" ? -0.2 * fmax : 0.0);
      for (int j = 0; j <= np; ++j) {
        double x, v;
        hm.state(tp * j / np, x, v);
        std::snprintf(line, sizeof line, "%s,%d,%.6f,%.3f\n", curve, j + 1, x * 1e3, hm.force_kN(x, v) * 1e3 + off);
        cf << line;
      }
    }
  }
  return 0;
}
