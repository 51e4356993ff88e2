// SPDX-License-Identifier: GPL-3.0-or-later
// Allocation and per-element output values of a shell element group.
#include "shells/shell_group_data.hpp"

#include <algorithm>
#include <cmath>

namespace hbm::solver::shells {

void ShellGroupData::allocate() {
  nodes_per_element = kind == ShellKind::QuadBT ? 4 : 3;
  const std::size_t np = static_cast<std::size_t>(sec.n_points);
  thick0 = thick;
  wave_speed = mat.plate_wave_speed();
  stress.assign(n * np * 3, 0.0);
  epsp.assign(n * np, 0.0);
  eps_rate.assign(mat.plastic() && mat.plasticity.rate_filter > 0.0 ? n : 0, 0.0);
  hist.assign(n * np * static_cast<std::size_t>(mat.n_history()), 0.0);
  extra.assign(n * static_cast<std::size_t>(extra_per_element()), 0.0);
  n_failed.assign(n, 0);
  deleted.assign(n, 0);
  eint.assign(n, 0.0);
  ehg.assign(n, 0.0);
  dt_elem.assign(n, 1e300);
  area.assign(n, 0.0);
  frozen.assign(small_strain.enabled ? n : 0, 0);
  frozen_shape.assign(frozen.size() * kFrozenShapeStride, 0.0);
}

double ShellGroupData::von_mises(std::size_t e) const {
  const int np = sec.n_points;
  double sum = 0;
  for (int p = 0; p < np; ++p) {
    const double s0 = point_stress(e, p, 0), s1 = point_stress(e, p, 1), s2 = point_stress(e, p, 2);
    sum += std::sqrt(std::max(0.0, s0 * s0 - s0 * s1 + s1 * s1 + 3.0 * s2 * s2));
  }
  return sum / np;
}

double ShellGroupData::max_epsp(std::size_t e) const {
  const int np = sec.n_points;
  double m = 0;
  for (int p = 0; p < np; ++p) m = std::max(m, epsp[e * np + p]);
  return m;
}

}  // namespace hbm::solver::shells
