// SPDX-License-Identifier: GPL-3.0-or-later
// Average nodal pressure of 4-node tetrahedra (see nodal_pressure_average.hpp).
#include "solid/nodal_pressure_average.hpp"

#include "hbm/solver/nodal_state.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace hbm::solver {

namespace {

// (b - a) . ((c - a) x (d - a)) / 6 of four points given by their coordinates.
double tetra_volume(const double* a, const double* b, const double* c, const double* d) {
  const double ax = b[0] - a[0], ay = b[1] - a[1], az = b[2] - a[2];
  const double cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
  const double dx = d[0] - a[0], dy = d[1] - a[1], dz = d[2] - a[2];
  return (ax * (cy * dz - cz * dy) + ay * (cz * dx - cx * dz) + az * (cx * dy - cy * dx)) / 6.0;
}

double tetra_volume(const NodalState& nodes, const Index* n) {
  double p[4][3];
  for (int i = 0; i < 4; ++i) {
    const auto k = static_cast<std::size_t>(n[i]);
    p[i][0] = nodes.x.x[k]; p[i][1] = nodes.x.y[k]; p[i][2] = nodes.x.z[k];
  }
  return tetra_volume(p[0], p[1], p[2], p[3]);
}

}  // namespace

void NodalPressureAverage::setup(const std::vector<Index>& connectivity, const std::vector<double>& volume0) {
  std::unordered_map<Index, Index> to_local;
  local_.resize(connectivity.size());
  for (std::size_t s = 0; s < connectivity.size(); ++s) {
    auto [it, inserted] = to_local.try_emplace(connectivity[s], static_cast<Index>(to_local.size()));
    local_[s] = it->second;
  }
  v0_.assign(to_local.size(), 0.0);
  for (std::size_t e = 0; e < volume0.size(); ++e)
    for (int i = 0; i < 4; ++i) v0_[static_cast<std::size_t>(local_[e * 4 + i])] += 0.25 * volume0[e];
  v_ = v0_;
  log_j_.assign(v0_.size(), 0.0);
  volume0_ = volume0;
  mean_log_j_.assign(volume0.size(), 0.0);
}

void NodalPressureAverage::update(const NodalState& nodes, const std::vector<Index>& connectivity,
                                  const std::vector<std::uint8_t>& alive, const FrozenGeometry& frozen) {
  std::fill(v_.begin(), v_.end(), 0.0);
  const std::size_t n = volume0_.size();
  for (std::size_t e = 0; e < n; ++e) {
    const double* xf = frozen.active() && frozen.frozen[e] ? &frozen.x[e * 12] : nullptr;
    const double ve = !alive[e] ? volume0_[e]
                      : xf      ? tetra_volume(xf, xf + 3, xf + 6, xf + 9)
                                : tetra_volume(nodes, &connectivity[e * 4]);
    for (int i = 0; i < 4; ++i) v_[static_cast<std::size_t>(local_[e * 4 + i])] += 0.25 * ve;
  }
  for (std::size_t k = 0; k < v_.size(); ++k) {
    log_j_[k] = v_[k] > 0.0 ? std::log(v_[k] / v0_[k]) : 0.0;
  }
  for (std::size_t e = 0; e < n; ++e) {
    const Index* l = &local_[e * 4];
    mean_log_j_[e] = 0.25 * (log_j_[static_cast<std::size_t>(l[0])] + log_j_[static_cast<std::size_t>(l[1])] +
                             log_j_[static_cast<std::size_t>(l[2])] + log_j_[static_cast<std::size_t>(l[3])]);
  }
}

}  // namespace hbm::solver
