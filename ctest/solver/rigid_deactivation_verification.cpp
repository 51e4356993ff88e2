// SPDX-License-Identifier: GPL-3.0-or-later
// Elements inside a rigid body are deactivated (OpenRadioss /RBODY: "all the elements
// belonging to the rigid body are deactivated"; ElementGroup::deactivate). The deck is
// written by the test: a closed box 40 x 40 x 40 mm (16 /SHELL quads on the four sides,
// 16 /SH3N triangles on top and bottom, diagonals through the face centres, and one /BRICK
// on the 8 corners), all 26 box nodes secondaries of one /RBODY, translating at v0 and
// spinning at w0 about z (a principal axis: the lumped masses have the box's symmetry), no
// loads; a separate 100 x 100 mm /SHELL plate at rest sets the element time step.
// Checked against the analytic free motion:
//  - the body spins at w = w0 Jp / Jzz (angular momentum Jp w0 of the nodal velocities;
//    Jzz = Jp + nodal rotational inertias) and a corner node follows
//    x(t) = v0 t + Rz(w t) r0 (1e-6 mm; 10 printed digits of displacements up to 80 mm),
//  - the body's KE is 0.5 M |v0|^2 + 0.5 Jzz w^2 with M, Jzz from the elements' lumped
//    masses (rho t A / npe per shell node, rho V / 8 per brick node) and shell nodal
//    inertias m (t^2 + A) / 12: their mass is in the body (1e-9, the printed digits),
//  - internal and hourglass energies of the box parts are exactly 0 (never computed),
//  - the time step is 0.9 x the plate's L / c (the box's smaller elements, 5 x shorter,
//    would set a 5 x smaller one if they counted),
//  - the listing names the deactivated count per group and per part.
#include "example_deck_runner.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using hbm::solver::testing::per_process_suffix;
using hbm::solver::testing::read_text;
using hbm::solver::testing::read_th;
using hbm::solver::testing::ThTable;

namespace {

constexpr double kHalf = 20.0;                      // box half side [mm]
constexpr double kRho = 1e-6, kE = 1.0, kNu = 0.3;  // kg/mm^3, GPa
constexpr double kThick = 1.0;                      // shell thickness [mm]
constexpr double kPlate = 100.0;                    // plate side [mm]
constexpr double kW0 = 0.2;                         // spin about z [rad/ms]
constexpr std::array<double, 3> kV0 = {3.0, -1.0, 2.0};  // [mm/ms]
constexpr double kEnd = 20.0;                             // [ms]

struct Box {
  std::vector<std::array<double, 3>> x;    // node positions (node id = index + 1)
  std::vector<std::array<int, 4>> quads;   // node ids
  std::vector<std::array<int, 3>> trias;
  std::array<int, 8> brick{};
  int node(int i, int j, int k) const {    // lattice -1..1 -> node id
    for (std::size_t n = 0; n < x.size(); ++n)
      if (x[n][0] == kHalf * i && x[n][1] == kHalf * j && x[n][2] == kHalf * k) return static_cast<int>(n) + 1;
    return 0;
  }
};

Box make_box() {
  Box b;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k)
        if (i || j || k) b.x.push_back({kHalf * i, kHalf * j, kHalf * k});
  for (int s : {-1, 1})
    for (int p = -1; p <= 0; ++p)
      for (int q = -1; q <= 0; ++q) {
        b.quads.push_back({b.node(s, p, q), b.node(s, p + 1, q), b.node(s, p + 1, q + 1), b.node(s, p, q + 1)});
        b.quads.push_back({b.node(p, s, q), b.node(p + 1, s, q), b.node(p + 1, s, q + 1), b.node(p, s, q + 1)});
        // Top and bottom: the cell's diagonal through the face centre (0, 0).
        const int a = b.node(p, q, s), c1 = b.node(p + 1, q, s), c = b.node(p + 1, q + 1, s), d = b.node(p, q + 1, s);
        const bool centre_ac = (p == -1 && q == -1) || (p == 0 && q == 0);
        if (centre_ac) {
          b.trias.push_back({a, c1, c});
          b.trias.push_back({a, c, d});
        } else {
          b.trias.push_back({a, c1, d});
          b.trias.push_back({c1, c, d});
        }
      }
  b.brick = {b.node(-1, -1, -1), b.node(1, -1, -1), b.node(1, 1, -1), b.node(-1, 1, -1),
             b.node(-1, -1, 1), b.node(1, -1, 1), b.node(1, 1, 1), b.node(-1, 1, 1)};
  return b;
}

std::string i10(long long v) {
  char s[16];
  std::snprintf(s, sizeof s, "%10lld", v);
  return s;
}
std::string r20(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%20.12E", v);
  return s;
}

// Writes the starter and engine decks into `dir`; returns the starter path.
std::filesystem::path write_deck(const Box& b, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const int n_box = static_cast<int>(b.x.size());
  const int main_node = 100, plate0 = 200;
  std::ostringstream s;
  s << "#RADIOSS STARTER\n/BEGIN\nrigid_deactivation\n      2024         0\n"
    << "                  kg                  mm                  ms\n"
    << "                  kg                  mm                  ms\n/NODE\n";
  for (int n = 0; n < n_box; ++n) s << i10(n + 1) << r20(b.x[n][0]) << r20(b.x[n][1]) << r20(b.x[n][2]) << "\n";
  s << i10(main_node) << r20(0.0) << r20(0.0) << r20(0.0) << "\n";
  const double pz = -200.0;
  const double pxy[4][2] = {{-300, -50}, {-200, -50}, {-200, 50}, {-300, 50}};
  for (int k = 0; k < 4; ++k) s << i10(plate0 + k) << r20(pxy[k][0]) << r20(pxy[k][1]) << r20(pz) << "\n";
  s << "/MAT/LAW1/1\nbox material\n" << r20(kRho) << "\n" << r20(kE) << r20(kNu) << "\n";
  s << "/PROP/TYPE1/1\nshell 1 mm\n         0         0         0         0         0            0.000000000000E+00\n"
    << "  1.000000000000E-02  1.000000000000E-02  1.000000000000E-02  0.000000000000E+00  0.000000000000E+00\n"
    << "         3         0" << r20(kThick) << "  8.333333333333E-01                   0         1\n";
  s << "/PROP/TYPE14/2\nbrick\n         0\n  1.100000000000E+00  5.000000000000E-02  1.000000000000E-01\n";
  s << "/PART/1\nbox sides\n         1         1         0\n/PART/2\nbox top bottom\n         1         1         0\n"
    << "/PART/3\nbox brick\n         2         1         0\n/PART/4\nfree plate\n         1         1         0\n";
  s << "/SHELL/1\n";
  for (std::size_t e = 0; e < b.quads.size(); ++e)
    s << i10(static_cast<long long>(e + 1)) << i10(b.quads[e][0]) << i10(b.quads[e][1]) << i10(b.quads[e][2])
      << i10(b.quads[e][3]) << "\n";
  s << "/SH3N/2\n";
  for (std::size_t e = 0; e < b.trias.size(); ++e)
    s << i10(static_cast<long long>(e + 101)) << i10(b.trias[e][0]) << i10(b.trias[e][1]) << i10(b.trias[e][2]) << "\n";
  s << "/BRICK/3\n" << i10(201);
  for (int n : b.brick) s << i10(n);
  s << "\n/SHELL/4\n" << i10(301) << i10(plate0) << i10(plate0 + 1) << i10(plate0 + 2) << i10(plate0 + 3) << "\n";
  s << "/GRNOD/NODE/1\nbox nodes\n";
  for (int n = 1; n <= n_box; ++n) s << i10(n) << (n % 10 == 0 || n == n_box ? "\n" : "");
  s << "/RBODY/1\nbox\n" << i10(main_node) << "         0         0         0" << r20(0.0)
    << "         1         0         1         0\n";
  // Initial velocity of the rigid motion v0 + w0 e_z x r, one card per node.
  for (int n = 0; n <= n_box; ++n) {
    const int id = n < n_box ? n + 1 : main_node;
    const double x = n < n_box ? b.x[n][0] : 0.0, y = n < n_box ? b.x[n][1] : 0.0;
    s << "/GRNOD/NODE/" << 10 + n << "\nnode " << id << "\n" << i10(id) << "\n";
    s << "/INIVEL/TRA/" << 10 + n << "\nnode " << id << "\n"
      << r20(kV0[0] - kW0 * y) << r20(kV0[1] + kW0 * x) << r20(kV0[2]) << i10(10 + n) << "\n";
  }
  s << "/TH/RBODY/1\nbody\n        KE        WZ\n         1\n";
  s << "/TH/NODE/2\ncorner\n        DX        DY        DZ\n" << i10(b.node(1, 1, 1)) << "         0corner\n";
  s << "/TH/PART/3\nenergies\n        IE        HE\n         1         2         3         4\n/END\n";
  const std::filesystem::path starter = dir / "rigid_deactivation_0000.rad";
  std::ofstream(starter) << s.str();
  std::ofstream(dir / "rigid_deactivation_0001.rad")
      << "#RADIOSS ENGINE\n/RUN/rigid_deactivation/1\n" << kEnd << "\n/TFILE/4\n0.5\n/PRINT/-20\n";
  return starter;
}

}  // namespace

TEST(RigidDeactivation, BoxOfShellsAndBrickMovesAsTheFreeRigidBody) {
#ifndef HBM_SOLVER_EXE
  GTEST_SKIP() << "hbm-solver was not built";
#else
  const Box b = make_box();
  ASSERT_EQ(b.x.size(), 26u);
  ASSERT_EQ(b.quads.size(), 16u);  // 4 sides x 4 cells
  ASSERT_EQ(b.trias.size(), 16u);
  const std::filesystem::path dir = std::filesystem::current_path() / ("deck_rigid_deactivation" + per_process_suffix());
  const std::filesystem::path out = std::filesystem::current_path() / ("out_rigid_deactivation" + per_process_suffix());
  std::filesystem::remove_all(out);
  const std::filesystem::path starter = write_deck(b, dir);
  const std::string cmd = std::string("'") + HBM_SOLVER_EXE + "' '" + starter.string() + "' --out '" + out.string() +
                          "' > '" + out.string() + ".log' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;

  // Lumped masses and nodal rotational inertias (the engine's rule: m = rho t A / npe,
  // j = m (t^2 + A) / 12 per shell node; rho V / 8 per brick node) -> body mass M and
  // Jzz = Jp + Jn about the centre (the origin; Jp of the point masses, Jn the nodal
  // inertias). The nodes start with the velocities of the spin w0 (no nodal spin), so the
  // body's angular momentum is Lz = Jp w0 and it spins at w = Lz / Jzz.
  std::vector<double> m(b.x.size(), 0.0), j(b.x.size(), 0.0);
  auto lump = [&](const auto& conn, double mass_each, double inertia_each) {
    for (int n : conn) {
      m[static_cast<std::size_t>(n - 1)] += mass_each;
      j[static_cast<std::size_t>(n - 1)] += inertia_each;
    }
  };
  const double a_quad = kHalf * kHalf, a_tria = 0.5 * a_quad;
  const double m_quad = kRho * kThick * a_quad / 4, m_tria = kRho * kThick * a_tria / 3;
  for (const auto& q : b.quads) lump(q, m_quad, m_quad * (kThick * kThick + a_quad) / 12);
  for (const auto& t : b.trias) lump(t, m_tria, m_tria * (kThick * kThick + a_tria) / 12);
  lump(b.brick, kRho * std::pow(2 * kHalf, 3) / 8, 0.0);
  double M = 0, Jp = 0, Jn = 0;
  for (std::size_t n = 0; n < m.size(); ++n) {
    M += m[n];
    Jp += m[n] * (b.x[n][0] * b.x[n][0] + b.x[n][1] * b.x[n][1]);
    Jn += j[n];
  }
  const double w_exact = kW0 * Jp / (Jp + Jn);
  const double v2 = kV0[0] * kV0[0] + kV0[1] * kV0[1] + kV0[2] * kV0[2];
  const double ke_exact = 0.5 * M * v2 + 0.5 * (Jp + Jn) * w_exact * w_exact;

  const ThTable body = read_th(out / "rigid_deactivation_TH_RBODY_1.csv");
  const ThTable corner = read_th(out / "rigid_deactivation_TH_NODE_2.csv");
  const ThTable parts = read_th(out / "rigid_deactivation_TH_PART_3.csv");
  ASSERT_GT(body.rows.size(), 30u);
  const auto t = body.column("time");
  EXPECT_NEAR(t.back(), kEnd, 0.1);
  const auto ke = body.column("KE"), wz = body.column("WZ");
  const auto dx = corner.column("DX"), dy = corner.column("DY"), dz = corner.column("DZ");
  double ke_dev = 0, w_dev = 0, pos_dev = 0;
  const double r0x = kHalf, r0y = kHalf;
  for (std::size_t i = 0; i < t.size(); ++i) {
    ke_dev = std::max(ke_dev, std::abs(ke[i] - ke_exact) / ke_exact);
    w_dev = std::max(w_dev, std::abs(wz[i] - w_exact) / w_exact);
    const double c = std::cos(w_exact * t[i]), s = std::sin(w_exact * t[i]);
    const double ex = kV0[0] * t[i] + c * r0x - s * r0y - r0x;
    const double ey = kV0[1] * t[i] + s * r0x + c * r0y - r0y;
    const double ez = kV0[2] * t[i];
    pos_dev = std::max(pos_dev, std::sqrt(std::pow(dx[i] - ex, 2) + std::pow(dy[i] - ey, 2) + std::pow(dz[i] - ez, 2)));
  }
  std::printf("rigid_deactivation: M %.6e kg, KE %.6e J (exact %.6e), |dKE|/KE %.2e, |dw|/w %.2e, corner %.2e mm\n",
              M, ke.back(), ke_exact, ke_dev, w_dev, pos_dev);
  // The time histories print 10 significant digits: that is the tolerance.
  EXPECT_LT(ke_dev, 1e-9);
  EXPECT_LT(w_dev, 1e-9);
  EXPECT_LT(pos_dev, 1e-6);
  // Nothing of the box is computed: its parts' energies are exactly zero.
  std::size_t zero_columns = 0;
  for (const char* part : {"part 1 ", "part 2 ", "part 3 "})
    for (const char* var : {" IE ", " HE "})
      for (std::size_t c = 0; c < parts.header.size(); ++c) {
        if (parts.header[c].find(part) == std::string::npos || parts.header[c].find(var) == std::string::npos)
          continue;
        ++zero_columns;
        for (const auto& row : parts.rows) EXPECT_EQ(row[c], 0.0) << parts.header[c];
      }
  EXPECT_EQ(zero_columns, 6u);

  // Time step: 0.9 L / c of the plate (L = area / longest side = kPlate).
  const std::string listing = read_text(out / "rigid_deactivation_0001.out");
  const double c_plate = std::sqrt(kE / (kRho * (1 - kNu * kNu)));
  const double dt_exact = 0.9 * kPlate / c_plate;
  std::smatch mt;
  const std::regex cycle_line(R"(\n +(\d+) +([0-9.eE+-]+) +([0-9.eE+-]+) )");
  double dt_last = 0;
  for (auto it = std::sregex_iterator(listing.begin(), listing.end(), cycle_line); it != std::sregex_iterator(); ++it)
    dt_last = std::stod((*it)[3]);
  std::printf("rigid_deactivation: time step %.4e ms (plate 0.9 L/c %.4e)\n", dt_last, dt_exact);
  EXPECT_NEAR(dt_last, dt_exact, 1e-4 * dt_exact);
  // Listing: counts per group, per part and in all.
  EXPECT_NE(listing.find("elements 34 (33 deactivated inside rigid bodies)"), std::string::npos);
  EXPECT_NE(listing.find("16 elements, shell4 Belytschko-Tsay (BWC warping, hourglass), 16 deactivated"),
            std::string::npos);
  EXPECT_NE(listing.find("16 elements, shell3 CST membrane + DKT bending, 16 deactivated"), std::string::npos);
  EXPECT_NE(listing.find("deactivated 16  box sides"), std::string::npos);
  EXPECT_NE(listing.find("deactivated 16  box top bottom"), std::string::npos);
  EXPECT_NE(listing.find("deactivated 1  box brick"), std::string::npos);
  EXPECT_NE(listing.find("deactivated 0  free plate"), std::string::npos);
  EXPECT_NE(listing.find("NORMAL TERMINATION"), std::string::npos);
#endif
}
