// SPDX-License-Identifier: GPL-3.0-or-later
// TYPE7 penalty kernel on point masses, against closed-form solutions:
// - a node bouncing on a fixed face: penalty spring of stiffness K, so the overshoot
//   past the gap is v0 sqrt(m/K), the contact lasts pi sqrt(m/K), the rebound speed is
//   v0 and the contact energy returns to 0 (central difference, omega dt = 3e-3: the
//   errors are O((omega dt)^2) ~ 1e-5, tolerances 1e-3 relative);
// - a node hitting a free segment: 1-D elastic collision (momentum to round-off, final
//   velocities (m1-m2)/(m1+m2) v0 and 2 m1/(m1+m2) v0);
// - Coulomb friction: sliding under a constant normal load decelerates at mu g; below the
//   Coulomb limit the incremental form (Iform 2) sticks, the viscous form (Iform 1, the
//   OpenRadioss default) creeps at F / (VISF sqrt(2 K m));
// - self-contact of a folded strip: no force from a node's own or neighbouring
//   segments, opposite layers pushed apart with zero resultant;
// - search: no re-sort before some node moved half the margin, re-sort after;
// - fixed-step stiffness cap, Tstart/Tstop, gap from thickness (Igap 1);
// - Inacti 5/6: an initially penetrated node starts without force, its reduced gap grows
//   back as it moves away and is dropped once it is clear.
#include "contact/penalty_contact.hpp"
#include "contact_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace hbm::solver;
using namespace hbm::solver::contact;
using namespace hbm::solver::contact::testing;

namespace {

// A flat quad z = 0, side 2 L centred on the origin, with given nodal masses.
ContactSurface flat_quad(NodalState& n, double L, double m, double k0, bool one_sided,
                         double thickness = 0) {
  ContactSurface s;
  const Index a = add_node(n, {-L, -L, 0}, m), b = add_node(n, {L, -L, 0}, m),
              c = add_node(n, {L, L, 0}, m), d = add_node(n, {-L, L, 0}, m);
  s.nodes.push_back({a, b, c, d});
  s.k0.push_back(k0);
  s.thickness.push_back(thickness);
  s.one_sided.push_back(one_sided ? 1 : 0);
  s.depth.push_back(L);
  return s;
}

// Moves `node` through the (x, z) positions of `path`, one cycle of 1e-3 each, and records
// the z force on it and the contact's elastic energy after each.
void drive_through(PenaltyContact& c, NodalState& n, Index node, const std::vector<std::array<double, 2>>& path,
                   std::vector<double>& fz, std::vector<double>& u) {
  for (std::size_t k = 0; k < path.size(); ++k) {
    n.x.x[node] = path[k][0];
    n.x.z[node] = path[k][1];
    n.force.fill(0);
    c.add_forces(n, 1e-3 * static_cast<double>(k), 1e-3);
    fz.push_back(n.force.z[node]);
    u.push_back(c.elastic_energy());
  }
}

}  // namespace

TEST(ContactPenalty, BounceOnFixedFaceMatchesSpringSolution) {
  NodalState n;
  const double m = 1e-3, K = 100, v0 = 1.0, gap = 0.1, dt = 1e-5;
  ContactSurface s = flat_quad(n, 1.0, 1.0, K, true);
  const Index node = add_node(n, {0.1, 0.2, 0.3}, m, {0, 0, -v0});
  std::vector<std::uint8_t> fixed(n.n_nodes, 0);
  for (int i = 0; i < 4; ++i) fixed[i] = 1;
  PenaltyContactParams p;
  p.gapmin = gap;
  p.vis_s = 0;
  PenaltyContact c(s, {node}, p, n);
  double t = 0, zmin = 1e9, t_in = -1, t_out = -1;
  const double e0 = kinetic(n);
  for (int k = 0; k < 60000 && t_out < 0; ++k) {
    step(n, dt, [&](NodalState& s2) { c.add_forces(s2, t, dt); }, fixed);
    t += dt;
    zmin = std::min(zmin, n.x.z[node]);
    if (t_in < 0 && c.resultant().n_active > 0) t_in = t;
    if (t_in > 0 && t_out < 0 && c.resultant().n_active == 0) t_out = t;
  }
  const double omega = std::sqrt(K / m);
  EXPECT_NEAR(gap - zmin, v0 / omega, 1e-3 * v0 / omega);
  EXPECT_NEAR(t_out - t_in, M_PI / omega, 2 * dt + 1e-3 * M_PI / omega);
  EXPECT_NEAR(n.v.z[node], v0, 1e-3 * v0);
  EXPECT_NEAR(n.v.x[node], 0.0, 1e-12);
  EXPECT_NEAR(-c.work(), 0.0, 1e-3 * e0);  // energy given back
  EXPECT_NEAR(-c.trapezoid_work(), 0.0, 1e-3 * e0);
  EXPECT_NEAR(kinetic(n), e0, 1e-3 * e0);
}

TEST(ContactPenalty, ElasticCollisionWithFreeSegment) {
  NodalState n;
  const double m1 = 1.0, m2 = 2.0, v0 = 2.0, dt = 1e-4;
  ContactSurface s = flat_quad(n, 1.0, m2 / 4, 1e3, false);
  const Index node = add_node(n, {0, 0, 0.5}, m1, {0, 0, -v0});
  PenaltyContactParams p;
  p.gapmin = 0.2;
  p.vis_s = 0;
  p.stmax = 1e3;  // linear-like: K(p) from the shell law is capped, both are conservative
  PenaltyContact c(s, {node}, p, n);
  const auto p0 = momentum(n);
  const double e0 = kinetic(n);
  double t = 0;
  for (int k = 0; k < 20000; ++k) {
    step(n, dt, [&](NodalState& s2) { c.add_forces(s2, t, dt); });
    t += dt;
  }
  const auto p1 = momentum(n);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(p1[d], p0[d], 1e-13 * m1 * v0);
  EXPECT_EQ(c.resultant().n_active, 0);
  EXPECT_NEAR(n.v.z[node], -v0 * (m1 - m2) / (m1 + m2), 1e-3 * v0);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(n.v.z[i], -v0 * 2 * m1 / (m1 + m2), 1e-3 * v0);
  EXPECT_NEAR(kinetic(n), e0, 1e-3 * e0);
}

TEST(ContactPenalty, CoulombFrictionDeceleratesAtMuG) {
  NodalState n;
  const double m = 1.0, g = 9.81e-3, mu = 0.3, K = 1e3, gap = 0.05, dt = 1e-3, v0 = 0.05;
  ContactSurface s = flat_quad(n, 100.0, 1.0, K, true);
  const Index node = add_node(n, {0, 0, gap - m * g / K}, m, {v0, 0, 0});  // at equilibrium
  std::vector<std::uint8_t> fixed(n.n_nodes, 0);
  for (int i = 0; i < 4; ++i) fixed[i] = 1;
  PenaltyContactParams p;
  p.gapmin = gap;
  p.fric = mu;
  p.vis_s = 0;
  PenaltyContact c(s, {node}, p, n);
  double t = 0;
  const int steps = 10000;  // 10 time units: v drops by mu g 10 = 0.029 < v0
  for (int k = 0; k < steps; ++k) {
    step(n, dt, [&](NodalState& s2) {
      s2.force.z[node] -= m * g;
      c.add_forces(s2, t, dt);
    }, fixed);
    t += dt;
  }
  const double decel = (v0 - n.v.x[node]) / t;
  EXPECT_NEAR(decel, mu * g, 1e-3 * mu * g);
  // Friction energy = work of the friction force = mu m g * distance.
  const double dist = n.x.x[node];
  EXPECT_NEAR(c.friction_energy(), mu * m * g * dist, 2e-3 * mu * m * g * dist);
}

// A node of mass m = 1 pressed on a fixed flat quad (K = 1e3, side 2 half_side) by N = 1,
// in equilibrium, and pulled along x by F = 0.8 mu N ramped over `ramp` (mu = 0.5), dt =
// 1e-3 until t_end; after_step(t, n, node, c) after each step.
constexpr double kPullM = 1.0, kPullN = 1.0, kPullMu = 0.5, kPullK = 1e3, kPullF = 0.8 * kPullMu * kPullN;

template <class AfterStep>
void pull_on_plane(PenaltyContactParams p, double half_side, double ramp, double t_end, AfterStep&& after_step) {
  NodalState n;
  const double gap = 0.05, dt = 1e-3;
  ContactSurface s = flat_quad(n, half_side, 1.0, kPullK, true);
  const Index node = add_node(n, {0, 0, gap - kPullN / kPullK}, kPullM);
  std::vector<std::uint8_t> fixed(n.n_nodes, 0);
  for (int i = 0; i < 4; ++i) fixed[i] = 1;
  p.gapmin = gap;
  p.fric = kPullMu;
  p.vis_s = 0.5;
  PenaltyContact c(s, {node}, p, n);
  double t = 0;
  for (int k = 0; k < static_cast<int>(std::lround(t_end / dt)); ++k) {
    step(n, dt, [&](NodalState& s2) {
      s2.force.z[node] -= kPullN;
      s2.force.x[node] += kPullF * std::min(1.0, t / ramp);
      c.add_forces(s2, t, dt);
    }, fixed);
    t += dt;
    after_step(t, n, node, c);
  }
}

TEST(ContactPenalty, IncrementalFrictionSticksBelowTheCoulombLimit) {
  // Iform 2: a tangential pull F = 0.8 mu N, ramped slowly, only stretches the stick
  // spring: the node ends at the static stick displacement F/K (no slip).
  PenaltyContactParams p;
  p.friction_form = 2;
  const double F = kPullF, K = kPullK;
  double x_end = 0, e_end = 0;
  pull_on_plane(p, 10.0, 10.0, 20.0, [&](double, const NodalState& n, Index node, const PenaltyContact& c) {
    x_end = n.x.x[node];
    e_end = c.friction_energy();
  });
  EXPECT_NEAR(x_end, F / K, 0.1 * F / K);
  // Nothing dissipated: the friction energy is what the stick spring stores, F^2/(2K).
  EXPECT_NEAR(e_end, F * F / (2 * K), 0.2 * F * F / (2 * K));
}

TEST(ContactPenalty, ViscousFrictionCreepsBelowTheCoulombLimit) {
  // Iform 1 (OpenRadioss's default, i7for3.F): the friction force is a tangential damper
  // VISF sqrt(2 K m) v_t capped at mu F_n, so a constant pull F below the cap has no
  // static equilibrium: the node creeps at v = F / (VISF sqrt(2 K m)), and all the work of
  // the friction force is dissipated (friction energy = F x creep distance).
  for (const double visf : {1.0, 2.0}) {
    PenaltyContactParams p;
    p.visf = visf;
    const double ramp = 2.0, t_end = 12.0, F = kPullF;
    double x_ramped = 0, e_ramped = 0, x_end = 0, v_end = 0, e_end = 0;
    pull_on_plane(p, 1e3, ramp, t_end, [&](double t, const NodalState& n, Index node, const PenaltyContact& c) {
      if (std::abs(t - 2 * ramp) < 0.5e-3) {
        x_ramped = n.x.x[node];
        e_ramped = c.friction_energy();
      }
      x_end = n.x.x[node];
      v_end = n.v.x[node];
      e_end = c.friction_energy();
    });
    const double v_creep = F / (visf * std::sqrt(2.0 * kPullK * kPullM));
    EXPECT_NEAR(v_end, v_creep, 1e-3 * v_creep) << "VISF " << visf;
    EXPECT_NEAR(x_end - x_ramped, v_creep * (t_end - 2 * ramp), 2e-3 * v_creep * (t_end - 2 * ramp));
    // Every bit of the friction work is dissipated: F x distance once the pull is constant.
    const double w = F * (x_end - x_ramped);
    EXPECT_NEAR(e_end - e_ramped, w, 1e-3 * w) << "VISF " << visf;
  }
}

TEST(ContactPenalty, DampingDissipatesWhatTheNodeLoses) {
  NodalState n;
  const double m = 1e-3, K = 100, v0 = 1.0, dt = 1e-5;
  ContactSurface s = flat_quad(n, 1.0, 1.0, K, true);
  const Index node = add_node(n, {0, 0, 0.2}, m, {0, 0, -v0});
  std::vector<std::uint8_t> fixed(n.n_nodes, 0);
  for (int i = 0; i < 4; ++i) fixed[i] = 1;
  PenaltyContactParams p;
  p.gapmin = 0.1;
  p.vis_s = 0.1;
  PenaltyContact c(s, {node}, p, n);
  const double e0 = kinetic(n);
  double t = 0;
  for (int k = 0; k < 40000; ++k) {
    step(n, dt, [&](NodalState& s2) { c.add_forces(s2, t, dt); }, fixed);
    t += dt;
  }
  ASSERT_EQ(c.resultant().n_active, 0);
  const double e1 = kinetic(n);
  // Linear damped oscillator: restitution exp(-zeta pi / sqrt(1 - zeta^2)) = 0.7292 for
  // zeta = 0.1; the force is kept compressive, which ends contact slightly earlier and
  // gives back a little less: the rebound lies between that value and 1.
  const double e = n.v.z[node] / v0;
  EXPECT_GT(e, 0.7292 - 1e-3);
  EXPECT_LT(e, 0.80);
  // Contact energy (-work) equals the kinetic energy lost (balance, 1e-3).
  EXPECT_NEAR(-c.work(), e0 - e1, 1e-3 * e0);
  EXPECT_NEAR(-c.trapezoid_work(), e0 - e1, 1e-3 * e0);
  EXPECT_NEAR(c.damping_energy(), e0 - e1, 1e-3 * e0);
}

TEST(ContactPenalty, SelfContactOfFoldedStrip) {
  // Strip of 10 unit shell quads (width 1) folded in two: the upper layer lies 0.05
  // above the lower one, the fold is a vertical quad. Gap 0.1: each upper node sees the
  // lower layer (not its neighbour) and is pushed up, and vice versa; nodes at the fold
  // see only neighbours.
  NodalState n;
  ContactSurface s;
  std::vector<Index> lo0, lo1, up0, up1;
  for (int i = 0; i <= 5; ++i) {
    lo0.push_back(add_node(n, {double(i), 0, 0}, 1));
    lo1.push_back(add_node(n, {double(i), 1, 0}, 1));
  }
  for (int i = 0; i <= 5; ++i) {
    up0.push_back(add_node(n, {double(5 - i), 0, 0.05}, 1));
    up1.push_back(add_node(n, {double(5 - i), 1, 0.05}, 1));
  }
  auto quad = [&](Index a, Index b, Index c, Index d) {
    s.nodes.push_back({a, b, c, d});
    s.k0.push_back(10);
    s.thickness.push_back(0.01);
    s.one_sided.push_back(0);
    s.depth.push_back(0);
  };
  for (int i = 0; i < 5; ++i) quad(lo0[i], lo0[i + 1], lo1[i + 1], lo1[i]);
  quad(lo0[5], up0[0], up1[0], lo1[5]);  // the fold
  for (int i = 0; i < 5; ++i) quad(up0[i], up0[i + 1], up1[i + 1], up1[i]);
  std::vector<Index> all;
  for (std::size_t i = 0; i < n.n_nodes; ++i) all.push_back(static_cast<Index>(i));
  PenaltyContactParams p;
  p.gapmin = 0.1;
  p.vis_s = 0;
  PenaltyContact c(s, all, p, n);
  n.force.fill(0);
  c.add_forces(n, 0.0, 0.0);
  double fz_up = 0, fz_lo = 0;
  for (int i = 0; i <= 5; ++i) {
    fz_up += n.force.z[up0[i]] + n.force.z[up1[i]];
    fz_lo += n.force.z[lo0[i]] + n.force.z[lo1[i]];
    // Node x = 0 of the upper layer sits above x = 0 of the lower: pushed up.
  }
  EXPECT_GT(fz_up, 0);
  EXPECT_LT(fz_lo, 0);
  EXPECT_NEAR(fz_up + fz_lo, 0.0, 1e-12 * fz_up);
  EXPECT_GT(c.resultant().n_active, 0);
  // Every force is along z (layers are parallel): no in-plane push from neighbours.
  for (std::size_t i = 0; i < n.n_nodes; ++i) {
    EXPECT_NEAR(n.force.x[i], 0.0, 1e-12);
    EXPECT_NEAR(n.force.y[i], 0.0, 1e-12);
  }
  // Unfolded flat strip: no contact at all (only neighbours within the gap).
  NodalState f;
  ContactSurface fs;
  std::vector<Index> a0, a1;
  for (int i = 0; i <= 10; ++i) {
    a0.push_back(add_node(f, {0.5 * i, 0, 0}, 1));
    a1.push_back(add_node(f, {0.5 * i, 0.5, 0}, 1));
  }
  for (int i = 0; i < 10; ++i) {
    fs.nodes.push_back({a0[i], a0[i + 1], a1[i + 1], a1[i]});
    fs.k0.push_back(10);
    fs.thickness.push_back(0.01);
    fs.one_sided.push_back(0);
    fs.depth.push_back(0);
  }
  std::vector<Index> fall;
  for (std::size_t i = 0; i < f.n_nodes; ++i) fall.push_back(static_cast<Index>(i));
  PenaltyContact cf(fs, fall, p, f);
  cf.add_forces(f, 0.0, 0.0);
  EXPECT_EQ(cf.resultant().n_active, 0);
}

TEST(ContactPenalty, ResortOnlyAfterHalfMarginDisplacement) {
  NodalState n;
  ContactSurface s = flat_quad(n, 1.0, 1.0, 10, true);
  const Index node = add_node(n, {0, 0, 3.0}, 1.0);
  PenaltyContactParams p;
  p.gapmin = 0.1;
  p.margin = 0.4;
  PenaltyContact c(s, {node}, p, n);
  EXPECT_EQ(c.n_sorts(), 1u);
  EXPECT_EQ(c.n_candidates(), 0u);  // 3.0 above: beyond gap + margin
  n.x.z[node] = 3.0 - 0.19;         // moved less than margin / 2
  c.add_forces(n, 0, 0);
  EXPECT_EQ(c.n_sorts(), 1u);
  n.x.z[node] = 0.45;               // moved more: re-sort, within gap + margin: candidate
  c.add_forces(n, 0, 0);
  EXPECT_EQ(c.n_sorts(), 2u);
  EXPECT_EQ(c.n_candidates(), 1u);
}

TEST(ContactPenalty, StiffnessCapKeepsTheFixedStep) {
  // With a fixed step, K <= 2 f m (Tsca/dt)^2; the node's nodal step with the contact
  // alone is Tsca sqrt(2 m / K) >= dt / sqrt(f).
  NodalState n;
  const double m = 1e-6, dt = 1.5e-3, tsca = 0.9;
  ContactSurface s = flat_quad(n, 1.0, 1.0, 1e9, true);
  const Index node = add_node(n, {0, 0, 0.05}, m);
  PenaltyContactParams p;
  p.gapmin = 0.1;
  p.fixed_dt = dt;
  p.tsca = tsca;
  p.cap_fraction = 0.5;
  PenaltyContact c(s, {node}, p, n);
  n.force.fill(0);
  c.add_forces(n, 0, 0);
  const double cap = 2 * 0.5 * m * (tsca / dt) * (tsca / dt);
  EXPECT_NEAR(n.stiffness[node], cap, 1e-12 * cap);
  EXPECT_NEAR(n.force.z[node], cap * 0.05, 1e-12 * cap);
}

TEST(ContactPenalty, TstartTstopAndVariableGap) {
  NodalState n;
  ContactSurface s = flat_quad(n, 1.0, 1.0, 10, false, /*thickness=*/0.4);
  const Index node = add_node(n, {0, 0, 0.25}, 1.0);
  PenaltyContactParams p;
  p.igap = 1;
  p.gapmin = 0.01;
  p.tstart = 1.0;
  p.tstop = 2.0;
  p.stmax = 10;  // K = Kp = 10 in the whole range (law capped at Kp)
  p.vis_s = 0;
  PenaltyContact c(s, {node}, p, n, /*node_gap=*/{0.1});
  EXPECT_NEAR(c.gap_of_pair(0, 0), 0.3, 1e-15);  // t_main/2 + gs
  n.force.fill(0);
  c.add_forces(n, 0.5, 0);
  EXPECT_EQ(n.force.z[node], 0.0);
  c.add_forces(n, 1.5, 0);
  EXPECT_NEAR(n.force.z[node], 10 * (0.3 - 0.25), 1e-12);
  n.force.fill(0);
  c.add_forces(n, 2.5, 0);
  EXPECT_EQ(n.force.z[node], 0.0);
}

TEST(ContactPenalty, ShellLawStiffensTowardsMidSurface) {
  // K(p) = Kp g/(g-p): F(g/2) = Kp g; potential is the integral of F.
  const double kp = 2, g = 0.5, kmax = 1e9;
  EXPECT_NEAR(PenaltyContact::law_force(0.25, g, kp, kmax, false), kp * g, 1e-14);
  const double h = 1e-6, p = 0.3;
  const double dU = (PenaltyContact::law_energy(p + h, g, kp, kmax, false) -
                     PenaltyContact::law_energy(p - h, g, kp, kmax, false)) / (2 * h);
  EXPECT_NEAR(dU, PenaltyContact::law_force(p, g, kp, kmax, false), 1e-6);
  // Tangent-capped branch: beyond pt = g (1 - sqrt(kp/kmax)), where dF/dp = kp g^2/(g-p)^2
  // reaches kmax, F goes on with slope kmax: F(p) = F(pt) + kmax (p - pt).
  const double km = 10.0, pt = g * (1 - std::sqrt(kp / km));
  EXPECT_NEAR(PenaltyContact::law_tangent_limit(g, kp, km), pt, 1e-15);
  const double f_pt = kp * g * pt / (g - pt);
  EXPECT_NEAR(PenaltyContact::law_force(0.45, g, kp, km, false), f_pt + km * (0.45 - pt), 1e-12);
  for (double q : {0.1, pt - 1e-4, pt + 1e-4, 0.45, 0.6}) {  // 0.6: past the mid-surface
    const double dF = (PenaltyContact::law_force(q + h, g, kp, km, false) -
                       PenaltyContact::law_force(q - h, g, kp, km, false)) / (2 * h);
    EXPECT_NEAR(PenaltyContact::law_stiffness(q, g, kp, km, false), dF, 1e-5 * km) << "p = " << q;
    EXPECT_LE(dF, km * (1 + 1e-6)) << "p = " << q;
    const double dUq = (PenaltyContact::law_energy(q + h, g, kp, km, false) -
                        PenaltyContact::law_energy(q - h, g, kp, km, false)) / (2 * h);
    EXPECT_NEAR(dUq, PenaltyContact::law_force(q, g, kp, km, false), 1e-6) << "p = " << q;
  }
}

TEST(ContactPenalty, SoftShellContactAtTheMidSurfaceStaysBounded) {
  // The clavicle-skin contact of the body model: kp 5e-4 kN/mm, kmax 271 kN/mm (fixed-step
  // cap of a 0.75 g node), gap 1 mm. A node at the mid-surface (p = g) feels
  // F(pt) + kmax (g - pt) < 2 g sqrt(kp kmax) (0.74 kN), not kmax g (271 kN).
  const double kp = 5e-4, kmax = 271.2, g = 1.0;
  const double f = PenaltyContact::law_force(g, g, kp, kmax, false);
  EXPECT_GT(f, g * std::sqrt(kp * kmax));
  EXPECT_LT(f, 2 * g * std::sqrt(kp * kmax));
  EXPECT_EQ(PenaltyContact::law_stiffness(g, g, kp, kmax, false), kmax);
}

// Inacti 6 (OpenRadioss): a node 0.2 above a shell with gap 0.5 (P0 = 0.3) gets the gap
// Gap - P0 - 5 % (Gap - P0) = 0.19, so no force at t = 0; pushed 0.05 further in it feels
// the law at p = 0.19 - 0.15 with that gap; the gap follows it out (0.95 d) and is dropped
// beyond the full gap, after which the full law applies. Inacti 0 pushes at once.
TEST(ContactPenalty, InactiSixStartsPenetratedNodesWithoutForce) {
  const double kp = 100, g = 0.5, kmax = 100 * kp;
  auto run = [&](int inacti, const std::vector<double>& z, std::vector<double>& fz, std::vector<double>& u) {
    NodalState n;
    ContactSurface s = flat_quad(n, 1.0, 1.0, kp, false);
    const Index node = add_node(n, {0.1, -0.2, z.front()}, 1e-3);
    PenaltyContactParams p;
    p.gapmin = g;
    p.vis_s = 0;
    p.inacti = inacti;
    PenaltyContact c(s, {node}, p, n);
    for (std::size_t k = 0; k < z.size(); ++k) {
      n.x.z[node] = z[k];
      n.force.fill(0);
      c.add_forces(n, 1e-3 * static_cast<double>(k), 1e-3);
      fz.push_back(n.force.z[node]);
      u.push_back(c.elastic_energy());
    }
  };
  const std::vector<double> z = {0.2, 0.15, 0.3, 0.25, 0.6, 0.4};
  std::vector<double> f6, u6, f0, u0, f5, u5;
  run(6, z, f6, u6);
  EXPECT_EQ(f6[0], 0.0);
  EXPECT_EQ(u6[0], 0.0);
  const double g6 = 0.95 * 0.2;
  EXPECT_NEAR(f6[1], PenaltyContact::law_force(g6 - 0.15, g6, kp, kmax, false), 1e-12);
  EXPECT_NEAR(u6[1], PenaltyContact::law_energy(g6 - 0.15, g6, kp, kmax, false), 1e-15);
  EXPECT_EQ(f6[2], 0.0);  // out at 0.3: the gap follows, 0.95 x 0.3 = 0.285
  // back in to 0.25: inside the raised gap 0.285 (it never shrinks back)
  EXPECT_NEAR(f6[3], PenaltyContact::law_force(0.285 - 0.25, 0.285, kp, kmax, false), 1e-12);
  EXPECT_EQ(f6[4], 0.0);  // 0.6: clear of the full gap, reduction dropped
  EXPECT_NEAR(f6[5], PenaltyContact::law_force(g - 0.4, g, kp, kmax, false), 1e-12);
  run(0, z, f0, u0);
  EXPECT_NEAR(f0[0], PenaltyContact::law_force(g - 0.2, g, kp, kmax, false), 1e-12);
  run(5, z, f5, u5);
  EXPECT_EQ(f5[0], 0.0);
  EXPECT_NEAR(f5[1], PenaltyContact::law_force(0.2 - 0.15, 0.2, kp, kmax, false), 1e-12);
}

// Inacti 6 during the run: a node that slides in past the edge of a shell (gap 0.5) at
// 0.1 above it would find itself 0.4 deep in one cycle; it is treated as an initial
// penetration (gap 0.95 d, no force, no potential made from nothing) and then feels the law
// with that gap as it goes deeper. A node approaching the face along its normal by less
// than PenaltyContact::kEntryJump g per cycle gets the full law; Inacti 0 pushes the
// entering node at once.
TEST(ContactPenalty, InactiSixTreatsAnEntryPastTheEdgeAsInitialPenetration) {
  const double kp = 100, g = 0.5, kmax = 100 * kp;
  std::size_t entries = 0;
  auto run = [&](int inacti, const std::vector<std::array<double, 2>>& xz, std::vector<double>& fz,
                 std::vector<double>& u) {
    NodalState n;
    ContactSurface s = flat_quad(n, 1.0, 1.0, kp, false);
    const Index node = add_node(n, {xz.front()[0], 0.0, xz.front()[1]}, 1e-3);
    PenaltyContactParams p;
    p.gapmin = g;
    p.vis_s = 0;
    p.inacti = inacti;
    PenaltyContact c(s, {node}, p, n);
    drive_through(c, n, node, xz, fz, u);
    entries = c.n_entry_caps();
  };
  const std::vector<std::array<double, 2>> slide = {{2.0, 0.1}, {1.02, 0.1}, {0.9, 0.1}, {0.9, 0.085}};
  std::vector<double> f6, u6, f0, u0;
  run(6, slide, f6, u6);
  EXPECT_EQ(f6[0], 0.0);
  EXPECT_EQ(entries, 1u) << "one entry treated as initial penetration";
  EXPECT_EQ(f6[1], 0.0) << "entry past the edge: no force";
  EXPECT_EQ(u6[1], 0.0) << "entry past the edge: no potential";
  EXPECT_EQ(f6[2], 0.0);
  const double d_entry = std::hypot(0.02, 0.1), g6 = 0.95 * d_entry;
  EXPECT_NEAR(f6[3], PenaltyContact::law_force(g6 - 0.085, g6, kp, kmax, false), 1e-12);
  run(0, slide, f0, u0);
  // normal from the closest point on the edge: z share 0.1 / d
  EXPECT_NEAR(f0[1], PenaltyContact::law_force(g - d_entry, g, kp, kmax, false) * 0.1 / d_entry, 1e-9);
  EXPECT_GT(u0[1], 0.0);
  // A solid face (one-sided, linear law): a node that slides in under it, 0.1 behind the face,
  // gets the gap 0.95 x (-0.1), no force at the entry, then the small push the law gives at
  // p = 0.005 (as an initially penetrated node would).
  {
    NodalState n;
    ContactSurface s = flat_quad(n, 1.0, 1.0, kp, true);
    const Index node = add_node(n, {2.0, 0.0, -0.1}, 1e-3);
    PenaltyContactParams p;
    p.gapmin = g;
    p.vis_s = 0;
    p.inacti = 6;
    PenaltyContact c(s, {node}, p, n);
    std::vector<double> fs;
    for (double xk : {2.0, 0.9, 0.9}) {
      n.x.x[node] = xk;
      n.force.fill(0);
      c.add_forces(n, 1e-3 * static_cast<double>(fs.size()), 1e-3);
      fs.push_back(n.force.z[node]);
    }
    EXPECT_EQ(fs[1], 0.0) << "entry under a solid face: no force";
    EXPECT_NEAR(fs[2], PenaltyContact::law_force(0.95 * -0.1 + 0.1, 0.95 * -0.1, kp, kmax, true), 1e-12);
    EXPECT_GT(fs[2], 0.0) << "pushed back out of the solid";
  }
  const std::vector<std::array<double, 2>> approach = {{0.0, 0.6}, {0.0, 0.52}, {0.0, 0.44}, {0.0, 0.36}};
  std::vector<double> fa, ua;
  run(6, approach, fa, ua);
  EXPECT_EQ(entries, 0u) << "an approach is not an entry";
  EXPECT_NEAR(fa[2], PenaltyContact::law_force(g - 0.44, g, kp, kmax, false), 1e-12);
  EXPECT_NEAR(fa[3], PenaltyContact::law_force(g - 0.36, g, kp, kmax, false), 1e-12);
}

// Inacti 6 during the run, a change of closest segment: a node rests 0.4 deep in the 0.5 gap
// of a soft solid face (k0 1) and slides, at that depth, onto the neighbouring face of a
// stiffer element (k0 100). Its penalty potential would jump from 0.5 x 1 x 0.4^2 to
// 0.5 x 100 x 0.4^2 (+7.92) with no work done: treated as an initial penetration (gap 0.95 d,
// no force, no potential). Between two faces of the same stiffness the slide is seamless.
TEST(ContactPenalty, InactiSixTreatsASwitchToAStifferSegmentAsAnEntry) {
  const double g = 0.5, depth = 0.4;
  auto run = [&](double k_second, int inacti, std::vector<double>& fz, std::vector<double>& u, std::size_t& entries) {
    NodalState n;
    // Two unit faces side by side (x in [-1, 0] and [0, 1]), one-sided, normal +z.
    ContactSurface s;
    const Index a = add_node(n, {-1, -1, 0}, 1.0), b = add_node(n, {0, -1, 0}, 1.0), c = add_node(n, {0, 1, 0}, 1.0),
                d = add_node(n, {-1, 1, 0}, 1.0), e = add_node(n, {1, -1, 0}, 1.0), f = add_node(n, {1, 1, 0}, 1.0);
    s.nodes.push_back({a, b, c, d});
    s.nodes.push_back({b, e, f, c});
    s.k0 = {1.0, k_second};
    s.thickness = {0, 0};
    s.one_sided = {1, 1};
    s.depth = {1.0, 1.0};
    const Index node = add_node(n, {-0.5, 0.0, 0.6}, 1e-3);
    PenaltyContactParams p;
    p.gapmin = g;
    p.vis_s = 0;
    p.fric = 0;
    p.inacti = inacti;
    PenaltyContact ct(s, {node}, p, n);
    // Approach in steps of 0.01 (no entry), then slide across x = 0 at the same depth.
    std::vector<std::array<double, 2>> path;
    for (double z = 0.6; z > g - depth + 1e-9; z -= 0.01) path.push_back({-0.5, z});
    for (double x : {-0.2, -0.02, 0.02, 0.2}) path.push_back({x, g - depth});
    drive_through(ct, n, node, path, fz, u);
    entries = ct.n_entry_caps();
  };
  std::vector<double> f, u;
  std::size_t entries = 0;
  run(100.0, 6, f, u, entries);
  const std::size_t last = f.size() - 1;
  EXPECT_NEAR(u[last - 2], 0.5 * 1.0 * depth * depth, 1e-12) << "on the soft face, 0.4 deep";
  EXPECT_EQ(entries, 1u);
  EXPECT_EQ(u[last - 1], 0.0) << "on the stiff face: no potential made from nothing";
  EXPECT_EQ(f[last - 1], 0.0);
  std::vector<double> f0, u0;
  run(100.0, 0, f0, u0, entries);
  EXPECT_NEAR(u0[last - 1], 0.5 * 100.0 * depth * depth, 1e-9) << "Inacti 0: the jump the rule removes";
  std::vector<double> fe, ue;
  run(1.0, 6, fe, ue, entries);
  EXPECT_EQ(entries, 0u) << "same stiffness: no entry";
  EXPECT_NEAR(ue[last - 1], 0.5 * 1.0 * depth * depth, 1e-12);
  EXPECT_NEAR(fe[last - 1], 1.0 * depth, 1e-12);
}
