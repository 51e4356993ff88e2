// SPDX-License-Identifier: GPL-3.0-or-later
// SAE J211-1 (March 1995) / ISO 6487 channel frequency class (CFC) filters and resampling.
// The CFC filter is the phaseless 4-pole filter of SAE J211-1 Appendix C: a 2-pole
// Butterworth low pass (bilinear transform, design frequency 2.0775 x CFC) run forward over
// the signal and then backward over the result, so the phase shifts cancel.
#pragma once

#include <vector>

namespace hbm::corridors {

/// Coefficients of the 2-pole section, SAE J211-1 Appendix C:
///   wd = 2 pi CFC 2.0775,  wa = tan(wd T / 2),  den = 1 + sqrt(2) wa + wa^2
///   a0 = wa^2/den, a1 = 2 a0, a2 = a0, b1 = -2 (wa^2 - 1)/den, b2 = (-1 + sqrt(2) wa - wa^2)/den
///   Y[t] = a0 X[t] + a1 X[t-1] + a2 X[t-2] + b1 Y[t-1] + b2 Y[t-2]
struct J211Coefficients {
  double a0, a1, a2, b1, b2;
};

/// cfc in Hz (60, 180, 600, 1000 or any positive class), sample interval dt in s.
J211Coefficients j211_coefficients(double cfc, double dt_s);

/// Phaseless CFC filter of a uniformly sampled signal (interval dt_s, seconds). The ends are
/// extended by a point reflection (2 x0 - x[k]) of about two CFC periods so the start-up
/// transient of the recursion falls outside the data; the result has the input's length.
/// Throws std::invalid_argument when the sampling rate is below 2.0775*CFC*2 (the design
/// frequency must lie below Nyquist) or cfc <= 0.
std::vector<double> cfc_filter(const std::vector<double>& x, double dt_s, double cfc);

/// One pass of the 2-pole section (forward), exposed for tests of the phase shift.
std::vector<double> j211_single_pass(const std::vector<double>& x, const J211Coefficients& c);

/// Linear interpolation of (t, y) at the times t_new; t must be non-decreasing. Outside
/// [t.front(), t.back()] the end values are held.
std::vector<double> resample_linear(const std::vector<double>& t, const std::vector<double>& y,
                                    const std::vector<double>& t_new);

/// Uniform grid t0, t0+dt, ... up to t1 (inclusive within dt*1e-9).
std::vector<double> uniform_grid(double t0, double t1, double dt);

/// True when the samples are uniformly spaced within a relative tolerance of 1e-6 of dt.
bool is_uniform(const std::vector<double>& t);

}  // namespace hbm::corridors
