// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers for the contact kernel tests: a NodalState of point masses and a plain
// central-difference loop (f = 0, interactions, a = f/m, v += dt a, x += dt v) so the
// kernels can be checked against closed-form solutions without element groups.
#pragma once

#include "hbm/solver/nodal_state.hpp"

#include <array>
#include <functional>
#include <vector>

namespace hbm::solver::contact::testing {

inline Index add_node(NodalState& n, std::array<double, 3> x, double m,
                      std::array<double, 3> v = {0, 0, 0}) {
  const std::size_t i = n.n_nodes;
  auto grow = [&](Vec3Soa& a, std::array<double, 3> val) {
    a.x.push_back(val[0]);
    a.y.push_back(val[1]);
    a.z.push_back(val[2]);
  };
  grow(n.x0, x);
  grow(n.x, x);
  grow(n.v, v);
  grow(n.a, {0, 0, 0});
  grow(n.force, {0, 0, 0});
  grow(n.force_ext, {0, 0, 0});
  grow(n.contact_force, {0, 0, 0});
  grow(n.omega, {0, 0, 0});
  grow(n.moment, {0, 0, 0});
  n.user_id.push_back(static_cast<std::int64_t>(i + 1));
  n.mass0.push_back(m);
  n.mass.push_back(m);
  n.added_mass.push_back(0);
  n.stiffness.push_back(0);
  n.inertia0.push_back(0);
  n.inertia.push_back(0);
  n.rot_stiffness.push_back(0);
  n.has_rotation.push_back(0);
  n.is_secondary.push_back(0);
  n.n_nodes = i + 1;
  return static_cast<Index>(i);
}

inline double kinetic(const NodalState& n) {
  double e = 0;
  for (std::size_t i = 0; i < n.n_nodes; ++i)
    if (!n.is_secondary[i])
      e += 0.5 * n.mass[i] * (n.v.x[i] * n.v.x[i] + n.v.y[i] * n.v.y[i] + n.v.z[i] * n.v.z[i]);
  return e;
}

inline std::array<double, 3> momentum(const NodalState& n) {
  std::array<double, 3> p{0, 0, 0};
  for (std::size_t i = 0; i < n.n_nodes; ++i) {
    if (n.is_secondary[i]) continue;
    p[0] += n.mass[i] * n.v.x[i];
    p[1] += n.mass[i] * n.v.y[i];
    p[2] += n.mass[i] * n.v.z[i];
  }
  return p;
}

// One central-difference step with fixed nodes (velocity forced to 0).
// `forces(n)` adds every force at t^n (x^n, v^{n-1/2}).
inline void step(NodalState& n, double dt, const std::function<void(NodalState&)>& forces,
                 const std::vector<std::uint8_t>& fixed = {}) {
  n.force.fill(0);
  for (double& k : n.stiffness) k = 0;
  forces(n);
  for (std::size_t i = 0; i < n.n_nodes; ++i) {
    if (!fixed.empty() && fixed[i]) {
      n.v.x[i] = n.v.y[i] = n.v.z[i] = 0;
      continue;
    }
    n.v.x[i] += dt * n.force.x[i] / n.mass[i];
    n.v.y[i] += dt * n.force.y[i] / n.mass[i];
    n.v.z[i] += dt * n.force.z[i] / n.mass[i];
  }
  for (std::size_t i = 0; i < n.n_nodes; ++i) {
    n.x.x[i] += dt * n.v.x[i];
    n.x.y[i] += dt * n.v.y[i];
    n.x.z[i] += dt * n.v.z[i];
  }
}

}  // namespace hbm::solver::contact::testing
