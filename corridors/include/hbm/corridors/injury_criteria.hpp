// SPDX-License-Identifier: GPL-3.0-or-later
// Injury criteria computed from processed (filtered) channels on a uniform time grid.
// Time in ms throughout; the unit of each input is stated per function.
//  HIC (FMVSS 208): max over t2 - t1 <= window of (t2 - t1) [1/(t2 - t1) int a dt]^2.5,
//    a = resultant head acceleration in g, times in s.
//  a3ms: largest level the chest resultant acceleration exceeds for 3 ms in total
//    (cumulative); the continuous-3-ms ("clip") variant is given too.
//  VC (Lau & Viano 1986; SAE J1727 5-point velocity): VC(t) = SF V(t) D(t)/D0,
//    V(t) = [8 (D(t+h) - D(t-h)) - (D(t+2h) - D(t-2h))] / (12 h).
//  Nij (FMVSS 208 S6.6): Fz/Fzc + My/Myc over the four load modes, occipital-condyle
//    moment My - e Fx with e = 0.01778 m (49 CFR 572 Hybrid III upper neck load cell).
#pragma once

#include <string>
#include <vector>

namespace hbm::corridors {

struct WindowValue {
  double value = 0.0;
  double t1 = 0.0, t2 = 0.0;  ///< ms: window (HIC, a3ms clip) or time of the value (t1 = t2)
};

/// HIC over windows up to window_ms; t in ms (uniform), a in g.
WindowValue head_injury_criterion(const std::vector<double>& t_ms, const std::vector<double>& a_g,
                                  double window_ms);

/// Cumulative 3 ms exceedance level of |a| (same unit as a).
double a3ms_cumulative(const std::vector<double>& t_ms, const std::vector<double>& a, double duration_ms = 3.0);

/// Continuous ("clip") variant: max over windows of duration_ms of the window minimum of |a|.
WindowValue a3ms_continuous(const std::vector<double>& t_ms, const std::vector<double>& a, double duration_ms = 3.0);

/// Peak of |y| with its sign: value = y at the peak, t1 = t2 = time of the peak.
WindowValue signed_peak(const std::vector<double>& t_ms, const std::vector<double>& y);

/// VC time history in m/s; deflection d in mm, t in ms (so V in mm/ms = m/s); d0 in mm.
std::vector<double> viscous_criterion(const std::vector<double>& t_ms, const std::vector<double>& d_mm,
                                      double scale_factor, double d0_mm);

struct NijIntercepts {
  double tension_N = 6806.0, compression_N = 6160.0;          // FMVSS 208, 50th male
  double flexion_Nm = 310.0, extension_Nm = 135.0;
};

struct NijResult {
  double value = 0.0;
  std::string mode;  ///< NTE, NTF, NCE or NCF
  double t_ms = 0.0;
  double nte = 0.0, ntf = 0.0, nce = 0.0, ncf = 0.0;  ///< max of each mode
};

/// fz in N (tension positive), my in N m (flexion positive), fx in N (may be empty: no
/// correction), e_m the moment arm of the correction My_oc = My - e Fx.
NijResult neck_injury_criterion(const std::vector<double>& t_ms, const std::vector<double>& fz_N,
                                const std::vector<double>& my_Nm, const std::vector<double>& fx_N,
                                double e_m = 0.01778, const NijIntercepts& c = {});

}  // namespace hbm::corridors
