// SPDX-License-Identifier: GPL-3.0-or-later
// Average nodal pressure of 4-node tetrahedra (see nodal_pressure_average.hpp).
#include "solid/nodal_pressure_average.hpp"

#include "hbm/solver/nodal_state.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace hbm::solver {

namespace {

double tetra_volume(const NodalState& nodes, const Index* n) {
  const auto a = static_cast<std::size_t>(n[0]), b = static_cast<std::size_t>(n[1]);
  const auto c = static_cast<std::size_t>(n[2]), d = static_cast<std::size_t>(n[3]);
  const double ax = nodes.x.x[b] - nodes.x.x[a], ay = nodes.x.y[b] - nodes.x.y[a], az = nodes.x.z[b] - nodes.x.z[a];
  const double cx = nodes.x.x[c] - nodes.x.x[a], cy = nodes.x.y[c] - nodes.x.y[a], cz = nodes.x.z[c] - nodes.x.z[a];
  const double dx = nodes.x.x[d] - nodes.x.x[a], dy = nodes.x.y[d] - nodes.x.y[a], dz = nodes.x.z[d] - nodes.x.z[a];
  return (ax * (cy * dz - cz * dy) + ay * (cz * dx - cx * dz) + az * (cx * dy - cy * dx)) / 6.0;
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
                                  const std::vector<std::uint8_t>& alive, const std::vector<double>& small_volume) {
  std::fill(v_.begin(), v_.end(), 0.0);
  const std::size_t n = volume0_.size();
  for (std::size_t e = 0; e < n; ++e) {
    const bool switched = !small_volume.empty() && small_volume[e] > 0.0;
    const double ve = !alive[e] ? volume0_[e] : switched ? small_volume[e] : tetra_volume(nodes, &connectivity[e * 4]);
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
