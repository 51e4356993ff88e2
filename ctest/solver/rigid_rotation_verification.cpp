// SPDX-License-Identifier: GPL-3.0-or-later
// Rigid body rotation, verified through the /RBODY constraint in the central-difference
// cycle (springs_mini_cycle.hpp), fixed step 1.5e-3 ms as in the body model:
//  - free tumbling of an asymmetric body (I = 500, 1000, 1300 x 0.08 kg mm^2 per unit):
//    over 1e5 cycles the angular momentum and the kinetic energy stay within 1e-6
//    relative of their initial values (exact invariants of the free rigid body), and
//    the body stays rigid (node distances to 1e-10);
//  - intermediate-axis (Dzhanibekov) instability: spun about the intermediate axis with
//    a 1e-6 perturbation the body flips; the perturbation grows at the analytic rate
//    lambda = Omega sqrt((I3 - I2)(I2 - I1) / (I1 I3)) (3 %); spun about the minor or the
//    major axis it stays within 1e-4 of the spin axis.
#include "springs_mini_cycle.hpp"

#include "rigid/rigid_body.hpp"
#include "rigid/rigid_rotation.hpp"

#include <gtest/gtest.h>

#include <cmath>

using hbm::solver::Index;
using hbm::solver::rigid::RigidBody;
using hbm::solver::testing::MiniCycle;

namespace {

// A 3x3x3 lattice of 10 g nodes with spacings 10, 20, 30 mm plus a main node at its
// centre, as one rigid body with initial angular velocity w0 (global axes, rad/ms).
struct Tumbler {
  MiniCycle cyc;
  RigidBody body;
  explicit Tumbler(const Eigen::Vector3d& w0_principal) {
    const int n = 3;
    cyc.init_nodes(n * n * n + 1);
    std::size_t k = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int l = 0; l < n; ++l, ++k) {
          cyc.nodes.x0.x[k] = cyc.nodes.x.x[k] = 10.0 * i + 5.0;
          cyc.nodes.x0.y[k] = cyc.nodes.x.y[k] = 20.0 * j - 3.0;
          cyc.nodes.x0.z[k] = cyc.nodes.x.z[k] = 30.0 * l + 1.0;
          cyc.nodes.mass0[k] = 0.01;
          body.secondary.push_back(static_cast<Index>(k));
        }
    body.main = static_cast<Index>(k);
    body.id = 1;
    body.assemble(cyc.nodes, 0.0, Eigen::Matrix3d::Zero(), true, false);
    cyc.finish_build();
    // Initial rigid velocity field v = w0 x r with w0 given in the principal frame.
    const Eigen::Vector3d w0 = body.Q * w0_principal;
    const Eigen::Vector3d c(cyc.nodes.x.x[k], cyc.nodes.x.y[k], cyc.nodes.x.z[k]);
    for (Index s : body.secondary) {
      const auto i = static_cast<std::size_t>(s);
      const Eigen::Vector3d r = Eigen::Vector3d(cyc.nodes.x.x[i], cyc.nodes.x.y[i], cyc.nodes.x.z[i]) - c;
      const Eigen::Vector3d v = w0.cross(r);
      cyc.nodes.v.x[i] = v.x(); cyc.nodes.v.y[i] = v.y(); cyc.nodes.v.z[i] = v.z();
    }
    cyc.constraints.push_back(&body);
  }
  Eigen::Vector3d body_omega() const {  // angular velocity in the principal frame
    return body.principal.cwiseInverse().cwiseProduct(body.Q.transpose() * body.L);
  }
};

}  // namespace

TEST(RigidRotation, FreeTumblingConservesEnergyAndAngularMomentum) {
  // 20..50 rad/s about a generic axis.
  Tumbler t(Eigen::Vector3d(0.03, -0.02, 0.05));
  t.cyc.step();
  const Eigen::Vector3d L0 = t.body.L;
  const double E0 = t.body.kinetic_energy();
  ASSERT_GT(E0, 0.0);
  const double d01 = std::hypot(t.cyc.nodes.x.x[0] - t.cyc.nodes.x.x[26],
                                std::hypot(t.cyc.nodes.x.y[0] - t.cyc.nodes.x.y[26],
                                           t.cyc.nodes.x.z[0] - t.cyc.nodes.x.z[26]));
  double max_e = 0, max_l = 0, max_node_e = 0, max_node_l = 0, max_cycle_e = 0;
  const double tol = 1e-6;
  for (int c = 1; c < 100000; ++c) {
    t.cyc.step();
    max_e = std::max(max_e, std::abs(t.body.kinetic_energy() / E0 - 1.0));
    max_l = std::max(max_l, (t.body.L - L0).norm() / L0.norm());
    // Energy as the engine accounts it: main node 0.5 m v^2 + 0.5 inertia omega^2.
    max_cycle_e = std::max(max_cycle_e, std::abs(t.cyc.kinetic / E0 - 1.0));
    if (c % 1000 == 0) {
      // Energy seen through the nodes: 0.5 sum m_s |v_s|^2 of the secondaries.
      double e = 0;
      for (Index s : t.body.secondary) {
        const auto i = static_cast<std::size_t>(s);
        e += 0.5 * t.cyc.nodes.mass0[i] * (t.cyc.nodes.v.x[i] * t.cyc.nodes.v.x[i] +
                                           t.cyc.nodes.v.y[i] * t.cyc.nodes.v.y[i] +
                                           t.cyc.nodes.v.z[i] * t.cyc.nodes.v.z[i]);
      }
      max_node_e = std::max(max_node_e, std::abs(e / E0 - 1.0));
      // Angular momentum seen through the nodes: sum m_s r_s x v_s about the centre, at
      // the mid-step positions r = x^n + dt/2 v^{n+1/2} - (same for the main node).
      const auto m = static_cast<std::size_t>(t.body.main);
      const double h = 0.5 * t.cyc.dt;
      const Eigen::Vector3d cm(t.cyc.nodes.x.x[m] - h * t.cyc.nodes.v.x[m],
                               t.cyc.nodes.x.y[m] - h * t.cyc.nodes.v.y[m],
                               t.cyc.nodes.x.z[m] - h * t.cyc.nodes.v.z[m]);
      Eigen::Vector3d ln = Eigen::Vector3d::Zero();
      for (Index s : t.body.secondary) {
        const auto i = static_cast<std::size_t>(s);
        const Eigen::Vector3d v(t.cyc.nodes.v.x[i], t.cyc.nodes.v.y[i], t.cyc.nodes.v.z[i]);
        const Eigen::Vector3d x(t.cyc.nodes.x.x[i], t.cyc.nodes.x.y[i], t.cyc.nodes.x.z[i]);
        ln += t.cyc.nodes.mass0[i] * (x - h * v - cm).cross(v);
      }
      max_node_l = std::max(max_node_l, (ln - L0).norm() / L0.norm());
    }
  }
  const double d01_end = std::hypot(t.cyc.nodes.x.x[0] - t.cyc.nodes.x.x[26],
                                    std::hypot(t.cyc.nodes.x.y[0] - t.cyc.nodes.x.y[26],
                                               t.cyc.nodes.x.z[0] - t.cyc.nodes.x.z[26]));
  std::printf("tumbling 1e5 cycles: max |dE/E| body %.3e, nodes %.3e; max |dL|/|L| body %.3e, "
              "nodes %.3e; engine-accounted energy %.3e; rigidity %.3e\n", max_e, max_node_e, max_l,
              max_node_l, max_cycle_e,
              std::abs(d01_end / d01 - 1.0));
  EXPECT_LT(max_e, tol);
  EXPECT_LT(max_node_e, tol);
  EXPECT_LT(max_l, tol);
  EXPECT_LT(max_node_l, tol);
  EXPECT_LT(max_cycle_e, tol);
  EXPECT_LT(std::abs(d01_end / d01 - 1.0), 1e-10);
}

namespace {

// Spin Omega about principal axis `axis` with a relative perturbation eps on the other
// two; returns the largest relative deviation of the body angular velocity from the
// spin axis over `cycles`, and (for the intermediate axis) the measured growth rate.
struct SpinResult { double max_dev = 0; double growth = 0; bool flipped = false; };

SpinResult spin(int axis, double omega, double eps, int cycles) {
  Eigen::Vector3d w = Eigen::Vector3d::Constant(eps * omega);
  w(axis) = omega;
  Tumbler t(w);
  SpinResult r;
  double t_small = -1, t_large = -1;
  for (int c = 0; c < cycles; ++c) {
    t.cyc.step();
    const Eigen::Vector3d wb = t.body_omega();
    double dev = 0;
    for (int a = 0; a < 3; ++a)
      if (a != axis) dev += wb(a) * wb(a);
    dev = std::sqrt(dev) / omega;
    r.max_dev = std::max(r.max_dev, dev);
    if (t_small < 0 && dev > 1e-4) t_small = t.cyc.time;
    if (t_large < 0 && dev > 1e-2) t_large = t.cyc.time;
    if (wb(axis) < 0) r.flipped = true;
  }
  if (t_small > 0 && t_large > 0) r.growth = std::log(100.0) / (t_large - t_small);
  return r;
}

}  // namespace

TEST(RigidRotation, IntermediateAxisFlipsAtTheAnalyticRate) {
  const double omega = 0.2, eps = 1e-6;  // rad/ms
  Tumbler probe(Eigen::Vector3d::Zero());
  const Eigen::Vector3d I = probe.body.principal;  // ascending
  const double lambda = omega * std::sqrt((I(2) - I(1)) * (I(1) - I(0)) / (I(0) * I(2)));
  const int cycles = static_cast<int>((std::log(1.0 / eps) + 4.0) / lambda / 1.5e-3);
  const SpinResult mid = spin(1, omega, eps, cycles);
  std::printf("intermediate axis: growth %.5f /ms, analytic %.5f /ms, flipped %d, %d cycles\n",
              mid.growth, lambda, mid.flipped, cycles);
  EXPECT_TRUE(mid.flipped);
  EXPECT_NEAR(mid.growth, lambda, 0.03 * lambda);
  const SpinResult minor = spin(0, omega, eps, cycles);
  const SpinResult major = spin(2, omega, eps, cycles);
  std::printf("minor axis max deviation %.3e, major axis %.3e\n", minor.max_dev, major.max_dev);
  EXPECT_FALSE(minor.flipped);
  EXPECT_FALSE(major.flipped);
  EXPECT_LT(minor.max_dev, 1e-4);
  EXPECT_LT(major.max_dev, 1e-4);
}
