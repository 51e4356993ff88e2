// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers of the solid element verifications (HA8 brick, nodal pressure tetra): the body
// model's flesh, the distorted 30 mm patch block driven by a linear velocity field, and the
// cantilever whose first bending frequency is compared with Euler-Bernoulli,
// f1 = (1.8751^2 / 2 pi) sqrt(E' I / (rho A L^4)).
#pragma once

#include "hbm/solver/cycle.hpp"
#include "loads/loads.hpp"
#include "solid/brick_block.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

namespace hbm::solver::testing {

// The body model's flesh: LAW34, K = 128.75 MPa, G0 = 5.15 kPa, Ginf = 1.5 kPa, beta 100 /s.
inline SolidMaterial flesh() {
  SolidMaterial mat;
  mat.rho = 1.02e-6;
  mat.law = SolidLaw::Viscoelastic;
  mat.set_viscoelastic(0.12875, 5.15e-6, 1.5e-6, 0.1);  // K, G0, Ginf [GPa], beta [1/ms]
  return mat;
}

// 3 x 3 x 3 bricks, 30 mm cube.
inline BrickBlock patch_block(const SolidMaterial& mat) {
  BrickBlock b;
  b.nx = b.ny = b.nz = 3;
  b.lx = b.ly = b.lz = 30;
  b.material = mat;
  return b;
}

// Moves the interior nodes of block b by up to 2 mm (fixed pattern), x0 = x.
inline void distort_interior(Model& m, const BrickBlock& b) {
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i) {
    const double x = m.nodes.x.x[i], y = m.nodes.x.y[i], z = m.nodes.x.z[i];
    const double t = 1e-6 * (b.lx + b.ly + b.lz);
    if (x > t && x < b.lx - t && y > t && y < b.ly - t && z > t && z < b.lz - t) {
      m.nodes.x.x[i] += 2.0 * std::sin(0.3 * static_cast<double>(i));
      m.nodes.x.y[i] += 1.5 * std::cos(0.7 * static_cast<double>(i));
      m.nodes.x.z[i] -= 1.8 * std::sin(1.1 * static_cast<double>(i));
    }
  }
  m.nodes.x0 = m.nodes.x;
}

// Puts g (its connectivity set) in place of the block's brick group m.groups[0]: V0 and
// masses on the current positions, lumped nodal masses rho V0 / n, incidence rebuilt.
template <class Group>
Group& replace_block_group(Model& m, std::unique_ptr<Group> g) {
  const std::size_t npe = g->nodes_per_element;
  g->n_elements = g->connectivity.size() / npe;
  EXPECT_EQ(g->initialize(m.nodes), kNoIndex);
  std::fill(m.nodes.mass0.begin(), m.nodes.mass0.end(), 0.0);
  for (std::size_t e = 0; e < g->n_elements; ++e)
    for (std::size_t a = 0; a < npe; ++a)
      m.nodes.mass0[static_cast<std::size_t>(g->connectivity[e * npe + a])] += g->mass[e] / static_cast<double>(npe);
  m.nodes.mass = m.nodes.mass0;
  Group& ref = *g;
  m.groups[0] = std::move(g);
  build_incidence(m);
  return ref;
}

// Largest net force on an interior node of the 30 mm block.
template <class Group>
double max_interior_force(const Model& m, const Group& g) {
  std::vector<double> fx(m.nodes.n_nodes, 0.0), fy = fx, fz = fx;
  for (std::size_t sl = 0; sl < g.connectivity.size(); ++sl) {
    const auto n = static_cast<std::size_t>(g.connectivity[sl]);
    fx[n] += g.slot_force.x[sl];
    fy[n] += g.slot_force.y[sl];
    fz[n] += g.slot_force.z[sl];
  }
  double f = 0.0;
  for (std::size_t i = 0; i < fx.size(); ++i) {
    const double x = m.nodes.x0.x[i], y = m.nodes.x0.y[i], z = m.nodes.x0.z[i];
    if (x > 1 && x < 29 && y > 1 && y < 29 && z > 1 && z < 29)
      f = std::max(f, std::sqrt(fx[i] * fx[i] + fy[i] * fy[i] + fz[i] * fz[i]));
  }
  return f;
}

// Drives the block's group with v = A (x - 15) (A fixed) for n steps of dt.
template <class Group>
void drive_linear(Model& m, Group& g, const double A[3][3], double dt, int n) {
  NodalState& s = m.nodes;
  StepContext step;
  GroupStepResult res;
  for (int k = 0; k <= n; ++k) {
    for (std::size_t i = 0; i < s.n_nodes; ++i) {
      const double r[3] = {s.x.x[i] - 15.0, s.x.y[i] - 15.0, s.x.z[i] - 15.0};
      s.v.x[i] = A[0][0] * r[0] + A[0][1] * r[1] + A[0][2] * r[2];
      s.v.y[i] = A[1][0] * r[0] + A[1][1] * r[1] + A[1][2] * r[2];
      s.v.z[i] = A[2][0] * r[0] + A[2][1] * r[1] + A[2][2] * r[2];
    }
    if (k > 0) {
      for (std::size_t i = 0; i < s.n_nodes; ++i) {
        s.x.x[i] += dt * s.v.x[i];
        s.x.y[i] += dt * s.v.y[i];
        s.x.z[i] += dt * s.v.z[i];
      }
      step.dt_prev = dt;
      step.time += dt;
    }
    g.compute_forces(step, s, res);
  }
}

// Cantilever along x, L = 80, h = 10 (z), width 10 (y): nx x 1 x nz cells, E = 0.2 GPa.
inline BrickBlock cantilever_block(double nu, int nx, int nz) {
  BrickBlock b;
  b.nx = nx;
  b.ny = 1;
  b.nz = nz;
  b.lx = 80;
  b.ly = 10;
  b.lz = 10;
  b.material.rho = 1e-6;
  b.material.set_elastic(0.2, nu);
  return b;
}

// First bending mode of a cantilever clamped at x = 0, length L (Euler-Bernoulli:
// beta L = 1.8751, sigma = 0.7341), unscaled.
inline double cantilever_first_mode(double x, double L) {
  const double beta = 1.8751 / L, sigma = 0.7341, s = beta * x;
  return std::cosh(s) - std::cos(s) - sigma * (std::sinh(s) - std::sin(s));
}

struct BendingResult {
  double f_fem = 0, f_beam = 0, energy_error = 0, hourglass = 0;
  long long cycles = 0;
};

// Clamps the cantilever of block b at x = 0 (y fixed everywhere too if plane_strain),
// starts it in its first beam mode and measures the frequency from two downward zero
// crossings of the tip node (x = L, y = 0, nearest the axis z = 5); f_beam with
// E' = E / (1 - nu^2) in plane strain, E otherwise.
inline BendingResult run_cantilever(Model& m, const BrickBlock& b, bool plane_strain) {
  auto clamp = std::make_unique<FixedDofs>();
  clamp->fixed = {true, true, true, false, false, false};
  auto plane = std::make_unique<FixedDofs>();
  plane->fixed = {false, true, false, false, false, false};
  std::size_t tip = 0;
  const double L = b.lx, v0 = 1e-3;
  auto phi = [&](double x) { return cantilever_first_mode(x, L); };
  const double phi_tip = phi(L);
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i) {
    const double x = m.nodes.x.x[i];
    if (x < 1e-9) clamp->nodes.push_back(static_cast<Index>(i));
    if (plane_strain) plane->nodes.push_back(static_cast<Index>(i));
    m.nodes.v.z[i] = v0 * phi(x) / phi_tip;
    if (x > L - 1e-9 && m.nodes.x.y[i] < 1e-9 &&
        (m.nodes.x.x[tip] < L - 1e-9 || std::abs(m.nodes.x.z[i] - 5.0) < std::abs(m.nodes.x.z[tip] - 5.0)))
      tip = i;
  }
  m.constraints.push_back(std::move(clamp));
  m.constraints.push_back(std::move(plane));
  m.control.dt_scale = 0.9;
  BendingResult r;
  const double nu = b.material.nu, E = b.material.E;
  const double E1 = plane_strain ? E / (1.0 - nu * nu) : E, h = b.lz;
  r.f_beam = 1.8751 * 1.8751 / (2.0 * std::numbers::pi) * std::sqrt(E1 * h * h / (12.0 * b.material.rho * std::pow(L, 4)));
  CycleState c;
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i)
    c.energies.initial_total += 0.5 * m.nodes.mass[i] * m.nodes.v.z[i] * m.nodes.v.z[i];
  std::vector<double> down;
  double z_prev = 0.0, t_prev = 0.0;
  const double t_end = 4.0 / r.f_beam;
  while (c.step.time < t_end) {
    run_cycle(m, c);
    const double zt = m.nodes.x.z[tip] - m.nodes.x0.z[tip];
    const double t = c.step.time;
    if (z_prev > 0.0 && zt <= 0.0) down.push_back(t_prev + (t - t_prev) * z_prev / (z_prev - zt));
    z_prev = zt;
    t_prev = t;
    if (c.stop != StopReason::None || down.size() >= 2) break;
  }
  r.f_fem = down.size() >= 2 ? 1.0 / (down[1] - down[0]) : 0.0;
  r.energy_error = c.energies.energy_error();
  r.hourglass = c.energies.hourglass;
  r.cycles = static_cast<long long>(c.step.cycle);
  return r;
}

// 200 cycles of a 30 x 30 x 15 flesh block of 16 x 16 x 8 cells (2048 bricks: 16 chunks,
// run in parallel) on `threads` threads, from a fixed field of small velocities. `build(m, b)`
// makes the block's group and returns a callable that appends the group's state to a vector.
// Returns nodal x and v_z, that state and the internal energy, for a bitwise comparison.
template <class Build>
std::vector<double> run_block_on_threads(int threads, Build build) {
  omp_set_num_threads(threads);
  Model m;
  BrickBlock b;
  b.nx = 16;
  b.ny = 16;
  b.nz = 8;
  b.lx = b.ly = 30;
  b.lz = 15;
  b.material = flesh();
  auto append_state = build(m, b);
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i) {
    m.nodes.v.x[i] = 1e-3 * std::sin(0.37 * static_cast<double>(i));
    m.nodes.v.y[i] = 1e-3 * std::cos(0.23 * static_cast<double>(i));
    m.nodes.v.z[i] = -2e-3 * std::sin(0.11 * static_cast<double>(i));
  }
  CycleState c;
  for (int k = 0; k < 200; ++k) run_cycle(m, c);
  std::vector<double> out;
  for (std::size_t i = 0; i < m.nodes.n_nodes; ++i) {
    out.push_back(m.nodes.x.x[i]);
    out.push_back(m.nodes.v.z[i]);
  }
  append_state(out);
  out.push_back(c.energies.internal);
  return out;
}

}  // namespace hbm::solver::testing
