// SPDX-License-Identifier: GPL-3.0-or-later
// Eigen views of one node's entry in a struct-of-arrays nodal vector (x, v, f, omega, ...),
// for the rigid-body code that works per body rather than in hot per-node loops.
#pragma once

#include "hbm/solver/nodal_state.hpp"

#include <Eigen/Dense>

#include <cstddef>

namespace hbm::solver::rigid {

inline Eigen::Vector3d load(const Vec3Soa& a, Index i) {
  const auto k = static_cast<std::size_t>(i);
  return {a.x[k], a.y[k], a.z[k]};
}

inline void store(Vec3Soa& a, Index i, const Eigen::Vector3d& v) {
  const auto k = static_cast<std::size_t>(i);
  a.x[k] = v.x(); a.y[k] = v.y(); a.z[k] = v.z();
}

}  // namespace hbm::solver::rigid
