// SPDX-License-Identifier: GPL-3.0-or-later
// Run control read from the engine deck NAME_0001.rad: final time, output intervals,
// time-step control, stop criteria, listing frequency. Plain values, read once.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

namespace hbm::solver {

struct RunControl {
  double t_stop = 0.0;            // /RUN [time]
  double th_interval = 0.0;       // /TFILE; 0 = no time histories [time]
  double anim_start = 0.0;        // /ANIM/DT Tstart [time]
  double anim_interval = 0.0;     // /ANIM/DT Tfreq; 0 = no animation [time]
  // /DT/NODA/CST: fixed step Tmin with nodal mass scaling; otherwise element step.
  bool nodal_cst = false;
  double dt_scale = 0.9;          // Tsca (also the element-step factor without /DT/NODA/CST)
  double dt_min = 0.0;            // Tmin [time]
  // /STOP
  double stop_energy_error = std::numeric_limits<double>::infinity();  // Emax (ratio)
  double stop_mass_ratio = std::numeric_limits<double>::infinity();    // DMmax, (M-M0)/M0
  // /PRINT/-N: listing line every N cycles; negative N also prints to stdout.
  std::int64_t print_every = 100;
  bool print_stdout = true;
};

}  // namespace hbm::solver
