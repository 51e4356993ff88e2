// SPDX-License-Identifier: GPL-3.0-or-later
// /DT/BRICK/CST small strain switch (solid/small_strain_switch.hpp) on one brick crushed in
// uniaxial strain: bottom face fixed, top face moving down at speed v, no lateral motion.
//  - before the switch (large strain): sigma_zz = M ln(h / h0), M = lambda + 2G;
//  - the switch happens at the first cycle whose volume ratio h / h0 reaches VDEF_min;
//  - after it the geometry is the one at the switch (height h_s): the strain rate is
//    -v / h_s, so sigma_zz grows linearly, sigma_s - M v (t - t_s) / h_s;
//  - the brick is crushed through zero height without inverting (the control run without
//    the switch stops with an inverted element), and the internal energy equals the work
//    of the nodal forces on the moving top face (trapezoidal rule) throughout.
// Both the one-point brick (Isolid 1/24) and the HA8 brick (Isolid 14) are checked, and a
// 4-node tetra (three nodes on the bottom face, the apex moving down: uniaxial strain as
// well) with the element pressure and with the average nodal pressure (Itetra4 3, whose
// switched tetra counts the volume integrated from its strain rate).
#include "solid/brick_block.hpp"
#include "solid/brick_ha8_group.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace hbm::solver {
namespace {

constexpr double kH0 = 10.0;     // cube edge [mm]
constexpr double kV = 1.0;       // top face speed [mm/ms]
constexpr double kDt = 1e-4;     // [ms]
constexpr double kVdef = 0.6;    // switch at V / V0 <= 0.6

struct CrushResult {
  bool inverted = false;
  int switch_cycle = -1;          // first cycle computed on the frozen geometry
  double h_switch = 0.0;          // height at the switch
  double t_switch = 0.0;
  double sigma_switch = 0.0;      // sigma_zz computed at the switch cycle
  double sigma_end = 0.0, t_end = 0.0, h_end = 0.0;
  double work = 0.0, e_int = 0.0;
  double max_large_strain_error = 0.0;  // |sigma - M ln(h/h0)| / |M ln(h/h0)| before the switch
};

// Drives one 8-node brick group (nodes 0-3 bottom, 4-7 top in make_brick_block's order)
// for n cycles; stress() reads sigma_zz, frozen() says whether the element is switched.
template <class Group, class Stress, class Frozen>
CrushResult crush(Model& m, Group& g, int n, Stress stress, Frozen frozen, double M) {
  NodalState& s = m.nodes;
  StepContext step;
  GroupStepResult res;
  CrushResult r;
  auto top = [&](std::size_t i) { return s.x0.z[i] > 0.5 * kH0; };
  double f_top_old = 0.0;
  for (int k = 0; k <= n; ++k) {
    for (std::size_t i = 0; i < s.n_nodes; ++i) {
      s.v.x[i] = s.v.y[i] = 0.0;
      s.v.z[i] = top(i) ? -kV : 0.0;
    }
    if (k > 0) {
      for (std::size_t i = 0; i < s.n_nodes; ++i) s.x.z[i] += kDt * s.v.z[i];
      step.dt_prev = kDt;
      step.time += kDt;
    }
    const bool was_frozen = frozen();
    res = GroupStepResult{};
    g.compute_forces(step, s, res);
    if (res.inverted_element != kNoIndex) {
      r.inverted = true;
      return r;
    }
    double f_top = 0.0;  // z force of the element on the top nodes
    for (std::size_t sl = 0; sl < g.connectivity.size(); ++sl)
      if (top(static_cast<std::size_t>(g.connectivity[sl]))) f_top += g.slot_force.z[sl];
    if (k > 0) r.work += 0.5 * (f_top_old + f_top) * (-kV) * kDt * -1.0;  // work done ON the brick
    f_top_old = f_top;
    const double h = kH0 - kV * step.time;
    const double sz = stress();
    if (!was_frozen && frozen()) {
      r.switch_cycle = k + 1;
      r.h_switch = h;
      r.t_switch = step.time;
      r.sigma_switch = sz;
    }
    if (!frozen() && k > 0) {
      const double expect = M * std::log(h / kH0);
      r.max_large_strain_error = std::max(r.max_large_strain_error, std::abs(sz - expect) / std::abs(expect));
    }
    r.sigma_end = sz;
    r.t_end = step.time;
    r.h_end = h;
  }
  for (double e : g.e_int) r.e_int += e;
  return r;
}

SolidMaterial elastic() {
  SolidMaterial mat;
  mat.rho = 1e-6;
  mat.law = SolidLaw::Elastic;
  mat.set_elastic(1e-3, 0.3);  // 1 MPa
  return mat;
}

void check(const CrushResult& r, double M, bool switched) {
  ASSERT_FALSE(r.inverted) << "crushed through zero height without inverting";
  ASSERT_EQ(switched, true);
  // Large strain branch: M ln(h/h0) (mid-step gradient: second order in dt).
  EXPECT_LT(r.max_large_strain_error, 1e-6);
  // Switch at the first cycle with h/h0 <= VDEF_min.
  EXPECT_LE(r.h_switch / kH0, kVdef);
  EXPECT_GT(r.h_switch / kH0, kVdef - kV * kDt / kH0 - 1e-12);
  // Small strain branch: linear in time with the frozen height.
  const double expect = r.sigma_switch - M * kV * (r.t_end - r.t_switch) / r.h_switch;
  EXPECT_LT(r.h_end, 0.0) << "the top face passed the bottom face";
  EXPECT_NEAR(r.sigma_end, expect, 1e-9 * std::abs(expect));
  // Energy: internal energy = work of the nodal forces on the brick.
  EXPECT_NEAR(r.e_int, r.work, 1e-6 * std::abs(r.work));
}

constexpr int kCycles = static_cast<int>(1.2 * kH0 / (kV * kDt));  // to h = -0.2 h0

// Crushes group g (one brick) with the switch on or off and checks the result: with it,
// the analytic large- and small-strain stresses and the energy balance; without, the
// control inversion.
template <class Group>
void crush_and_check(Model& m, Group& g, bool enable) {
  const double M = g.material.lambda + 2.0 * g.material.G;
  auto stress = [&] {
    double s[6];
    g.stress(0, s);
    return s[2];
  };
  auto frozen = [&] { return g.frozen_geometry.active() && g.frozen_geometry.frozen[0] != 0; };
  const CrushResult r = crush(m, g, kCycles, stress, frozen, M);
  if (!enable) {
    EXPECT_TRUE(r.inverted) << "control: without /DT/BRICK/CST the brick inverts";
    return;
  }
  check(r, M, frozen());
}

// One kH0 cube of the elastic material (nodes, masses and its one-point group in m).
SolidGroup& make_cube(Model& m) {
  BrickBlock b;
  b.nx = b.ny = b.nz = 1;
  b.lx = b.ly = b.lz = kH0;
  b.material = elastic();
  return make_brick_block(m, b);
}

TEST(SolidSmallStrainSwitch, OnePointBrickCrushedThroughWithoutInverting) {
  for (bool enable : {false, true}) {
    Model m;
    SolidGroup& g = make_cube(m);
    g.qa = g.qb = 0.0;
    g.small_strain.enabled = enable;
    g.small_strain.vdef_min = kVdef;
    if (enable) g.frozen_geometry.allocate(g.n_elements);
    crush_and_check(m, g, enable);
  }
}

TEST(SolidSmallStrainSwitch, Ha8BrickCrushedThroughWithoutInverting) {
  for (bool enable : {false, true}) {
    Model m;
    const SolidGroup& one = make_cube(m);  // nodes and masses; the HA8 group below stands in for it
    BrickHa8Group g;
    g.material = one.material;
    g.connectivity = one.connectivity;
    g.n_elements = 1;
    g.nodes_per_element = 8;
    g.qa = g.qb = 0.0;
    g.small_strain.enabled = enable;
    g.small_strain.vdef_min = kVdef;
    ASSERT_EQ(g.initialize(m.nodes), kNoIndex);
    crush_and_check(m, g, enable);
  }
}

TEST(SolidSmallStrainSwitch, TetraCrushedThroughWithoutInverting) {
  for (bool nodal_pressure : {false, true})
    for (bool enable : {false, true}) {
      Model m;
      const SolidGroup& cube = make_cube(m);  // nodes 0 (0,0,0), 1 (h,0,0), 2 (0,h,0), 4 (0,0,h)
      SolidGroup g;
      g.material = cube.material;
      g.connectivity = {0, 1, 2, 4};
      g.n_elements = 1;
      g.nodes_per_element = 4;
      g.qa = g.qb = 0.0;
      g.nodal_pressure.enabled = nodal_pressure;
      g.small_strain.enabled = enable;
      g.small_strain.vdef_min = kVdef;
      ASSERT_EQ(g.initialize(m.nodes), kNoIndex);
      crush_and_check(m, g, enable);
    }
}

}  // namespace
}  // namespace hbm::solver
