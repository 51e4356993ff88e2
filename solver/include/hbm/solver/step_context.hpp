// SPDX-License-Identifier: GPL-3.0-or-later
// What every per-cycle callback (element group, interaction, constraint) receives: the
// time, the steps around it and the cycle number. Nothing in here allocates or looks
// anything up by name.
#pragma once

#include <cstdint>

namespace hbm::solver {

struct StepContext {
  std::int64_t cycle = 0;
  double time = 0.0;     // t^n [time]
  double dt_prev = 0.0;  // dt^{n-1/2} = t^n - t^{n-1}: the step v^{n-1/2} acted over
                         //   (0 at cycle 0) [time]
  double dt_next = 0.0;  // dt^{n+1/2}: the step of the coming position update. Known to
                         //   constraints and to the velocity update; element groups see
                         //   the previous cycle's value (their own dt is an output) [time]
};

}  // namespace hbm::solver
