// SPDX-License-Identifier: GPL-3.0-or-later
// Radioss spring DOF law (spring_dof_law.hpp), driven by prescribed deformation
// histories; every expected value follows from the law's definition:
// linear K delta + C delta_dot; nonlinear elastic force equal to the curve (and its
// linear extrapolation); elastoplastic unloading with slope K and permanent set
// (H=1 isotropic, H=2 decoupled); kinematic band (H=4); hysteresis (H=7); logarithmic
// rate factor; failure; trapezoidal energy equal to the exact integral of F d delta.
#include "springs/spring_dof_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace hbm::solver::springs;

namespace {

struct Curve {
  std::vector<double> x, y;
  CurveView view() const { return {x.data(), y.data(), x.size()}; }
};

// Drive the DOF through deformations d[i] with step dt and return the last force.
double drive(const SpringDofLaw& law, SpringDofState& s, double from, double to, int n, double dt = 1e-3) {
  double f = 0;
  for (int i = 1; i <= n; ++i) f = spring_dof_force(law, s, from + (to - from) * i / n, dt);
  return f;
}

}  // namespace

TEST(SpringDofLaw, LinearStiffnessAndDamping) {
  SpringDofLaw law;
  law.K = 20.0;  // kN/mm
  law.C = 0.5;   // kN ms/mm
  SpringDofState s;
  EXPECT_DOUBLE_EQ(spring_dof_force(law, s, 0.0, 0.0), 0.0);
  // delta 0 -> 0.01 mm in 1e-3 ms: rate 10 mm/ms.
  EXPECT_NEAR(spring_dof_force(law, s, 0.01, 1e-3), 20.0 * 0.01 + 0.5 * 10.0, 1e-12);
  // Linear law ignores A (Radioss: A, B, E only scale nonlinear curves).
  law.A = 3.0;
  SpringDofState s2;
  EXPECT_NEAR(spring_dof_force(law, s2, 0.02, 0.0), 20.0 * 0.02, 1e-14);
}

TEST(SpringDofLaw, NonlinearElasticFollowsTheCurve) {
  const Curve c{{-1.0, 0.0, 0.5, 2.0}, {-3.0, 0.0, 1.0, 1.5}};  // mm -> kN
  SpringDofLaw law;
  law.f1 = c.view();
  law.A = 2.0;
  law.Ascale = 2.0;  // curve abscissa is delta / 2
  SpringDofState s;
  for (double d : {-3.0, -1.0, 0.3, 1.0, 2.5, 4.0, 6.0}) {
    const double x = d / 2.0;
    double expect;
    if (x <= 0.0) expect = 3.0 * x;                        // segment (-1,-3)-(0,0), extrapolated below
    else if (x <= 0.5) expect = 2.0 * x;
    else expect = 1.0 + (x - 0.5) / 3.0;                   // (0.5,1)-(2,1.5), extrapolated above
    EXPECT_NEAR(spring_dof_force(law, s, d, 0.0), 2.0 * expect, 1e-12) << "delta " << d;
  }
}

TEST(SpringDofLaw, IsotropicHardeningUnloadsWithSlopeKAndKeepsPermanentSet) {
  // Yield curve f(x) = 1 + 0.5 x for x > 0 (kN, mm), symmetric; K = 10 kN/mm.
  const Curve c{{-10.0, -0.1, 0.1, 10.0}, {-5.95, -1.0, 1.0, 5.95}};
  SpringDofLaw law;
  law.f1 = c.view();
  law.H = Hardening::Isotropic;
  law.K = 10.0;
  SpringDofState s;
  const double f_load = drive(law, s, 0.0, 2.0, 2000);
  // On the curve at the equivalent displacement x = plastic + F/K = delta (monotonic).
  EXPECT_NEAR(f_load, c.view()(2.0), 1e-9);
  // Unload by 0.05 mm: elastic, slope K.
  const double f_un = drive(law, s, 2.0, 1.95, 50);
  EXPECT_NEAR(f_un, f_load - 10.0 * 0.05, 1e-9);
  // Unload to zero force: permanent set delta_p = 2 - f_load / K.
  const double d_zero = 2.0 - f_load / 10.0;
  EXPECT_NEAR(drive(law, s, 1.95, d_zero, 50), 0.0, 1e-9);
  // Isotropic: compressive yield is raised to -f at the accumulated equivalent
  // displacement, so a small compression stays elastic with slope K.
  EXPECT_NEAR(drive(law, s, d_zero, d_zero - 0.1, 50), -1.0, 1e-9);
}

TEST(SpringDofLaw, DecoupledHardeningHasAGapBetweenPermanentSets) {
  const Curve c{{-10.0, 0.0, 10.0}, {-10.0, 0.0, 10.0}};  // f = delta (kN/mm)
  SpringDofLaw law;
  law.f1 = c.view();
  law.H = Hardening::Decoupled;
  law.K = 4.0;
  SpringDofState s;
  EXPECT_NEAR(drive(law, s, 0.0, 2.0, 200), 2.0, 1e-12);        // on the curve
  // Unloading: F = K (delta - set_t), set_t = 2 - 2/4 = 1.5.
  EXPECT_NEAR(drive(law, s, 2.0, 1.8, 20), 4.0 * (1.8 - 1.5), 1e-12);
  EXPECT_NEAR(drive(law, s, 1.8, 0.5, 20), 0.0, 1e-15);         // in the gap
  EXPECT_NEAR(drive(law, s, 0.5, -1.0, 20), -1.0, 1e-12);       // compression on the curve
  EXPECT_NEAR(drive(law, s, -1.0, 1.0, 40), 0.0, 1e-15);        // back in the gap
}

TEST(SpringDofLaw, KinematicHardeningStaysInTheBand) {
  const Curve up{{-10.0, 10.0}, {1.0, 3.0}};     // upper 2 + 0.1 delta
  const Curve low{{-10.0, 10.0}, {-3.0, -1.0}};  // lower -2 + 0.1 delta
  SpringDofLaw law;
  law.f1 = up.view();
  law.f3 = low.view();
  law.H = Hardening::Kinematic;
  law.K = 10.0;
  SpringDofState s;
  EXPECT_NEAR(drive(law, s, 0.0, 1.0, 100), 2.1, 1e-12);  // capped by the upper curve
  // Reverse by 0.3 mm: elastic, 2.1 - 3.0 = -0.9 (inside the band).
  EXPECT_NEAR(drive(law, s, 1.0, 0.7, 30), -0.9, 1e-12);
  EXPECT_NEAR(drive(law, s, 0.7, 0.0, 70), -2.0, 1e-12);  // on the lower curve
}

TEST(SpringDofLaw, HysteresisLoadsOnF1AndUnloadsOnF3) {
  const Curve load{{0.0, 1.0, 10.0}, {0.0, 2.0, 2.0}};
  const Curve unload{{0.0, 10.0}, {0.0, 1.0}};  // 0.1 delta
  SpringDofLaw law;
  law.f1 = load.view();
  law.f3 = unload.view();
  law.H = Hardening::Hysteresis;
  law.K = 20.0;
  SpringDofState s;
  EXPECT_NEAR(drive(law, s, 0.0, 3.0, 300), 2.0, 1e-12);
  EXPECT_NEAR(drive(law, s, 3.0, 2.95, 5), 1.0, 1e-12);          // elastic drop K * 0.05
  EXPECT_NEAR(drive(law, s, 2.95, 1.0, 200), 0.1, 1e-12);        // on the unloading curve
}

TEST(SpringDofLaw, LogarithmicRateEffect) {
  const Curve c{{0.0, 10.0}, {0.0, 10.0}};
  SpringDofLaw law;
  law.f1 = c.view();
  law.A = 1.0;
  law.B = 0.2;
  law.D = 0.5;  // mm/ms
  SpringDofState s;
  spring_dof_force(law, s, 0.0, 0.0);
  // rate 0.01 / 0.002 = 5 mm/ms -> factor 1 + 0.2 ln(10).
  EXPECT_NEAR(spring_dof_force(law, s, 0.01, 0.002), 0.01 * (1.0 + 0.2 * std::log(10.0)), 1e-14);
}

TEST(SpringDofLaw, FailureAtDeltaMax) {
  SpringDofLaw law;
  law.K = 1.0;
  law.delta_max = 1.0;
  SpringDofState s;
  EXPECT_NEAR(drive(law, s, 0.0, 0.99, 99), 0.99, 1e-12);
  EXPECT_EQ(drive(law, s, 0.99, 1.01, 2), 0.0);
  EXPECT_TRUE(s.broken);
  EXPECT_EQ(drive(law, s, 1.01, 0.5, 5), 0.0);
}

TEST(SpringDofLaw, EnergyIsTheIntegralOfForce) {
  // Elastic curve f = delta^2 sampled finely; energy to delta = 1 is 1/3, and returns
  // to ~0 after unloading (elastic).
  Curve c;
  for (int i = 0; i <= 1000; ++i) { c.x.push_back(i * 1e-3); c.y.push_back(i * 1e-3 * i * 1e-3); }
  SpringDofLaw law;
  law.f1 = c.view();
  SpringDofState s;
  drive(law, s, 0.0, 1.0, 1000);
  EXPECT_NEAR(s.energy, 1.0 / 3.0, 1e-6);
  drive(law, s, 1.0, 0.0, 1000);
  EXPECT_NEAR(s.energy, 0.0, 1e-12);
}
