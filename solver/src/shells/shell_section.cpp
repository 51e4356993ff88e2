// SPDX-License-Identifier: GPL-3.0-or-later
// Gauss-Legendre points through the shell thickness (Newton iteration on P_n).
#include "shells/shell_section.hpp"

#include <cmath>
#include <numbers>

namespace hbm::solver::shells {

bool ShellSection::set_points(int n) {
  if (n < 1 || n > kMaxThicknessPoints) return false;
  n_points = n;
  zeta.fill(0.0);
  weight.fill(0.0);
  for (int i = 0; i < n; ++i) {
    // Initial guess (Abramowitz & Stegun 22.16.6), then Newton on P_n(x) = 0.
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) { p1 = x; p0 = 1.0; }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // Recompute derivative at the root for the weight w = 2 / ((1 - x^2) P_n'(x)^2).
    double p0 = 1.0, p1 = x;
    for (int k = 2; k <= n; ++k) {
      const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    dp = n * (x * p1 - p0) / (x * x - 1.0);
    zeta[i] = -x;  // ascending from the bottom surface
    weight[i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  if (n == 1) { zeta[0] = 0.0; weight[0] = 2.0; }
  return true;
}

}  // namespace hbm::solver::shells
