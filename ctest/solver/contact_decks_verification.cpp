// SPDX-License-Identifier: GPL-3.0-or-later
// Deck-level verification of the contact area: runs hbm-solver on the decks in
// decks/examples/contact_*/ and checks their time histories against analytic values.
//  - contact_blocks_collide: X momentum conserved to the CSV precision (1e-9 relative)
//    at every output; energy balance within 1% at every output; contact energy back to
//    < 1e-3 E0 once the blocks separated.
//  - contact_sphere_rwall: peak wall force within 10% of Hertz, rebound speed >= 0.9 V0
//    (elastic: e = 1 minus the energy left in the sphere's vibrations).
//  - contact_block_slide: deceleration mu g within 2% for TYPE7 friction and for the
//    RWALL with Slide = 2; tangential / normal wall force = mu (0.1%: a node whose
//    tangential velocity stops within a step takes less than mu dv_n).
//  - contact_shell_fold: shell strip thrown onto itself (self-contact, gap = t): the
//    mid-surfaces never cross (distance > 0 at every output) and contact did happen.
//  - contact_tied_bar: reflection at the TYPE2 interface < 2% of the incident pulse,
//    transmitted amplitude within 3% of the control bar's.
//  - contact_moving_wall: a moving /RWALL/PLANE (node, Mass, VX0) strikes a free block:
//    X momentum of wall + block conserved to the CSV precision at every output.
//  - contact_blocks_collide with Stfac and VISs 0, blank, or 1 and 0.05 written out: the
//    same time histories (OpenRadioss reads 0 as the default), and not those of VISs 1e-30.
//  - contact_block_slide with the wall's node group removed (Dsearch 0): no wall node, as in
//    OpenRadioss: zero wall force, block 3 in free fall (VZ = -g t to 1e-6), a warning.
#include "example_deck_runner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace hbm::solver::testing;

namespace {

// Lumped nodal masses of an n x n x n block of bricks of element mass me, in the node
// order of decks/examples/deck_tools/radioss_deck.py Deck.block (i fastest).
std::vector<double> block_masses(int nx, int ny, int nz, double me) {
  std::vector<double> m;
  auto c = [](int a, int n) { return (a == 0 || a == n) ? 1 : 2; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.push_back(c(i, nx) * c(j, ny) * c(k, nz) * me / 8.0);
  return m;
}

#define REQUIRE_SOLVER()                                  \
  do {                                                    \
    if (run_case_skip()) GTEST_SKIP() << "no hbm-solver"; \
  } while (0)
bool run_case_skip() {
#ifdef HBM_SOLVER_EXE
  return false;
#else
  return true;
#endif
}

}  // namespace

TEST(ContactDecks, BlocksCollideConserveMomentumAndEnergy) {
  REQUIRE_SOLVER();
  const std::string name = "contact_blocks_collide";
  const fs::path out = run_deck(name);
  ASSERT_FALSE(out.empty());
  const ThTable nodes = read_th(out / (name + "_TH_NODE_2.csv"));
  const ThTable inter = read_th(out / (name + "_TH_INTER_1.csv"));
  const double h = 10.0 / 6, me = 1e-6 * h * h * h, v0 = 5.0, m_block = 1e-3;
  std::vector<double> m = block_masses(6, 6, 6, me);
  const std::vector<double> mb = m;
  m.insert(m.end(), mb.begin(), mb.end());
  const double p0 = m_block * v0, e0 = 0.5 * m_block * v0 * v0;
  ASSERT_EQ(nodes.header.size(), 9 + m.size());
  for (const auto& r : nodes.rows) {
    double p = 0;
    for (std::size_t i = 0; i < m.size(); ++i) p += m[i] * r[9 + i];
    EXPECT_NEAR(p, p0, 1e-9 * p0) << "t = " << r[0];
  }
  const std::size_t err = inter.col("energy error"), ec = inter.col("contact energy");
  for (const auto& r : inter.rows) EXPECT_LT(std::abs(r[err]), 0.01) << "t = " << r[0];
  const auto& last = inter.rows.back();
  EXPECT_LT(std::abs(last[ec]), 1e-3 * e0);
  EXPECT_EQ(last[inter.col("inter 1 A nodes on B FNX")], 0.0);
  // The VTK frames carry the nodal contact forces (point vector "contact_force"), read
  // back with VTK's own reader: in the frame during the impact (t = 0.1 ms) the forces are
  // non-zero and, being action and reaction between the blocks, sum to zero in X
  // (round-off, 1e-9 of the largest nodal force); before contact (t = 0) they are zero.
  run_python("contact_force_frames.py", R"(import sys, vtk
def frame(path):
    r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(path); r.Update()
    a = r.GetOutput().GetPointData().GetArray('contact_force')
    assert a is not None, 'no contact_force in ' + path
    fx = [a.GetTuple3(i)[0] for i in range(a.GetNumberOfTuples())]
    return sum(fx), max(abs(f) for f in fx)
s0, m0 = frame(sys.argv[1] + '_0000.vtu')
assert m0 == 0.0, m0
s1, m1 = frame(sys.argv[1] + '_0001.vtu')
print('t=0.1 ms: max |fx|', m1, 'sum fx', s1)
assert m1 > 1e-4, m1
assert abs(s1) < 1e-9 * m1, s1
)",
             (out / name).string());
}

// /TH/PART XMOM, MASS and XCG (OpenRadioss names) on the same collision: each block's mass
// is its element mass; the two momenta add up to the initial m v0 at every output while
// block B takes nearly all of it (equal masses, elastic); the lateral momenta the contact
// exchanges cancel; the centre of gravity of the two
// parts moves at the total momentum over the total mass.
TEST(ContactDecks, PartMomentumAndCentreOfGravityFollowTheCollision) {
  REQUIRE_SOLVER();
  const std::string name = "contact_blocks_collide", tag = "part_momentum";
  std::string output;
  const std::string card =
      "/TH/PART/9\nblocks\n      XMOM      YMOM      MASS       XCG\n         1         2\n/END";
  ASSERT_EQ(run_modified_deck(name, tag, "/END", card, output), 0) << output;
  const ThTable t = read_th(modified_deck_dir(tag) / "out" / (name + "_TH_PART_9.csv"));
  const double m_block = 1e-3, v0 = 5.0, p0 = m_block * v0;
  const std::size_t pa = t.col("block A XMOM"), pb = t.col("block B XMOM"), ya = t.col("block A YMOM"),
                    yb = t.col("block B YMOM"), ma = t.col("block A MASS"), mb = t.col("block B MASS"), xa = t.col("block A XCG"),
                    xb = t.col("block B XCG");
  EXPECT_NE(t.header[pa].find("[kN*ms]"), std::string::npos) << t.header[pa];
  EXPECT_NE(t.header[xa].find("[mm]"), std::string::npos) << t.header[xa];
  ASSERT_GT(t.rows.size(), 10u);
  const auto& first = t.rows.front();
  const auto& last = t.rows.back();
  EXPECT_NEAR(first[ma], m_block, 1e-12);
  EXPECT_NEAR(first[mb], m_block, 1e-12);
  EXPECT_NEAR(first[pa], p0, 1e-9 * p0);
  EXPECT_NEAR(first[pb], 0.0, 1e-9 * p0);
  for (const auto& r : t.rows) {
    EXPECT_NEAR(r[pa] + r[pb], p0, 1e-9 * p0) << "t = " << r[0];
    EXPECT_NEAR(r[ya] + r[yb], 0.0, 1e-9 * p0) << "t = " << r[0];  // exchanged, not created
    EXPECT_LT(std::abs(r[ya]), 1e-6 * p0) << "t = " << r[0];          // round-off of a head-on impact
  }
  EXPECT_GT(last[pb], 0.9 * p0);  // the struck block leaves with most of the momentum
  EXPECT_LT(last[pa], 0.1 * p0);
  // centre of gravity of both blocks: x(t) = x(0) + p0 t / (2 m)
  const double x0 = 0.5 * (first[xa] + first[xb]), dt = last[0] - first[0];
  EXPECT_NEAR(0.5 * (last[xa] + last[xb]) - x0, p0 * dt / (2 * m_block), 1e-6 * p0 * dt / m_block);
  EXPECT_LT(first[xa], first[xb]);  // A starts behind B (it moves along +X into B)
}

TEST(ContactDecks, SphereOnRigidWallMatchesHertz) {
  REQUIRE_SOLVER();
  const std::string name = "contact_sphere_rwall";
  const fs::path out = run_deck(name);
  ASSERT_FALSE(out.empty());
  // Hertz, sphere on a rigid plane (Johnson 1985 §11.4); values of make_deck.py.
  const double R = 10, rho = 1e-6, E = 0.01, nu = 0.3, v0 = 1.0;
  const double estar = E / (1 - nu * nu), mass = rho * 4.0 / 3.0 * M_PI * R * R * R;
  const double dmax = std::pow(15 * mass * v0 * v0 / (16 * estar * std::sqrt(R)), 0.4);
  const double fmax = 4.0 / 3.0 * estar * std::sqrt(R) * std::pow(dmax, 1.5);
  const ThTable wall = read_th(out / (name + "_TH_RWALL_1.csv"));
  const std::vector<double> t = wall.column(0), fz = wall.column(wall.col("FNZ"));
  double peak = 0, t_end = 0;
  for (std::size_t k = 0; k < fz.size(); ++k) {
    peak = std::max(peak, std::abs(fz[k]));
    if (std::abs(fz[k]) > 1e-9) t_end = t[k];
  }
  EXPECT_NEAR(peak, fmax, 0.10 * fmax) << "Hertz F_max " << fmax << " kN";
  EXPECT_GT(t_end, 0.0);
  EXPECT_LT(t_end, t.back() - 0.1) << "the sphere must have left the wall";
  const ThTable centre = read_th(out / (name + "_TH_NODE_2.csv"));
  const std::vector<double> tc = centre.column(0), vz = centre.column(centre.col("VZ"));
  double sum = 0;
  int n = 0;
  for (std::size_t k = 0; k < vz.size(); ++k)
    if (tc[k] > t_end + 0.05) sum += vz[k], ++n;
  ASSERT_GT(n, 10);
  const double rebound = sum / n;
  EXPECT_GT(rebound, 0.9 * v0);
  EXPECT_LT(rebound, 1.0 * v0 + 1e-3);
  const std::size_t err = wall.col("energy error");
  EXPECT_LT(std::abs(wall.rows.back()[err]), 0.02);
}

namespace {
// Mass-weighted mean X velocity of a 2x2x2 block (27 nodes) whose VX columns start at c0.
std::vector<double> block_vx(const ThTable& c, const std::vector<std::size_t>& cols) {
  const std::vector<double> w = block_masses(2, 2, 2, 1.0);
  std::vector<double> v;
  double ws = 0;
  for (double x : w) ws += x;
  for (const auto& r : c.rows) {
    double s = 0;
    for (std::size_t i = 0; i < w.size(); ++i) s += w[i] * r[cols[i]];
    v.push_back(s / ws);
  }
  return v;
}
double slope(const std::vector<double>& t, const std::vector<double>& v, double t0, double t1) {
  double st = 0, sv = 0;
  int n = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= t0 && t[k] <= t1) st += t[k], sv += v[k], ++n;
  const double mt = st / n, mv = sv / n;
  double num = 0, den = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= t0 && t[k] <= t1) num += (t[k] - mt) * (v[k] - mv), den += (t[k] - mt) * (t[k] - mt);
  return num / den;
}
}  // namespace

TEST(ContactDecks, BlockSlidingDeceleratesAtMuG) {
  REQUIRE_SOLVER();
  const std::string name = "contact_block_slide";
  const fs::path out = run_deck(name);
  ASSERT_FALSE(out.empty());
  const double mu = 0.3, g = 1.0;
  const ThTable c = read_th(out / (name + "_TH_NODE_3.csv"));
  std::vector<std::size_t> vx;
  for (std::size_t i = 9; i < c.header.size(); ++i)
    if (c.header[i].find(" VX ") != std::string::npos) vx.push_back(i);
  ASSERT_EQ(vx.size(), 54u);
  const std::vector<double> t = c.column(0);
  const std::vector<std::size_t> b2(vx.begin(), vx.begin() + 27), b3(vx.begin() + 27, vx.end());
  // Fit over 0.1-0.8 ms, after the settling bounce and before the stop at 1 ms.
  EXPECT_NEAR(-slope(t, block_vx(c, b2), 0.1, 0.8), mu * g, 0.02 * mu * g) << "TYPE7 friction";
  EXPECT_NEAR(-slope(t, block_vx(c, b3), 0.1, 0.8), mu * g, 0.02 * mu * g) << "RWALL friction";
  // Wall: tangential / normal force = mu while sliding (force on the wall).
  const ThTable w = read_th(out / (name + "_TH_RWALL_2.csv"));
  const std::vector<double> tw = w.column(0), fn = w.column(w.col("FNZ")), ft = w.column(w.col("FTX"));
  for (std::size_t k = 0; k < tw.size(); ++k) {
    if (tw[k] > 0.1 && tw[k] < 0.8 && std::abs(fn[k]) > 0) {
      EXPECT_NEAR(ft[k] / std::abs(fn[k]), mu, 1e-3 * mu);
    }
  }
}

TEST(ContactDecks, TiedBarTransmitsTheWave) {
  REQUIRE_SOLVER();
  const std::string name = "contact_tied_bar";
  const fs::path out = run_deck(name);
  ASSERT_FALSE(out.empty());
  const ThTable c = read_th(out / (name + "_TH_NODE_2.csv"));
  const std::vector<double> t = c.column(0), b50 = c.column(c.col("bar1 x50")),
                            b150 = c.column(c.col("bar1 x150")), c50 = c.column(c.col("control x50")),
                            c150 = c.column(c.col("control x150"));
  double inc = 0, refl = 0, tr = 0, trc = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < 0.12) inc = std::max(inc, std::abs(c50[k]));
    // The interface reflection reaches x = 50 at t = 150/c = 0.15 ms (+ pulse 0.05 ms).
    if (t[k] >= 0.13 && t[k] <= 0.25) refl = std::max(refl, std::abs(b50[k] - c50[k]));
    tr = std::max(tr, std::abs(b150[k]));
    trc = std::max(trc, std::abs(c150[k]));
  }
  EXPECT_NEAR(inc, 1.0, 0.05);  // imposed amplitude 1 mm/ms, element dispersion
  EXPECT_LT(refl, 0.02 * inc);
  EXPECT_NEAR(tr, trc, 0.03 * trc);
}

TEST(ContactDecks, FoldedShellStripDoesNotCrossItself) {
  REQUIRE_SOLVER();
  const std::string name = "contact_shell_fold";
  const fs::path out = run_deck(name);
  ASSERT_FALSE(out.empty());
  const double gap = 1.0, z_upper = 5.0;  // make_deck.py: t = 1, legs 2 RF = 5 mm apart
  const ThTable c = read_th(out / (name + "_TH_NODE_2.csv"));
  double dmin = 1e30, dz_min = 0;
  for (const auto& r : c.rows)
    for (int k = 0; k < 3; ++k) {
      const double lower = r[9 + 2 * k], upper = z_upper + r[10 + 2 * k];
      dmin = std::min(dmin, upper - lower);
      dz_min = std::min(dz_min, r[10 + 2 * k]);
    }
  EXPECT_GT(dmin, 0.0) << "the upper leg went through the lower one";
  EXPECT_LT(dmin, gap) << "the legs never came within the gap: no contact tested";
  const ThTable i = read_th(out / (name + "_TH_INTER_3.csv"));
  double nact = 0;
  for (double v : i.column(i.col("NACT"))) nact = std::max(nact, v);
  EXPECT_GT(nact, 10.0);
  // The upper leg came back up after the impact (rebound).
  EXPECT_GT(c.rows.back()[10], dz_min + 1.0);
}

TEST(ContactDecks, MovingWallOfGivenMassConservesMomentum) {
  // Analytic value: total X momentum Mw VW = 2e-3 kg * 3 mm/ms = 6e-3 kg mm/ms at every row
  // (tolerance 1e-9 relative: the CSV holds 10 significant digits); the impact must have
  // happened (the wall lost more than 10% of its speed).
  REQUIRE_SOLVER();
  const std::string name = "contact_moving_wall";
  const fs::path out = run_deck(name);
  ASSERT_FALSE(out.empty());
  const ThTable nodes = read_th(out / (name + "_TH_NODE_2.csv"));
  const double mw = 2e-3, vw = 3.0, h = 10.0 / 4, me = 1e-6 * h * h * h, p0 = mw * vw;
  const std::vector<double> m = block_masses(4, 4, 4, me);
  const std::size_t wall = nodes.col("node 1000 wall VX");
  ASSERT_EQ(nodes.header.size(), wall + 1 + m.size());
  for (const auto& r : nodes.rows) {
    double p = mw * r[wall];
    for (std::size_t i = 0; i < m.size(); ++i) p += m[i] * r[wall + 1 + i];
    EXPECT_NEAR(p, p0, 1e-9 * p0) << "t = " << r[0];
  }
  EXPECT_LT(nodes.rows.back()[wall], 0.9 * vw);
}

// OpenRadioss reads a TYPE7 Stfac or VISs of 0 as its default (starter
// hm_read_inter_type07.F: STFAC 0 -> 1, VISC 0 -> 0.05), as it reads a blank one; the same
// deck must mean the same here. The committed deck writes VISs 1e-30 (no damping): its
// time histories must differ from the default's, or the comparison would prove nothing.
TEST(ContactDecks, ZeroOrBlankStfacAndVisSAreTheOpenRadiossDefaults) {
  REQUIRE_SOLVER();
  const std::string name = "contact_blocks_collide";
  const std::string src = read_text(example_deck(name));
  const std::string contact_line = "  1.000000000000E+00  0.000000000000E+00  2.000000000000E-01";
  const std::string damping_line = "                                       0  1.000000000000E-30";
  auto variant = [&](const std::string& tag, const std::string& stfac, const std::string& vis) {
    std::string deck = src;
    auto replace_all = [&deck](const std::string& from, const std::string& to) {
      int n = 0;
      for (auto pos = deck.find(from); pos != std::string::npos; pos = deck.find(from, pos + to.size()), ++n)
        deck.replace(pos, from.size(), to);
      EXPECT_EQ(n, 2) << from;  // two interfaces
    };
    replace_all(contact_line, stfac + contact_line.substr(20));
    replace_all(damping_line, damping_line.substr(0, 40) + vis);
    const fs::path dir = fs::current_path() / ("defaults_" + tag + per_process_suffix());
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / (name + "_0000.rad")) << deck;
    fs::copy_file(example_deck(name).parent_path() / (name + "_0001.rad"), dir / (name + "_0001.rad"));
    std::string log;
    EXPECT_EQ(run_solver(dir / (name + "_0000.rad"), log), 0) << log;
    return read_text(dir / "out" / (name + "_TH_INTER_1.csv")) + read_text(dir / "out" / (name + "_TH_NODE_2.csv"));
  };
  const std::string written = variant("written", "  1.000000000000E+00", "  5.000000000000E-02");
  const std::string zero = variant("zero", "  0.000000000000E+00", "  0.000000000000E+00");
  const std::string blank = variant("blank", std::string(20, ' '), std::string(20, ' '));
  const std::string undamped = variant("undamped", "  1.000000000000E+00", "  1.000000000000E-30");
  ASSERT_FALSE(written.empty());
  EXPECT_TRUE(zero == written) << "Stfac 0 / VISs 0 differ from 1 / 0.05";
  EXPECT_TRUE(blank == written) << "blank Stfac / VISs differ from 1 / 0.05";
  EXPECT_FALSE(undamped == written) << "VISs 0.05 changes nothing: the comparison proves nothing";
}

TEST(ContactDecks, BadWallIsReportedWithFileLineAndKeyword) {
  REQUIRE_SOLVER();
#ifdef HBM_SOLVER_EXE
  // A wall whose M1 equals M has no normal: the run must stop before the loop (exit 1)
  // with a message naming the file, line and card.
  const fs::path dir = fs::current_path() / "contact_bad_wall";
  fs::create_directories(dir);
  auto f20 = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%20.6E", v);
    return std::string(b);
  };
  auto i10 = [](long v) {
    char b[16];
    std::snprintf(b, sizeof b, "%10ld", v);
    return std::string(b);
  };
  std::ofstream s(dir / "bad_0000.rad");
  s << "#RADIOSS STARTER\n/BEGIN\nbad\n" << i10(2024) << i10(0) << "\n"
    << "                  kg                  mm                  ms\n"
    << "                  kg                  mm                  ms\n/NODE\n";
  const double xyz[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int i = 0; i < 8; ++i) s << i10(i + 1) << f20(xyz[i][0]) << f20(xyz[i][1]) << f20(xyz[i][2]) << "\n";
  s << "/BRICK/1\n" << i10(1);
  for (int i = 1; i <= 8; ++i) s << i10(i);
  s << "\n/PART/1\ncube\n" << i10(1) << i10(1) << "\n/PROP/TYPE14/1\nsolid\n" << i10(0) << "\n"
    << "/MAT/LAW1/1\nelastic\n" << f20(1e-6) << "\n" << f20(0.01) << f20(0.3) << "\n"
    << "/RWALL/PLANE/7\nwall\n" << i10(0) << i10(0) << i10(0) << i10(0) << "\n"
    << f20(0) << f20(0) << "\n" << f20(0) << f20(0) << f20(-1) << "\n" << f20(0) << f20(0) << f20(-1)
    << "\n/END\n";
  s.close();
  std::ofstream e(dir / "bad_0001.rad");
  e << "/RUN/bad/1\n1.0\n/TFILE/4\n0.1\n";
  e.close();
  const std::string cmd = "cd '" + dir.string() + "' && '" + HBM_SOLVER_EXE + "' bad_0000.rad > run.log 2>&1";
  const int rc = std::system(cmd.c_str());
  EXPECT_NE(rc, 0);
  const std::string text = read_text(dir / "run.log");
  EXPECT_NE(text.find("bad_0000.rad:"), std::string::npos) << text;
  EXPECT_NE(text.find("/RWALL/PLANE/7"), std::string::npos) << text;
  EXPECT_NE(text.find("M1 equals M"), std::string::npos) << text;
#endif
}

// /RWALL/PLANE secondary nodes as OpenRadioss selects them (starter hm_read_rwall_plane.F):
// grnd_ID1, plus the nodes within Dsearch of the wall on its free side when Dsearch != 0,
// minus grnd_ID2; Dsearch 0 without grnd_ID1 gives a wall with no node (it took every node
// here until 2026-11-24). contact_block_slide's wall holds block 3 (group 3), resting on it
// under gravity; the variant without the group must let the block fall through the plane
// (no wall force at any output, the block's vertical speed -g t) and say why in the log,
// while the slab and block 2, on the free side of the plane, stay off the wall.
TEST(ContactDecks, RigidWallWithoutGroupOrSearchDistanceHoldsNoNode) {
  REQUIRE_SOLVER();
  const std::string name = "contact_block_slide";
  std::string log;
  ASSERT_EQ(run_modified_deck(name, "rwall_no_node", "/RWALL/PLANE/1\nfloor wall\n         0         2         3         0\n",
                              "/RWALL/PLANE/1\nfloor wall\n         0         2         0         0\n", log),
            0)
      << log;
  const fs::path dir = modified_deck_dir("rwall_no_node");
  EXPECT_NE(log.find("Dsearch = 0 and no grnd_ID1"), std::string::npos) << log;
  const ThTable w = read_th(dir / "out" / (name + "_TH_RWALL_2.csv"));
  ASSERT_FALSE(w.rows.empty());
  for (const char* f : {"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ"})
    for (double v : w.column(w.col(f))) EXPECT_EQ(v, 0.0) << f;
  // Block 3 in free fall: VZ = -g t at every node (g = 1 mm/ms^2 in this deck).
  const ThTable c = read_th(dir / "out" / (name + "_TH_NODE_3.csv"));
  std::vector<std::size_t> vz;
  for (std::size_t i = 0; i < c.header.size(); ++i)
    if (c.header[i].find(" VZ ") != std::string::npos) vz.push_back(i);
  ASSERT_EQ(vz.size(), 54u);
  const std::vector<double> t = c.column(0);
  for (std::size_t k = 0; k < t.size(); ++k)
    for (std::size_t j = 27; j < 54; ++j) EXPECT_NEAR(c.rows[k][vz[j]], -1.0 * t[k], 1e-6) << "t = " << t[k];
}

// TYPE7 Stmin and Stmax act only with Istf 2-5, as OpenRadioss reads them
// (hm_read_inter_type07.F: IGSTI > 1 keeps them, else STMIN = 0, STMAX = 1e30); they used to
// cap the Istf 0 stiffness here. On contact_blocks_collide's first interface, a Stmax of
// 1e-9 kN/mm with Istf 0 must leave the run as it is (and warn), with Istf 2 it must change
// the run against Istf 2 alone.
TEST(ContactDecks, StminStmaxActOnlyWithIstfTwoToFive) {
  REQUIRE_SOLVER();
  const std::string name = "contact_blocks_collide";
  const std::string from = "         1         2         0         0         0\n"
                           "  0.000000000000E+00  0.000000000000E+00  0.000000000000E+00\n"
                           "  0.000000000000E+00  0.000000000000E+00\n";
  auto run = [&](const std::string& tag, int istf, const std::string& stmax, std::string& log) {
    char line1[64];
    std::snprintf(line1, sizeof line1, "         1         2%10d         0         0\n", istf);
    const std::string to = line1 + std::string("  0.000000000000E+00  0.000000000000E+00  0.000000000000E+00\n") +
                           "  0.000000000000E+00" + stmax + "\n";
    EXPECT_EQ(run_modified_deck(name, tag, from, to, log), 0) << log;
    const fs::path out = modified_deck_dir(tag) / "out";
    return read_text(out / (name + "_TH_INTER_1.csv")) + read_text(out / (name + "_TH_NODE_2.csv"));
  };
  const std::string none = "  0.000000000000E+00", tiny = "  1.000000000000E-09";
  std::string log0, log0s, log2, log2s;
  const std::string istf0 = run("stmax_istf0", 0, none, log0);
  const std::string istf0_capped = run("stmax_istf0_capped", 0, tiny, log0s);
  const std::string istf2 = run("stmax_istf2", 2, none, log2);
  const std::string istf2_capped = run("stmax_istf2_capped", 2, tiny, log2s);
  ASSERT_FALSE(istf0.empty());
  EXPECT_TRUE(istf0_capped == istf0) << "Stmax acted with Istf 0";
  EXPECT_NE(log0s.find("Stmax is not used with Istf 0"), std::string::npos) << log0s;
  EXPECT_FALSE(istf2_capped == istf2) << "Stmax did not act with Istf 2";
  EXPECT_EQ(log2s.find("is not used"), std::string::npos) << log2s;
}
