// SPDX-License-Identifier: GPL-3.0-or-later
// Spring kernels in the central-difference cycle (springs_mini_cycle.hpp), fixed step
// 1.5e-3 ms, units kg mm ms (kN):
//  - spring-mass (TYPE4, K = 10 kN/mm, m = 1 kg): period 2 pi sqrt(m/K) within 0.5 %;
//  - torsion spring (TYPE8 RX and TYPE13 torsion, K = 50 kN mm/rad on a node of
//    inertia J = 2 kg mm^2): period 2 pi sqrt(J/K) within 0.5 %;
//  - damping (TYPE4, zeta = 0.05): logarithmic decrement 2 pi zeta / sqrt(1 - zeta^2)
//    within 1 % and damped period T / sqrt(1 - zeta^2) within 0.5 %;
//  - nonlinear elastic spring (H=0) driven at constant speed: force equals the curve at
//    every cycle (1e-12), and a mass on it conserves KE + spring energy (1e-4).
#include "springs_mini_cycle.hpp"

#include "springs/spring_group_factory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace hbm::solver;
using namespace hbm::solver::springs;
using hbm::solver::testing::MiniCycle;

namespace {

// Node 0 fixed (no mass), node 1 free at (l0, 0, 0) with mass m and inertia J.
void two_node_model(MiniCycle& c, double l0, double m, double J) {
  c.init_nodes(2);
  c.nodes.x0.x[1] = c.nodes.x.x[1] = l0;
  c.nodes.mass0[1] = m;
  c.nodes.inertia0[1] = J;
  c.nodes.has_rotation[1] = J > 0;
  c.finish_build();
}

// Times of the upward zero crossings of a sampled signal (linear interpolation).
std::vector<double> up_crossings(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<double> out;
  for (std::size_t i = 1; i < y.size(); ++i)
    if (y[i - 1] < 0 && y[i] >= 0) out.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-y[i - 1]) / (y[i] - y[i - 1]));
  return out;
}

double mean_period(const std::vector<double>& z) {
  return (z.back() - z.front()) / static_cast<double>(z.size() - 1);
}

}  // namespace

TEST(SpringOscillator, SpringMassPeriod) {
  const double K = 10.0, m = 1.0;
  MiniCycle c;
  two_node_model(c, 100.0, m, 0.0);
  SpringProperty p;
  p.type = SpringType::Axial;
  p.dofs.resize(1);
  p.dofs[0].K = K;
  auto g = make_spring_group(p, 0, {0, 1}, {1}, c.nodes);
  c.groups.push_back(g.get());
  c.nodes.v.x[1] = 1.0;  // 1 m/s
  std::vector<double> t, y;
  for (int i = 0; i < 8000; ++i) {  // 12 ms, 6 periods
    c.step();
    t.push_back(c.time);
    y.push_back(c.nodes.x.x[1] - 100.0);
  }
  const double T = mean_period(up_crossings(t, y));
  const double T_exact = 2.0 * M_PI * std::sqrt(m / K);
  std::printf("spring-mass period %.6f ms, analytic %.6f ms, error %.2e\n", T, T_exact, T / T_exact - 1);
  EXPECT_NEAR(T, T_exact, 0.005 * T_exact);
}

TEST(SpringOscillator, TorsionSpringPeriodType8AndType13) {
  const double K = 50.0, J = 2.0;
  const double T_exact = 2.0 * M_PI * std::sqrt(J / K);
  for (SpringType type : {SpringType::General, SpringType::Beam}) {
    MiniCycle c;
    two_node_model(c, 10.0, 1.0, J);
    SpringProperty p;
    p.type = type;
    p.dofs.resize(6);
    p.dofs[3].K = K;  // RX only: free in every other DOF
    auto g = make_spring_group(p, 0, {0, 1}, {1}, c.nodes);
    c.groups.push_back(g.get());
    c.nodes.omega.x[1] = 0.5;  // rad/ms
    std::vector<double> t, y;
    for (int i = 0; i < 5000; ++i) {
      c.step();
      t.push_back(c.time);
      y.push_back(g->out_def[0][3]);
    }
    const double T = mean_period(up_crossings(t, y));
    std::printf("TYPE%d torsion period %.6f ms, analytic %.6f ms, error %.2e\n",
                static_cast<int>(type), T, T_exact, T / T_exact - 1);
    EXPECT_NEAR(T, T_exact, 0.005 * T_exact);
  }
}

TEST(SpringOscillator, DampingGivesTheAnalyticDecay) {
  const double K = 10.0, m = 1.0, zeta = 0.05;
  const double C = 2.0 * zeta * std::sqrt(K * m);
  MiniCycle c;
  two_node_model(c, 50.0, m, 0.0);
  SpringProperty p;
  p.type = SpringType::Axial;
  p.dofs.resize(1);
  p.dofs[0].K = K;
  p.dofs[0].C = C;
  auto g = make_spring_group(p, 0, {0, 1}, {1}, c.nodes);
  c.groups.push_back(g.get());
  c.nodes.v.x[1] = 1.0;
  std::vector<double> t, y, peaks, peak_t;
  for (int i = 0; i < 8000; ++i) {
    c.step();
    t.push_back(c.time);
    y.push_back(c.nodes.x.x[1] - 50.0);
    const std::size_t k = y.size();
    if (k >= 3 && y[k - 2] > y[k - 3] && y[k - 2] >= y[k - 1] && y[k - 2] > 0) {
      // Parabolic peak through the three samples.
      const double a = 0.5 * (y[k - 3] - 2 * y[k - 2] + y[k - 1]), b = 0.5 * (y[k - 1] - y[k - 3]);
      peaks.push_back(y[k - 2] - b * b / (4 * a));
      peak_t.push_back(t[k - 2] - b / (2 * a) * c.dt);
    }
  }
  ASSERT_GE(peaks.size(), 5u);
  const int n = static_cast<int>(peaks.size()) - 1;
  const double decrement = std::log(peaks.front() / peaks.back()) / n;
  const double decrement_exact = 2.0 * M_PI * zeta / std::sqrt(1.0 - zeta * zeta);
  const double Td = (peak_t.back() - peak_t.front()) / n;
  const double Td_exact = 2.0 * M_PI * std::sqrt(m / K) / std::sqrt(1.0 - zeta * zeta);
  std::printf("damping: log decrement %.6f (analytic %.6f), damped period %.6f (analytic %.6f)\n",
              decrement, decrement_exact, Td, Td_exact);
  EXPECT_NEAR(decrement, decrement_exact, 0.01 * decrement_exact);
  EXPECT_NEAR(Td, Td_exact, 0.005 * Td_exact);
}

TEST(SpringOscillator, NonlinearSpringFollowsItsFunction) {
  // Stiffening curve (kN vs mm), extrapolated linearly beyond 4 mm.
  const std::vector<double> fx{-4, -2, -1, 0, 1, 2, 4}, fy{-12, -3, -0.8, 0, 0.8, 3, 12};
  MiniCycle c;
  two_node_model(c, 20.0, 0.0, 0.0);  // node 1 massless: driven
  SpringProperty p;
  p.type = SpringType::Axial;
  p.dofs.resize(1);
  p.dofs[0].K = 1.0;
  p.dofs[0].f1 = {fx.data(), fy.data(), fx.size()};
  auto g = make_spring_group(p, 0, {0, 1}, {1}, c.nodes);
  c.groups.push_back(g.get());
  const CurveView f = p.dofs[0].f1;
  double max_err = 0;
  for (int i = 0; i < 4000; ++i) {
    const double v = (i < 2000) ? 3.0 : -3.0;  // mm/ms: 0 -> 9 mm -> 0
    c.nodes.v.x[1] = v;
    c.step();
    const double delta_n = c.nodes.x.x[1] - c.dt * v - 20.0;  // deformation at t^n
    max_err = std::max(max_err, std::abs(g->out_force[0][0] - f(delta_n)) / 12.0);
  }
  std::printf("nonlinear spring: max |F - f(delta)| / f_max = %.2e\n", max_err);
  EXPECT_LT(max_err, 1e-12);

  // Dynamics: 0.5 kg on the same spring, launched at 4 mm/ms.
  MiniCycle d;
  two_node_model(d, 20.0, 0.5, 0.0);
  auto g2 = make_spring_group(p, 0, {0, 1}, {1}, d.nodes);
  d.groups.push_back(g2.get());
  d.nodes.v.x[1] = 4.0;
  d.step();
  const double E0 = d.kinetic + g2->element_energy(0);
  double max_drift = 0;
  for (int i = 0; i < 20000; ++i) {
    d.step();
    max_drift = std::max(max_drift, std::abs(d.kinetic + g2->element_energy(0) - E0) / E0);
  }
  std::printf("nonlinear spring-mass: max |dE|/E0 = %.2e\n", max_drift);
  EXPECT_LT(max_drift, 1e-4);
}
