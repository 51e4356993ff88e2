// SPDX-License-Identifier: GPL-3.0-or-later
// TYPE2 kinematic tie on point masses: projection weights, mass lumping (total mass
// unchanged), force transfer and dependent velocity. With arbitrary forces on every
// node, the momentum change over a step equals the total impulse to round-off and the
// tied node keeps following the segment point.
#include "contact/tied_contact.hpp"
#include "contact_test_support.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace hbm::solver;
using namespace hbm::solver::contact;
using namespace hbm::solver::contact::testing;

TEST(ContactTied, ProjectionLumpingAndMomentum) {
  NodalState n;
  const Index a = add_node(n, {0, 0, 0}, 1.0), b = add_node(n, {2, 0, 0}, 2.0),
              c = add_node(n, {2, 2, 0}, 3.0), d = add_node(n, {0, 2, 0}, 4.0);
  const Index s = add_node(n, {0.5, 0.5, 0.01}, 0.8);
  const Index far = add_node(n, {0.5, 0.5, 5.0}, 0.1);
  ContactSurface surf;
  surf.nodes.push_back({a, b, c, d});
  surf.k0.push_back(1);
  surf.thickness.push_back(0);
  surf.one_sided.push_back(1);
  surf.depth.push_back(1);
  std::vector<Index> untied;
  TiedContact tie(5, "glue", surf, {s, far}, 0.1, n, untied);
  ASSERT_EQ(tie.links().size(), 1u);
  ASSERT_EQ(untied, std::vector<Index>{far});
  const TiedLink& l = tie.links()[0];
  double wsum = 0;
  V3 xp{};
  for (int k = 0; k < 4; ++k) {
    wsum += l.weight[k];
    xp += l.weight[k] * V3{n.x.x[l.main[k]], n.x.y[l.main[k]], n.x.z[l.main[k]]};
  }
  EXPECT_NEAR(wsum, 1.0, 1e-15);
  EXPECT_NEAR(xp.x, 0.5, 1e-15);
  EXPECT_NEAR(xp.y, 0.5, 1e-15);
  EXPECT_NEAR(l.distance, 0.01, 1e-15);

  const double m_total = 1 + 2 + 3 + 4 + 0.8 + 0.1;
  tie.transfer_mass(n);
  double m_free = 0;
  for (std::size_t i = 0; i < n.n_nodes; ++i)
    if (!n.is_secondary[i]) m_free += n.mass[i];
  EXPECT_NEAR(m_free, m_total, 1e-14);
  EXPECT_EQ(n.is_secondary[s], 1);

  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  const double dt = 1e-3;
  StepContext st;
  st.dt_next = dt;
  for (int k = 0; k < 100; ++k) {
    const auto p0 = momentum(n);
    n.force.fill(0);
    V3 total{};
    for (std::size_t i = 0; i < n.n_nodes; ++i) {
      n.force.x[i] = u(rng);
      n.force.y[i] = u(rng);
      n.force.z[i] = u(rng);
      total += V3{n.force.x[i], n.force.y[i], n.force.z[i]};
    }
    tie.gather_forces(st, n);
    for (std::size_t i = 0; i < n.n_nodes; ++i) {
      if (n.is_secondary[i]) continue;
      n.v.x[i] += dt * n.force.x[i] / n.mass[i];
      n.v.y[i] += dt * n.force.y[i] / n.mass[i];
      n.v.z[i] += dt * n.force.z[i] / n.mass[i];
    }
    tie.impose_dependent(st, n);
    for (std::size_t i = 0; i < n.n_nodes; ++i) {
      n.x.x[i] += dt * n.v.x[i];
      n.x.y[i] += dt * n.v.y[i];
      n.x.z[i] += dt * n.v.z[i];
    }
    const auto p1 = momentum(n);
    EXPECT_NEAR(p1[0] - p0[0], dt * total.x, 1e-15);
    EXPECT_NEAR(p1[1] - p0[1], dt * total.y, 1e-15);
    EXPECT_NEAR(p1[2] - p0[2], dt * total.z, 1e-15);
  }
  // The tied node still sits at the weighted segment point (+ its initial offset).
  V3 xs{};
  for (int k = 0; k < 4; ++k) xs += l.weight[k] * V3{n.x.x[l.main[k]], n.x.y[l.main[k]], n.x.z[l.main[k]]};
  EXPECT_NEAR(n.x.x[s], xs.x, 1e-12);
  EXPECT_NEAR(n.x.y[s], xs.y, 1e-12);
  EXPECT_NEAR(n.x.z[s], xs.z + 0.01, 1e-12);
}
