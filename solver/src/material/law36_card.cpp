// SPDX-License-Identifier: GPL-3.0-or-later
// /MAT/LAW36 -> PlasticityLaw (tabulated), shared by the solid and shell builders.
#include "material/law36_card.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace hbm::solver {

namespace {

// Fixed lines of /MAT/LAW36 (deck/src/keywords_model.cpp; an optional line absent from the
// deck reads as its defaults).
constexpr std::size_t kElasticity = 1, kCurves = 2, kPressure = 3, kYieldCurves = 4, kScales = 5, kRates = 6;

}  // namespace

bool read_law36_hardening(BuildContext& ctx, const hbm::deck::Card& m, PlasticityLaw& pl) {
  // Options this engine does not model are refused, never ignored: tensile damage and
  // failure strains, kinematic hardening, pressure-dependent yield, Young's modulus evolution.
  struct Unsupported {
    std::size_t line;
    const char* field;
    const char* what;
    bool id;  // an integer (function id) field
  };
  static constexpr Unsupported kUnsupported[] = {
      {kElasticity, "EPS_t", "tensile damage", false},
      {kElasticity, "EPS_m", "tensile damage", false},
      {kCurves, "Chard", "kinematic hardening", false},
      {kCurves, "EPS_f", "tensile failure", false},
      {kPressure, "fct_IDp", "pressure-dependent yield", true},
      {kPressure, "fct_IDE", "Young's modulus evolution", true},
      {kPressure, "CE", "Young's modulus evolution", false},
  };
  for (const auto& u : kUnsupported) {
    if (u.id ? m.integer(u.line, u.field) != 0 : m.real(u.line, u.field) != 0.0) {
      ctx.error(m, m.lines.at(u.line), u.field,
                std::string(u.what) + " is not supported (" + u.field + " must be 0); this engine reads "
                "E, nu, EPS_p_max, the yield curves with their scales and strain rates, F_cut and Vp");
      return false;
    }
  }
  pl.kind = PlasticityLaw::Kind::Tabulated;
  const double epm = m.real(kElasticity, "EPS_p_max");
  pl.eps_p_max = epm > 0 ? epm : std::numeric_limits<double>::infinity();
  const auto n = m.integer(kCurves, "N_funct");
  for (int k = 1; k <= n; ++k) {
    const std::string f = "fct_ID" + std::to_string(k);
    const std::int64_t fid = m.integer(kYieldCurves, f);
    const FunctionCurve* fc = ctx.function(fid);
    if (!fc) {
      ctx.error(m, m.lines.at(kYieldCurves), f, "no function " + std::to_string(fid));
      return false;
    }
    pl.tab.curves.push_back(fc);
    pl.tab.scales.push_back(m.real(kScales, "Fscale" + std::to_string(k)));
    pl.tab.rates.push_back(m.real(kRates, "EPS_dot" + std::to_string(k)));
  }
  for (std::size_t k = 1; k < pl.tab.rates.size(); ++k)
    if (!(pl.tab.rates[k] > pl.tab.rates[k - 1])) {
      ctx.error(m, "strain rates EPS_dot1..N must increase");
      return false;
    }
  // Strain rate used between the curves (OpenRadioss hm_read_mat36.F, mstrain_rate.F).
  if (m.integer(kCurves, "Vp") == 1) {
    ctx.error(m, m.lines.at(kCurves), "Vp",
              "Vp = 1 (yield curves by plastic strain rate) is not supported; 0 or 2 (equivalent "
              "deviatoric strain rate)");
    return false;
  }
  const double fcut = m.real(kCurves, "F_cut");
  if (pl.tab.curves.size() < 2) {
    // One curve: rate independent; OpenRadioss sets F_cut to 0.
    if (fcut != 0.0) ctx.warning(m, "F_cut is not used with a single yield curve (rate independent)");
    pl.rate_filter = 0.0;
    return true;
  }
  double f = fcut;
  if (f == 0.0) {
    const std::string& unit = ctx.starter().work_units.time;
    const auto sec = hbm::deck::unit_factor(unit, 's');
    if (!sec) {  // the deck check refuses such a /BEGIN first
      ctx.error(m, m.lines.at(kCurves), "F_cut",
                "F_cut = 0 means 10 kHz, but the work time unit '" + unit + "' of /BEGIN is not a unit of time");
      return false;
    }
    f = 1.0e4 * *sec;  // 10 kHz in cycles per work time unit
  }
  pl.rate_filter = 2.0 * M_PI * f;
  return true;
}

}  // namespace hbm::solver
