// SPDX-License-Identifier: GPL-3.0-or-later
// hbm-contact-bench: cost of the TYPE7 penalty contact per cycle and per secondary node.
// Two brick blocks (n x n x 4 cubes of 2 mm, outer faces as surfaces) press on each
// other and slide: every top-face node of the lower block is a secondary node against
// the bottom faces of the upper block (and vice versa, symmetric contact), the upper
// block slides at 10 m/s (10 mm/ms) so the search re-sorts regularly. Node motion is
// prescribed (no elements): only the contact is timed. Also times a self-contact
// interface over the whole outer surface of one block (all surface nodes secondary).
// Usage: hbm-contact-bench [n=100] [cycles=2000] [slide speed mm/ms = 10]
#include "contact/contact_surface.hpp"
#include "contact/penalty_contact.hpp"

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>

using namespace hbm::solver;
using namespace hbm::solver::contact;

namespace {

// Thread CPU time [s]: on a loaded machine wall time includes time spent descheduled.
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Blocks {
  NodalState nodes;
  std::vector<SolidForSurface> solids_lo, solids_hi;
  std::size_t n_lo = 0;
};

void add_block(Blocks& b, int n, int layers, double h, double z0, std::vector<SolidForSurface>& out) {
  const int m = n + 1;
  const std::size_t base = b.nodes.x.size();
  for (int k = 0; k <= layers; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        b.nodes.x.x.push_back(i * h);
        b.nodes.x.y.push_back(j * h);
        b.nodes.x.z.push_back(z0 + k * h);
      }
  auto id = [&](int i, int j, int k) { return static_cast<Index>(base + i + m * (j + m * k)); };
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        SolidForSurface s;
        s.nodes = {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                   id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        s.bulk_modulus = 0.01;  // 10 MPa in GPa
        out.push_back(s);
      }
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 100;
  const int cycles = argc > 2 ? std::atoi(argv[2]) : 2000;
  const double h = 2.0, dt = 1.5e-3, gap = 0.2;
  Blocks b;
  add_block(b, n, 4, h, 0.0, b.solids_lo);
  b.n_lo = b.nodes.x.x.size();
  add_block(b, n, 4, h, 4 * h + 0.15, b.solids_hi);  // 0.15 apart: inside the gap
  const std::size_t nn = b.nodes.x.x.size();
  NodalState& s = b.nodes;
  {
    Vec3Soa x = s.x;
    s.resize(nn);
    s.x = x;
    s.x0 = x;
    for (std::size_t i = 0; i < nn; ++i) s.mass0[i] = s.mass[i] = 1e-5;
  }
  ContactSurface lo = solid_outer_faces(b.solids_lo, s.x0.x, s.x0.y, s.x0.z);
  ContactSurface hi = solid_outer_faces(b.solids_hi, s.x0.x, s.x0.y, s.x0.z);
  // Secondary nodes: top layer of the lower block, bottom layer of the upper block.
  const int m = n + 1;
  std::vector<Index> top_lo, bottom_hi, surf_lo_nodes;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      top_lo.push_back(static_cast<Index>(i + m * (j + m * 4)));
      bottom_hi.push_back(static_cast<Index>(b.n_lo + i + m * j));
    }
  {
    std::vector<std::uint8_t> mark(nn, 0);
    for (const auto& q : lo.nodes)
      for (Index i : q) mark[static_cast<std::size_t>(i)] = 1;
    for (std::size_t i = 0; i < nn; ++i)
      if (mark[i]) surf_lo_nodes.push_back(static_cast<Index>(i));
  }
  PenaltyContactParams p;
  p.gapmin = gap;
  p.fric = 0.2;
  p.fixed_dt = dt;
  PenaltyContact c1(hi, top_lo, p, s), c2(lo, bottom_hi, p, s), self(lo, surf_lo_nodes, p, s);
  const std::size_t n_sec = top_lo.size() + bottom_hi.size();

  using clock = std::chrono::steady_clock;
  double t_contact = 0, t_self = 0, c_contact = 0, c_self = 0;
  const double v_slide = argc > 3 ? std::atof(argv[3]) : 10.0;  // mm/ms
  for (int k = 0; k < cycles; ++k) {
    for (std::size_t i = b.n_lo; i < nn; ++i) {
      s.v.x[i] = v_slide;
      s.x.x[i] += dt * v_slide;
    }
    s.force.fill(0);
    const auto t0 = clock::now();
    const double u0 = cpu_seconds();
    c1.add_forces(s, k * dt, dt);
    c2.add_forces(s, k * dt, dt);
    const auto t1 = clock::now();
    const double u1 = cpu_seconds();
    self.add_forces(s, k * dt, dt);
    const auto t2 = clock::now();
    const double u2 = cpu_seconds();
    c_contact += u1 - u0;
    c_self += u2 - u1;
    t_contact += std::chrono::duration<double>(t1 - t0).count();
    t_self += std::chrono::duration<double>(t2 - t1).count();
  }
  std::printf("hbm-contact-bench: two blocks %dx%dx4 bricks each, %d cycles, dt %.3g ms, slide %.0f mm/ms\n",
              n, n, cycles, dt, v_slide);
  std::printf("  block-on-block (2 interfaces): %zu secondary nodes, %zu + %zu segments, %zu + %zu sorts, "
              "%zu active\n", n_sec, hi.size(), lo.size(), c1.n_sorts(), c2.n_sorts(),
              static_cast<std::size_t>(c1.resultant().n_active + c2.resultant().n_active));
  std::printf("    candidates per secondary node %8.2f\n",
              double(c1.n_candidates() + c2.n_candidates()) / double(n_sec));
  std::printf("    contact time per cycle      %10.1f us wall  %10.1f us cpu\n", 1e6 * t_contact / cycles,
              1e6 * c_contact / cycles);
  std::printf("    per secondary node-cycle    %10.1f ns wall  %10.1f ns cpu\n", 1e9 * t_contact / cycles / n_sec,
              1e9 * c_contact / cycles / n_sec);
  std::printf("  self-contact of the lower block's outer surface: %zu secondary nodes, %zu segments, %zu sorts\n",
              surf_lo_nodes.size(), lo.size(), self.n_sorts());
  std::printf("    contact time per cycle      %10.1f us wall  %10.1f us cpu\n", 1e6 * t_self / cycles,
              1e6 * c_self / cycles);
  std::printf("    per secondary node-cycle    %10.1f ns wall  %10.1f ns cpu\n",
              1e9 * t_self / cycles / surf_lo_nodes.size(), 1e9 * c_self / cycles / surf_lo_nodes.size());
  return 0;
}
