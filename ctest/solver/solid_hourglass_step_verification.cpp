// SPDX-License-Identifier: GPL-3.0-or-later
// Critical step of the one-point brick's viscous hourglass damper (solid_group.cpp).
// The hourglass force -c sum_a gamma_a (gamma_a . v), c = h rho c_wave V^(2/3) / 4 (FB 1981),
// is a damper; central differences with the force on v^{n-1/2} keep a damped mode of nodal
// mass m and damping eigenvalue lambda stable while dt <= 2 m / lambda (the amplification
// factor of v is 1 - dt lambda / m). Checked here:
//  - a cube keeps the dilatational step 2 L / sqrt((12 lambda + 8 G) / rho) (the damper
//    limit does not bind: its Gram matrix is 8 I);
//  - a brick sheared and stretched out of shape gets the damper limit 2 (m_e / 8) / lambda,
//    lambda = c times the largest absolute row sum of the Gram matrix gamma_a . gamma_b, with
//    gamma computed here from a finite-difference volume gradient;
//  - that brick, free, with an initial hourglass velocity, loses kinetic energy at 0.9 times
//    the step the element reports, and the same motion grows without bound at 1.3 times the
//    exact damper limit of its mode: the step is needed and is not far too small.
#include "solid/brick_block.hpp"
#include "solid/brick_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace hbm::solver {
namespace {

constexpr double kL = 10.0;  // cube edge [mm]

SolidMaterial soft_elastic() {
  SolidMaterial m;
  m.rho = 1.0e-6;          // [kg/mm^3]
  m.set_elastic(1.0e-3, 0.3);  // 1 MPa
  return m;
}

// One brick with the given node coordinates as its reference shape; nodal masses m_e / 8.
SolidGroup& one_brick(Model& m, const std::array<std::array<double, 3>, 8>& x) {
  BrickBlock b;
  b.nx = b.ny = b.nz = 1;
  b.lx = b.ly = b.lz = kL;
  b.material = soft_elastic();
  b.hourglass = HourglassForm::Viscous;
  SolidGroup& g = make_brick_block(m, b);
  for (int i = 0; i < 8; ++i) {
    const auto n = static_cast<std::size_t>(g.connectivity[static_cast<std::size_t>(i)]);
    m.nodes.x0.x[n] = m.nodes.x.x[n] = x[static_cast<std::size_t>(i)][0];
    m.nodes.x0.y[n] = m.nodes.x.y[n] = x[static_cast<std::size_t>(i)][1];
    m.nodes.x0.z[n] = m.nodes.x.z[n] = x[static_cast<std::size_t>(i)][2];
  }
  g.initialize(m.nodes);
  for (int i = 0; i < 8; ++i) {
    const auto n = static_cast<std::size_t>(g.connectivity[static_cast<std::size_t>(i)]);
    m.nodes.mass0[n] = m.nodes.mass[n] = g.mass[0] / 8.0;
  }
  return g;
}

std::array<std::array<double, 3>, 8> cube() {
  std::array<std::array<double, 3>, 8> x{};
  for (int i = 0; i < 8; ++i) x[static_cast<std::size_t>(i)] = {kL * (brick::kXi[i] + 1) / 2, kL * (brick::kEta[i] + 1) / 2,
                                                                  kL * (brick::kZeta[i] + 1) / 2};
  return x;
}

// A 10 x 10 x 2 mm plate whose nodes are moved +-3 mm in z in its xi-eta hourglass pattern
// (kHourglass[2]): positive volume at the centre, faces crossing at the corners, as the
// flesh bricks at the impactor rim of hub_oblique_9p5 (Gram row sums there up to ~10^3).
std::array<std::array<double, 3>, 8> distorted() {
  auto x = cube();
  for (int i = 0; i < 8; ++i)
    x[static_cast<std::size_t>(i)][2] = 0.2 * x[static_cast<std::size_t>(i)][2] + 3.0 * brick::kHourglass[2][i];
  return x;
}

// Hex volume from 24 tetrahedra (centroid, face centre, edge): exact for the trilinear
// brick's faces split at their centres; its gradient by central differences.
double hex_volume(const std::array<std::array<double, 3>, 8>& x) {
  std::array<double, 3> c{};
  for (const auto& p : x)
    for (int k = 0; k < 3; ++k) c[static_cast<std::size_t>(k)] += p[static_cast<std::size_t>(k)] / 8;
  double v = 0;
  for (const auto& f : brick::kFaces) {
    std::array<double, 3> fc{};
    for (int a = 0; a < 4; ++a)
      for (int k = 0; k < 3; ++k) fc[static_cast<std::size_t>(k)] += x[static_cast<std::size_t>(f[a])][static_cast<std::size_t>(k)] / 4;
    for (int a = 0; a < 4; ++a) {
      const auto& p = x[static_cast<std::size_t>(f[a])];
      const auto& q = x[static_cast<std::size_t>(f[(a + 1) % 4])];
      const double u[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]}, w[3] = {q[0] - c[0], q[1] - c[1], q[2] - c[2]},
                   r[3] = {fc[0] - c[0], fc[1] - c[1], fc[2] - c[2]};
      v += (u[0] * (w[1] * r[2] - w[2] * r[1]) - u[1] * (w[0] * r[2] - w[2] * r[0]) + u[2] * (w[0] * r[1] - w[1] * r[0])) / 6;
    }
  }
  return std::abs(v);
}

struct HourglassModes {
  std::array<std::array<double, 8>, 4> gamma{};
  double gram_row_max = 0.0;
};

HourglassModes modes(const std::array<std::array<double, 3>, 8>& x) {
  const double V = hex_volume(x);
  std::array<std::array<double, 3>, 8> B{};
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      auto xp = x, xm = x;
      const double h = 1e-5 * kL;
      xp[i][k] += h;
      xm[i][k] -= h;
      B[i][k] = (hex_volume(xp) - hex_volume(xm)) / (2 * h);
    }
  HourglassModes m;
  for (std::size_t a = 0; a < 4; ++a) {
    double hx[3] = {0, 0, 0};
    for (std::size_t i = 0; i < 8; ++i)
      for (std::size_t k = 0; k < 3; ++k) hx[k] += brick::kHourglass[a][i] * x[i][k];
    for (std::size_t i = 0; i < 8; ++i)
      m.gamma[a][i] = brick::kHourglass[a][i] - (hx[0] * B[i][0] + hx[1] * B[i][1] + hx[2] * B[i][2]) / V;
  }
  for (std::size_t a = 0; a < 4; ++a) {
    double row = 0;
    for (std::size_t b = 0; b < 4; ++b) {
      double g = 0;
      for (std::size_t i = 0; i < 8; ++i) g += m.gamma[a][i] * m.gamma[b][i];
      row += std::abs(g);
    }
    m.gram_row_max = std::max(m.gram_row_max, row);
  }
  return m;
}

double reported_step(Model& m, SolidGroup& g) {
  StepContext step;
  GroupStepResult res;
  g.compute_forces(step, m.nodes, res);
  return res.dt_min;
}

// Damping coefficient c of the viscous form for the brick's present volume.
double damper_coefficient(const SolidGroup& g, double V) {
  const SolidMaterial& mat = g.material;
  return g.hourglass_coef * 0.25 * mat.rho * std::sqrt(mat.wave_modulus() / mat.rho) * std::cbrt(V * V);
}

TEST(SolidHourglassStep, CubeKeepsTheDilatationalStep) {
  Model m;
  SolidGroup& g = one_brick(m, cube());
  const SolidMaterial& mat = g.material;
  const double expect = 2.0 * kL / std::sqrt((12.0 * mat.lambda + 8.0 * mat.G) / mat.rho);
  EXPECT_NEAR(reported_step(m, g), expect, 1e-12 * expect);
  const HourglassModes h = modes(cube());
  EXPECT_NEAR(h.gram_row_max, 8.0, 1e-6);
  const double damper = 2.0 * (g.mass[0] / 8.0) / (damper_coefficient(g, kL * kL * kL) * h.gram_row_max);
  // 1.25 L / c_wave against 2 L / sqrt((12 lambda + 8 G) / rho) (0.59 L / c_wave as nu -> 1/2)
  EXPECT_GT(damper, 1.5 * expect);
}

TEST(SolidHourglassStep, DistortedBrickGetsTheDamperLimit) {
  Model m;
  const auto x = distorted();
  SolidGroup& g = one_brick(m, x);
  const HourglassModes h = modes(x);
  ASSERT_GT(h.gram_row_max, 50.0);  // the shape is far from a parallelepiped (8 for one)
  const double damper = 2.0 * (g.mass[0] / 8.0) / (damper_coefficient(g, hex_volume(x)) * h.gram_row_max);
  EXPECT_NEAR(reported_step(m, g), damper, 1e-6 * damper);
}

// Free brick, initial velocity along x in the hourglass mode with the largest |gamma|^2,
// integrated by central differences at step dt. Returns max KE / KE0 over the run and
// KE_end / KE0.
std::pair<double, double> free_hourglass_motion(double dt_factor_of_reported, double dt_factor_of_mode, int cycles) {
  Model m;
  const auto x = distorted();
  SolidGroup& g = one_brick(m, x);
  const HourglassModes h = modes(x);
  std::size_t am = 0;
  double g2max = 0;
  for (std::size_t a = 0; a < 4; ++a) {
    double s = 0;
    for (double v : h.gamma[a]) s += v * v;
    if (s > g2max) g2max = s, am = a;
  }
  const double mn = g.mass[0] / 8.0;
  double dt = 0;
  if (dt_factor_of_reported > 0) dt = dt_factor_of_reported * reported_step(m, g);
  else dt = dt_factor_of_mode * 2.0 * mn / (damper_coefficient(g, hex_volume(x)) * g2max);
  NodalState& s = m.nodes;
  for (int i = 0; i < 8; ++i) s.v.x[static_cast<std::size_t>(g.connectivity[static_cast<std::size_t>(i)])] = 0.1 * h.gamma[am][static_cast<std::size_t>(i)];
  auto kinetic = [&] {
    double k = 0;
    for (std::size_t n = 0; n < s.n_nodes; ++n) k += 0.5 * s.mass[n] * (s.v.x[n] * s.v.x[n] + s.v.y[n] * s.v.y[n] + s.v.z[n] * s.v.z[n]);
    return k;
  };
  const double ke0 = kinetic();
  double ke_max = ke0;
  StepContext step;
  for (int k = 0; k < cycles; ++k) {
    GroupStepResult res;
    g.compute_forces(step, s, res);
    std::vector<double> f(3 * s.n_nodes, 0.0);
    for (std::size_t sl = 0; sl < g.connectivity.size(); ++sl) {
      const auto n = static_cast<std::size_t>(g.connectivity[sl]);
      f[3 * n] += g.slot_force.x[sl];
      f[3 * n + 1] += g.slot_force.y[sl];
      f[3 * n + 2] += g.slot_force.z[sl];
    }
    for (std::size_t n = 0; n < s.n_nodes; ++n) {
      s.v.x[n] += dt * f[3 * n] / s.mass[n];
      s.v.y[n] += dt * f[3 * n + 1] / s.mass[n];
      s.v.z[n] += dt * f[3 * n + 2] / s.mass[n];
      s.x.x[n] += dt * s.v.x[n];
      s.x.y[n] += dt * s.v.y[n];
      s.x.z[n] += dt * s.v.z[n];
    }
    step.dt_prev = dt;
    step.time += dt;
    ke_max = std::max(ke_max, kinetic());
  }
  return {ke_max / ke0, kinetic() / ke0};
}

TEST(SolidHourglassStep, HourglassMotionDecaysAtTheReportedStep) {
  const auto [ke_max, ke_end] = free_hourglass_motion(0.9, 0.0, 60);
  EXPECT_LE(ke_max, 1.0 + 1e-3);  // a damper and an elastic body only lose kinetic energy
  EXPECT_LT(ke_end, 0.5);
}

TEST(SolidHourglassStep, HourglassMotionGrowsAboveTheDamperLimit) {
  const auto [ke_max, ke_end] = free_hourglass_motion(0.0, 1.3, 20);
  EXPECT_GT(ke_end, 1e3);
}

}  // namespace
}  // namespace hbm::solver
