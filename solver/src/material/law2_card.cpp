// SPDX-License-Identifier: GPL-3.0-or-later
// /MAT/LAW2 -> PlasticityLaw (Johnson-Cook), shared by the solid and shell builders.
#include "material/law2_card.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace hbm::solver {

namespace {

// Fixed lines of /MAT/LAW2 (deck/src/keywords_model.cpp).
constexpr std::size_t kElasticity = 1, kHardening = 2, kRate = 3, kTemperature = 4;

}  // namespace

bool read_law2_hardening(BuildContext& ctx, const hbm::deck::Card& m, PlasticityLaw& pl) {
  if (m.integer(kElasticity, "Iflag") != 0) {
    ctx.error(m, m.lines.at(kElasticity), "Iflag", "Iflag != 0 (yield and UTS input) is not supported; give a, b, n");
    return false;
  }
  // Thermal softening (1 - T*^m) needs the temperature to rise, T = T_r + plastic work /
  // rho0Cp, towards T_melt: OpenRadioss takes both 0 as "none" (1e20).
  if (m.real(kTemperature, "T_melt") != 0.0 && m.real(kTemperature, "rho0Cp") != 0.0) {
    ctx.error(m, m.lines.at(kTemperature), "T_melt",
              "thermal softening (T_melt and rho0Cp both given) is not supported; leave T_melt or rho0Cp 0");
    return false;
  }
  pl.kind = PlasticityLaw::Kind::JohnsonCook;
  auto& jc = pl.jc;
  jc.a = m.real(kHardening, "a");
  jc.b = m.real(kHardening, "b");
  jc.n = m.real(kHardening, "n");
  const double epm = m.real(kHardening, "EPS_p_max");
  pl.eps_p_max = epm > 0 ? epm : std::numeric_limits<double>::infinity();
  const double smax = m.real(kHardening, "SIG_max0");
  jc.sig_max = smax > 0 ? smax : std::numeric_limits<double>::infinity();
  jc.c = m.real(kRate, "c");
  jc.eps_dot0 = m.real(kRate, "EPS_DOT_0");
  if (jc.c > 0 && !(jc.eps_dot0 > 0)) {
    ctx.error(m, m.lines.at(kRate), "EPS_DOT_0", "c > 0 needs EPS_DOT_0 > 0");
    return false;
  }
  // ICC (0 -> 1): 1 = SIG_max0 scaled by the rate term as the yield stress is, 2 = not.
  jc.rate_scales_sig_max = m.integer(kRate, "ICC") != 2;
  // Strain rate filter at F_cut. F_cut 0 with c > 0: the rate of each step, unfiltered, as
  // OpenRadioss (hm_read_mat02_jc: asrate = 1e20, so m2law's weight min(1, asrate dt) is 1;
  // its starter warns, message 1220). Its plastic-strain-rate option VP = 1, which forces
  // F_cut to 10 kHz, is not on this card.
  const double fcut = m.real(kRate, "F_cut");
  pl.rate_filter = jc.c > 0 && fcut > 0 ? 2.0 * M_PI * fcut : 0.0;
  if (jc.c > 0 && fcut == 0.0)
    ctx.warning(m, "F_cut = 0 with c > 0: the strain rate of each step is used unfiltered, as in OpenRadioss "
                   "(give F_cut, e.g. 10 kHz in the work time unit, to filter it)");
  return true;
}

}  // namespace hbm::solver
