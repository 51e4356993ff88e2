// SPDX-License-Identifier: GPL-3.0-or-later
// /RWALL/PLANE on rigid-body secondary nodes, end to end through hbm-solver
// (decks/examples/rigid_rwall_impact, written by its make_deck.py): three rigid bodies
// dropped at 5 mm/ms on fixed walls, no gravity, fixed step 1.5e-3 ms.
//  flat box   lands with its 9 bottom nodes at once: after the impact VZ = 0 to round-off
//             (1e-9 mm/ms) and stays there (no rebound), VX = 2 and zero spin kept (1e-9);
//             the wall work equals the kinetic energy lost, 0.5 M 5^2 (1e-9 relative)
//  bars       one brick 40 x 10 x 10 mm, M = 0.04 kg, corner masses M/8, so
//             J = diag(M (b^2 + c^2), M (a^2 + c^2), M (a^2 + b^2)) / 4 in the bar frame,
//             rotated by R = Rx(15 deg) Ry(30 deg); arm a of the lowest corner.
//             Plastic impact (e = 0) at the corner, velocities just after:
//    frictionless (Slide 0): impulse lambda n with
//             lambda = -v.n / (1/M + (a x n) . J^-1 (a x n)), v' = v + lambda n / M,
//             w' = J^-1 (a x lambda n)
//    tied (Slide 1): the corner stops, v' + w' x a = 0; impulse p = -K^-1 v with
//             K = I/M - [a]x J^-1 [a]x (angular momentum about the corner conserved).
//             The impact takes two steps (the corner first lands on the wall, 1 mm being
//             no multiple of v dt), the body turns by |w'| dt in between, and the values are
//             read 3 steps after: tolerance 1e-3 |v0| and 1e-3 |w'| (|w'| dt ~ 3e-4).
//  energy     engine energy error below 1e-6 at every output (the wall work enters W_ext
//             split over the half steps), wall work = kinetic energy lost.
//  threads    time histories bitwise identical with 1 and 2 threads.
#include "example_deck_runner.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

using hbm::solver::testing::read_th;
using hbm::solver::testing::run_deck;
using hbm::solver::testing::ThTable;

namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d S;
  S << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return S;
}

struct Bar {
  double M;
  Eigen::Matrix3d J;
  Eigen::Vector3d arm;  // centre -> lowest corner
};

Bar bar() {
  const double a = 40, b = 10, c = 10, M = 1e-5 * a * b * c;
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(15 * kPi / 180, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(30 * kPi / 180, Eigen::Vector3d::UnitY()))
                                .toRotationMatrix();
  const Eigen::Vector3d jb(M * (b * b + c * c) / 4, M * (a * a + c * c) / 4, M * (a * a + b * b) / 4);
  Bar out{M, R * jb.asDiagonal() * R.transpose(), Eigen::Vector3d::Zero()};
  double zmin = 1e300;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) {
        const Eigen::Vector3d p = R * Eigen::Vector3d(sx * a / 2, sy * b / 2, sz * c / 2);
        if (p.z() < zmin) {
          zmin = p.z();
          out.arm = p;
        }
      }
  return out;
}

Eigen::Vector3d vec(const ThTable& th, const std::string& body, const std::string& q, std::size_t i) {
  return {th.column(body + " " + q + "X")[i], th.column(body + " " + q + "Y")[i], th.column(body + " " + q + "Z")[i]};
}

// First row whose time is at least t.
std::size_t row_at(const std::vector<double>& time, double t) {
  std::size_t i = 0;
  while (i + 1 < time.size() && time[i] < t - 1e-9) ++i;
  return i;
}

class RigidRwallImpact : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const auto out = run_deck("rigid_rwall_impact");
    ASSERT_FALSE(out.empty());
    th_ = new ThTable(read_th(out / "rigid_rwall_impact_TH_RBODY_1.csv"));
  }
  static void TearDownTestSuite() {
    delete th_;
    th_ = nullptr;
  }
  static ThTable* th_;
};
ThTable* RigidRwallImpact::th_ = nullptr;

// Impact of the corners at 1 mm / 5 mm/ms = 0.2 ms (cycle 133.3); read 3 steps after.
constexpr double kAfter = 0.2 + 4 * 1.5e-3;

}  // namespace

TEST_F(RigidRwallImpact, FlatBoxStopsWithoutRebound) {
  ASSERT_NE(th_, nullptr);
  const ThTable& th = *th_;
  const auto t = th.column("time");
  ASSERT_GE(t.back(), 0.499);
  const std::string box = "rbody 1 flat box";
  double vz = 0, dvx = 0, w = 0;
  for (std::size_t i = row_at(t, kAfter); i < t.size(); ++i) {
    vz = std::max(vz, std::abs(vec(th, box, "V", i).z()));
    dvx = std::max(dvx, std::abs(vec(th, box, "V", i).x() - 2.0));
    w = std::max(w, vec(th, box, "W", i).norm());
  }
  const double M = 1e-5 * 20 * 20 * 10;
  const auto ke = th.column(box + " KE");
  const double lost = ke.front() - ke.back();
  std::printf("flat box after impact: max |VZ| %.2e, max |VX - 2| %.2e, max |W| %.2e; KE lost %.9f J "
              "(0.5 M 5^2 = %.9f)\n", vz, dvx, w, lost, 0.5 * M * 25);
  EXPECT_LT(vz, 1e-9);
  EXPECT_LT(dvx, 1e-9);
  EXPECT_LT(w, 1e-9);
  EXPECT_NEAR(lost, 0.5 * M * 25, 1e-9 * lost);
}

TEST_F(RigidRwallImpact, BarCornerImpactsMatchPlasticImpactAtTheCorner) {
  ASSERT_NE(th_, nullptr);
  const ThTable& th = *th_;
  const auto t = th.column("time");
  const std::size_t i = row_at(t, kAfter);
  const Bar b = bar();
  const Eigen::Matrix3d Ji = b.J.inverse();
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ(), v0(0, 0, -5);
  // Frictionless.
  const Eigen::Vector3d an = b.arm.cross(n);
  const double lambda = -v0.dot(n) / (1 / b.M + an.dot(Ji * an));
  const Eigen::Vector3d v_free = v0 + lambda * n / b.M, w_free = Ji * b.arm.cross(lambda * n);
  // Tied.
  const Eigen::Matrix3d K = Eigen::Matrix3d::Identity() / b.M - skew(b.arm) * Ji * skew(b.arm);
  const Eigen::Vector3d p = -K.ldlt().solve(v0);
  const Eigen::Vector3d v_tied = v0 + p / b.M, w_tied = Ji * b.arm.cross(p);
  const std::string free = "rbody 2 bar on frictionless wall", tied = "rbody 3 bar on tied wall";
  const Eigen::Vector3d vf = vec(th, free, "V", i), wf = vec(th, free, "W", i);
  const Eigen::Vector3d vt = vec(th, tied, "V", i), wt = vec(th, tied, "W", i);
  std::printf("t = %.4f ms\n frictionless: V (%.5f %.5f %.5f) analytic (%.5f %.5f %.5f)\n"
              "               W (%.5f %.5f %.5f) analytic (%.5f %.5f %.5f)\n"
              " tied:         V (%.5f %.5f %.5f) analytic (%.5f %.5f %.5f)\n"
              "               W (%.5f %.5f %.5f) analytic (%.5f %.5f %.5f)\n",
              t[i], vf.x(), vf.y(), vf.z(), v_free.x(), v_free.y(), v_free.z(), wf.x(), wf.y(), wf.z(),
              w_free.x(), w_free.y(), w_free.z(), vt.x(), vt.y(), vt.z(), v_tied.x(), v_tied.y(), v_tied.z(),
              wt.x(), wt.y(), wt.z(), w_tied.x(), w_tied.y(), w_tied.z());
  EXPECT_GT(w_free.norm(), 0.05);  // the corner impact does spin the bar
  EXPECT_LT((vf - v_free).norm(), 1e-3 * 5.0);
  EXPECT_LT((wf - w_free).norm(), 1e-3 * w_free.norm());
  EXPECT_LT((vt - v_tied).norm(), 1e-3 * 5.0);
  EXPECT_LT((wt - w_tied).norm(), 1e-3 * w_tied.norm());
  // Tied: the corner is at rest just after the impact (v' + w' x a = 0).
  EXPECT_LT((vt + wt.cross(b.arm)).norm(), 1e-2 * 5.0);
}

TEST_F(RigidRwallImpact, WallWorkEqualsKineticEnergyLost) {
  ASSERT_NE(th_, nullptr);
  const ThTable& th = *th_;
  const auto err = th.column("energy error"), wext = th.column("external work"), kin = th.column("kinetic energy");
  double e = 0;
  for (double x : err) e = std::max(e, std::abs(x));
  std::printf("max |energy error| %.2e; wall work %.9f J, kinetic energy lost %.9f J\n", e, wext.back(),
              kin.front() - kin.back());
  EXPECT_LT(e, 1e-6);
  EXPECT_LT(wext.back(), -1.0);  // the walls did take energy out
  EXPECT_NEAR(-wext.back(), kin.front() - kin.back(), 1e-6 * kin.front());
}

TEST(RigidRwallThreads, BitwiseIdenticalWithOneAndTwoThreads) {
  const auto one = run_deck("rigid_rwall_impact", "--threads 1", "_t1");
  const auto two = run_deck("rigid_rwall_impact", "--threads 2", "_t2");
  ASSERT_FALSE(one.empty());
  ASSERT_FALSE(two.empty());
  for (const std::string f : {"rigid_rwall_impact_TH_RBODY_1.csv", "rigid_rwall_impact_TH_RWALL_2.csv"}) {
    std::stringstream a, b;
    a << std::ifstream(one / f).rdbuf();
    b << std::ifstream(two / f).rdbuf();
    EXPECT_FALSE(a.str().empty());
    EXPECT_TRUE(a.str() == b.str()) << f << " differs between 1 and 2 threads";
  }
}
