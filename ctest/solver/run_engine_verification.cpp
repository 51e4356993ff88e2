// SPDX-License-Identifier: GPL-3.0-or-later
// Engine verification: each case runs a deck of decks/examples/<case>/ in process (the
// frozen model is kept for inspection) and compares with the analytic value stated in
// the deck header, with the tolerance given here. Outputs go to the test's working
// directory (build tree).
#include "example_deck_runner.hpp"
#include "solid/solid_group.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace hbm::solver;
using namespace hbm::solver::testing;

namespace {

const SolidGroup& solid(const InProcessRun& r, std::size_t g = 0) {
  return dynamic_cast<const SolidGroup&>(*r.model.groups.at(g));
}

// Copy a deck pair, replacing the final time, to run one case at several times.
fs::path deck_with_tstop(const std::string& name, double tstop) {
  const fs::path dir = fs::current_path() / (name + "_t" + std::to_string(tstop));
  fs::create_directories(dir);
  fs::copy_file(example_deck(name), dir / (name + "_0000.rad"), fs::copy_options::overwrite_existing);
  std::ifstream in(example_deck(name).replace_filename(name + "_0001.rad"));
  std::ofstream out(dir / (name + "_0001.rad"));
  std::string line;
  bool next = false;
  while (std::getline(in, line)) {
    if (next) {
      out << tstop << "\n";
      next = false;
      continue;
    }
    next = line.rfind("/RUN/", 0) == 0;
    out << line << "\n";
  }
  return dir / (name + "_0000.rad");
}

}  // namespace

// Uniaxial stress, LAW1 (hypoelastic, Jaumann): sigma_xx = E ln(L/L0), lateral
// ln(W/W0) = -nu ln(L/L0), sigma_yy = sigma_zz = 0. Tolerance 1%.
TEST(EngineVerification, UniaxialLaw1LogStrain) {
  auto r = run_in_process("uniaxial_law1");
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const ThTable th = read_th(r->out / "uniaxial_law1_TH_NODE_1.csv");
  const auto& last = th.rows.back();
  const double L = 1.0 + last[th.col("DX")], W = 1.0 + last[th.col("DY")];
  const double E = 0.01, nu = 0.3;
  double s[6];
  solid(*r).stress(0, s);
  EXPECT_NEAR(s[0], E * std::log(L), 0.01 * E * std::log(L));
  EXPECT_NEAR(std::log(W), -nu * std::log(L), 0.01 * nu * std::log(L));
  EXPECT_LT(std::abs(s[1]) + std::abs(s[2]), 0.01 * s[0]);
  // Imposed: u = 0.1 / (0.95 T) * integral of the ramp (0, 0) (0.1 T, 1) (T, 1) ...
  const double T = 5.0, t = r->result.time;
  EXPECT_NEAR(L - 1.0, 0.1 / (0.95 * T) * (t - 0.05 * T), 1e-9);  // exact imposed displacement
  // The animation's specific energy (/ANIM/ELEM/ENER: internal energy / element mass) is the
  // stress work per unit mass: sigma = E e with e = ln L and V = V0 exp((1 - 2 nu) e), so
  // W / (rho V0) = E (exp(a e) (a e - 1) + 1) / (a^2 rho), a = 1 - 2 nu. 1 %.
  const double rho = 1e-6, a = 1.0 - 2.0 * nu, e = std::log(L);
  const double expect = E * (std::exp(a * e) * (a * e - 1.0) + 1.0) / (a * a * rho);
  std::vector<double> ener(1), hourg(1);
  solid(*r).cell_field(CellField::SpecificEnergy, ener);
  solid(*r).cell_field(CellField::HourglassEnergy, hourg);
  EXPECT_NEAR(ener[0], expect, 0.01 * expect);
  EXPECT_NEAR(hourg[0], r->result.energies.hourglass, 1e-12 + 1e-9 * std::abs(r->result.energies.hourglass));
}

// The per-element energies of the animation add up to the run's balance: over the 256
// bricks of law34_impact (physical hourglass), sum of specific energy x element mass = the
// internal energy and sum of hourglass energy = the hourglass energy (1e-9 relative).
TEST(EngineVerification, AnimationElementEnergiesSumToTheBalance) {
  auto r = run_in_process("law34_impact");
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const SolidGroup& g = solid(*r);
  std::vector<double> ener(g.n_elements), hourg(g.n_elements);
  g.cell_field(CellField::SpecificEnergy, ener);
  g.cell_field(CellField::HourglassEnergy, hourg);
  double ie = 0.0, he = 0.0;
  for (std::size_t e = 0; e < g.n_elements; ++e) {
    ie += ener[e] * g.mass[e];
    he += hourg[e];
  }
  ASSERT_GT(r->result.energies.internal, 0.0);
  ASSERT_GT(r->result.energies.hourglass, 0.0);
  EXPECT_NEAR(ie, r->result.energies.internal, 1e-9 * r->result.energies.internal);
  EXPECT_NEAR(he, r->result.energies.hourglass, 1e-9 * r->result.energies.hourglass);
}

// LAW2 Johnson-Cook: sigma = a + b eps_p^n, eps_p = ln(L) - sigma/E, yield at a. 1%.
TEST(EngineVerification, UniaxialLaw2YieldAndHardening) {
  auto r = run_in_process("uniaxial_law2");
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const ThTable th = read_th(r->out / "uniaxial_law2_TH_NODE_1.csv");
  const double L = 1.0 + th.rows.back()[th.col("DX")];
  const double E = 0.2, a = 3e-4, b = 5e-4, n = 0.5;
  double s[6];
  solid(*r).stress(0, s);
  const double eps_p = std::log(L) - s[0] / E;
  EXPECT_NEAR(s[0], a + b * std::pow(eps_p, n), 0.01 * s[0]);
  EXPECT_NEAR(solid(*r).eps_p[0], eps_p, 0.01 * eps_p);
  EXPECT_GT(s[0], a);
}

// LAW34 relaxation after a shear ramp gamma over tr: sigma_xy(t) =
// (gamma/tr) [Ginf tr + (G0 - Ginf)/beta (exp(-beta (t - tr)) - exp(-beta t))]. 1%.
TEST(EngineVerification, Law34RelaxationFollowsGt) {
  const double G0 = 1e-3, Ginf = 2.5e-4, beta = 10.0, tr = 0.01, gamma = 0.01;
  for (double t : {0.05, 0.1, 0.2, 0.4}) {
    auto r = run_in_process("relax_law34_" + std::to_string(t), deck_with_tstop("relax_law34", t));
    ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
    const double te = r->result.time;
    const double expect =
        gamma / tr * (Ginf * tr + (G0 - Ginf) / beta * (std::exp(-beta * (te - tr)) - std::exp(-beta * te)));
    double s[6];
    solid(*r).stress(0, s);
    EXPECT_NEAR(s[3], expect, 0.01 * expect) << "t = " << te;
  }
}

// Free fall: z = -g t^2 / 2 exactly (constant acceleration). 1e-9 relative.
TEST(EngineVerification, FreeFallIsExact) {
  auto r = run_in_process("free_fall");
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const ThTable th = read_th(r->out / "free_fall_TH_NODE_1.csv");
  ASSERT_GT(th.rows.size(), 10u);
  const double g = 9.81e-3;
  for (const auto& row : th.rows) {
    const double t = row[0];
    if (t <= 0) continue;
    EXPECT_NEAR(row[th.col("DZ")], -0.5 * g * t * t, 1e-9 * 0.5 * g * t * t) << "t = " << t;
    EXPECT_NEAR(row[th.col("VZ")], -g * t, 1e-9 * g * t) << "t = " << t;
  }
}

// Wave in a bar: arrival at x = 50 mm at 50/c, particle velocity v0 behind the front. 2%.
TEST(EngineVerification, ElasticWaveArrivalAndAmplitude) {
  auto r = run_in_process("wave_bar");
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const ThTable th = read_th(r->out / "wave_bar_TH_NODE_1.csv");
  const double c = std::sqrt(200.0 / 7.85e-6), v0 = 1.0;
  const std::size_t vx = th.col("mid bar VX");
  double arrival = -1, prev_t = 0, prev_v = 0, sum = 0;
  int count = 0;
  for (const auto& row : th.rows) {
    if (arrival < 0 && row[vx] >= 0.5 * v0)
      arrival = prev_t + (0.5 * v0 - prev_v) / (row[vx] - prev_v) * (row[0] - prev_t);
    prev_t = row[0];
    prev_v = row[vx];
    if (row[0] > 70.0 / c && row[0] < 140.0 / c) {
      sum += row[vx];
      ++count;
    }
  }
  EXPECT_NEAR(arrival, 50.0 / c, 0.02 * 50.0 / c);
  ASSERT_GT(count, 10);
  EXPECT_NEAR(sum / count, v0, 0.02 * v0);
  // Stress behind the front at t = 0.03 ms: -rho c v0 in the element at x = 30 mm (the
  // wave reflected at the free end, which unloads, has only come back to x = 49 mm).
  double s[6];
  solid(*r).stress(29, s);
  EXPECT_NEAR(s[0], -7.85e-6 * c * v0, 0.02 * 7.85e-6 * c * v0);
}

// Patch test on a distorted mesh: uniform stress to 1e-10 relative, interior node on the
// linear field.
TEST(EngineVerification, PatchTestDistortedMesh) {
  auto r = run_in_process("patch_distorted");
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const SolidGroup& g = solid(*r);
  double ref[6], s[6];
  g.stress(0, ref);
  double scale = 0;
  for (double v : ref) scale = std::max(scale, std::abs(v));
  ASSERT_GT(scale, 0.0);
  for (std::size_t e = 1; e < g.n_elements; ++e) {
    g.stress(e, s);
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(s[k], ref[k], 1e-10 * scale) << "element " << e << " component " << k;
  }
  // Interior node (1,1,1) initially at (1.15, 0.9, 1.12): u = A x0 t (x(t) linear in x0).
  const ThTable th = read_th(r->out / "patch_distorted_TH_NODE_1.csv");
  const double t = th.rows.back()[0];
  const double x0[3] = {1.15, 0.9, 1.12};
  const double A[3][3] = {{1e-3, 0.4e-3, -0.1e-3}, {0.4e-3, -0.5e-3, 0.2e-3}, {-0.1e-3, 0.2e-3, 0.3e-3}};
  const char* names[3] = {"DX", "DY", "DZ"};
  for (int a = 0; a < 3; ++a) {
    const double u = (A[a][0] * x0[0] + A[a][1] * x0[1] + A[a][2] * x0[2]) * t;
    EXPECT_NEAR(th.rows.back()[th.col(names[a])], u, 1e-9 * std::abs(u)) << names[a];
  }
}

// Mass scaling: added mass on the 8 nodes of the thin element equals k_n/2 (Tmin/Tsca)^2 - m0.
TEST(EngineVerification, MassScalingAddsTheFormulaMass) {
  auto r = run_in_process("mass_scaling");
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const double E = 0.2, nu = 0.3, rho = 7.85e-6, h = 0.05, tsca = 0.9, tmin = 2e-3;
  const double G = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  // Box of sides (L, 1, 1): T = diag(1/(2L^2), 1/2, 1/2); k_slot = 2 (m/8) / dt^2, dt = 2/w.
  auto k_slot = [&](double L) {
    const double t[3] = {1 / (2 * L * L), 0.5, 0.5};
    const double tr = t[0] + t[1] + t[2], tt = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
    const double w2 = 8 * (lambda * tr * tr + 2 * G * tt) / (rho * tr);
    const double dt = 2 / std::sqrt(w2);
    return 2 * (rho * L / 8) / (dt * dt);
  };
  const double k = k_slot(1.0) + k_slot(h);
  const double m0 = rho * (1.0 + h) / 8;
  const double expect_node = k / 2 * (tmin / tsca) * (tmin / tsca) - m0;
  ASSERT_GT(expect_node, 0.0);
  // The outer nodes need none: their nodal step is above Tmin.
  EXPECT_GT(tsca * std::sqrt(2 * (rho / 8) / k_slot(1.0)), tmin);
  const ThTable th = read_th(r->out / "mass_scaling_TH_PART_1.csv");
  const auto& last = th.rows.back();
  EXPECT_NEAR(last[th.col("added mass")], 8 * expect_node, 1e-9 * 8 * expect_node);
  EXPECT_NEAR(last[th.col("part 2 thin AM")], 8 * expect_node, 1e-9 * 8 * expect_node);
  EXPECT_EQ(last[th.col("part 1 big AM")], 0.0);
  const double M0 = rho * (2 + h);
  EXPECT_NEAR(last[th.col("mass ratio")], 8 * expect_node / M0, 1e-9);
}

// DMmax stop: exit code 3, message naming part 2 and element 2, valid outputs.
TEST(EngineVerification, DmMaxStopsCleanlyNamingPartAndElement) {
  auto r = run_in_process("mass_scaling_stop");
  EXPECT_EQ(r->result.exit_code, 3);
  EXPECT_EQ(r->result.reason, StopReason::AddedMass);
  const std::string& m = r->result.message;
  EXPECT_NE(m.find("exceeds DMmax"), std::string::npos) << m;
  EXPECT_NE(m.find("part 2 'thin'"), std::string::npos) << m;
  EXPECT_NE(m.find("elements: 2 "), std::string::npos) << m;
  const ThTable th = read_th(r->out / "mass_scaling_stop_TH_PART_1.csv");
  EXPECT_GE(th.rows.size(), 1u);
  EXPECT_NE(read_text(r->out / "mass_scaling_stop_0001.out").find("ERROR TERMINATION: added mass ratio"), std::string::npos);
}

// Elastic impact on a fixed face: E_kin + E_int + E_hg = E_0 within 0.1% at every row.
TEST(EngineVerification, EnergyBalanceElasticImpact) {
  auto r = run_in_process("energy_impact");
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const ThTable th = read_th(r->out / "energy_impact_TH_PART_1.csv");
  // E_0 = 0.5 m v0^2 of the moving nodes: block rho 10 x 10 x 20 mm^3 minus the lumped
  // mass of the fixed bottom face (16 elements x 4 of their 8 nodes).
  const double rho = 7.85e-6, v0 = 5.0, h3 = 2.5 * 2.5 * 2.5;
  const double e0 = 0.5 * rho * (2000.0 - 16 * 4 * h3 / 8) * v0 * v0;
  EXPECT_NEAR(th.rows.front()[th.col("kinetic energy")], e0, 1e-12 * e0);
  double max_ie = 0;
  for (const auto& row : th.rows) {
    const double total = row[th.col("kinetic energy")] + row[th.col("internal energy")] + row[th.col("hourglass energy")];
    EXPECT_NEAR(total, e0, 1e-3 * e0) << "t = " << row[0];
    EXPECT_LT(std::abs(row[th.col("energy error")]), 1e-3);
    max_ie = std::max(max_ie, row[th.col("internal energy")]);
  }
  EXPECT_GT(max_ie, 0.5 * e0);  // a real impact: most of the energy went through strain
}

// LAW34 block punched at 6.7 m/s: no inverted element, hourglass < 10% of internal.
TEST(EngineVerification, Law34ImpactHourglassBelowTenPercent) {
  auto r = run_in_process("law34_impact");
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const ThTable th = read_th(r->out / "law34_impact_TH_PART_2.csv");
  const auto& last = th.rows.back();
  const double ie = last[th.col("part 1 tissue block IE")], he = last[th.col("part 1 tissue block HE")];
  EXPECT_GT(ie, 0.0);
  EXPECT_LT(he, 0.1 * ie) << "hourglass " << he << " internal " << ie;
  EXPECT_EQ(solid(*r).hourglass, HourglassForm::Physical);
  const ThTable punch = read_th(r->out / "law34_impact_TH_NODE_1.csv");
  EXPECT_NEAR(punch.rows.back()[punch.col("DZ")], -6.7 * r->result.time, 1e-9 * 6.7);
}

// Results do not depend on the thread count: 1 and 2 threads bitwise identical.
TEST(EngineVerification, OneAndTwoThreadsBitwiseIdentical) {
  auto a = run_in_process("law34_impact", {}, 1);
  auto b = run_in_process("law34_impact", {}, 2);
  ASSERT_EQ(a->result.exit_code, 0);
  ASSERT_EQ(b->result.exit_code, 0);
  EXPECT_EQ(a->result.cycles, b->result.cycles);
  const NodalState &na = a->model.nodes, &nb = b->model.nodes;
  ASSERT_EQ(na.n_nodes, nb.n_nodes);
  std::size_t diff = 0;
  for (std::size_t i = 0; i < na.n_nodes; ++i)
    diff += (na.x.x[i] != nb.x.x[i]) + (na.x.y[i] != nb.x.y[i]) + (na.x.z[i] != nb.x.z[i]) +
            (na.v.x[i] != nb.v.x[i]) + (na.v.y[i] != nb.v.y[i]) + (na.v.z[i] != nb.v.z[i]);
  EXPECT_EQ(diff, 0u);
  EXPECT_EQ(a->result.energies.internal, b->result.energies.internal);
  EXPECT_EQ(a->result.energies.hourglass, b->result.energies.hourglass);
  EXPECT_EQ(a->result.energies.kinetic, b->result.energies.kinetic);
}

// Planted inverted element: stops with element, part and time; outputs valid.
TEST(EngineVerification, InvertedElementStopsCleanly) {
  auto r = run_in_process("inverted_element");
  EXPECT_EQ(r->result.exit_code, 3);
  EXPECT_EQ(r->result.reason, StopReason::InvertedElement);
  const std::regex msg("element 1 of part 1 'cube' inverted \\(negative volume\\) at time [0-9.e+-]+ ms");
  EXPECT_TRUE(std::regex_search(r->result.message, msg)) << r->result.message;
  const ThTable th = read_th(r->out / "inverted_element_TH_NODE_1.csv");
  ASSERT_GE(th.rows.size(), 2u);
  for (const auto& row : th.rows)
    for (double v : row) EXPECT_TRUE(std::isfinite(v));
  EXPECT_TRUE(fs::exists(r->out / "inverted_element.pvd"));
  for (const auto& e : fs::directory_iterator(r->out)) EXPECT_NE(e.path().extension(), ".tmp") << e.path();
}

// The animation of a run opens in an independent VTK reader (Debian python3-vtk9).
TEST(EngineVerification, PvdReadsBackWithVtk) {
  auto r = run_in_process("law34_impact", {}, 0);
  ASSERT_EQ(r->result.exit_code, 0);
  run_python("read_pvd.py", R"(import sys, xml.etree.ElementTree as ET, os, vtk
pvd = sys.argv[1]
sets = ET.parse(pvd).getroot().find('Collection').findall('DataSet')
assert len(sets) >= 2, 'frames'
for ds in sets:
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(os.path.join(os.path.dirname(pvd), ds.get('file')))
    r.Update()
    g = r.GetOutput()
    assert g.GetNumberOfCells() == 256, g.GetNumberOfCells()
    assert g.GetNumberOfPoints() == 405, g.GetNumberOfPoints()
    assert g.GetCellType(0) == vtk.VTK_HEXAHEDRON
    for a in ('displacement', 'velocity', 'added_mass'):
        assert g.GetPointData().GetArray(a) is not None, a
    for a in ('part', 'element_id', 'von_mises', 'plastic_strain', 'eroded', 'specific_energy', 'hourglass_energy'):
        assert g.GetCellData().GetArray(a) is not None, a
last = g.GetPointData().GetArray('displacement').GetRange(2)
print('frames', len(sets), 'dz range', last)
assert last[0] < -1.0
)",
             (r->out / "law34_impact.pvd").string());
}

// An animation result the engine does not write is named, with the engine file and line,
// not dropped silently; the run goes on (exit 0).
TEST(EngineVerification, UnwrittenAnimationResultIsNamed) {
  const fs::path src = example_deck("law34_impact").parent_path();
  const fs::path dir = fs::current_path() / ("anim_acc" + per_process_suffix());
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(src / "law34_impact_0000.rad", dir / "law34_impact_0000.rad");
  std::string engine = read_text(src / "law34_impact_0001.rad");
  const auto pos = engine.find("/ANIM/DT");
  ASSERT_NE(pos, std::string::npos);
  engine.insert(pos, "/ANIM/VECT/ACC\n");
  const auto line = 1 + std::count(engine.begin(), engine.begin() + static_cast<std::ptrdiff_t>(pos), '\n');
  std::ofstream(dir / "law34_impact_0001.rad") << engine;
  std::string out;
  EXPECT_EQ(run_solver(dir / "law34_impact_0000.rad", out), 0) << out;
  EXPECT_NE(out.find("law34_impact_0001.rad:" + std::to_string(line) + ": warning: /ANIM/VECT/ACC: not written to the animation"),
            std::string::npos)
      << out;
}

// Constant-strain tetra and degenerate (prism) bricks under uniaxial stress:
// sigma_xx = E ln(L) in every element (1%), other components small; cells as themselves.
TEST(EngineVerification, TetraAndPrismUniaxial) {
  auto r = run_in_process("tetra_prism_uniaxial");
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const ThTable th = read_th(r->out / "tetra_prism_uniaxial_TH_NODE_1.csv");
  const double L = 1.0 + th.rows.back()[th.col("tetra corner DX")];
  EXPECT_NEAR(th.rows.back()[th.col("prism corner DX")], L - 1.0, 1e-12);
  const double E = 0.01, expect = E * std::log(L);
  ASSERT_EQ(r->model.groups.size(), 2u);
  for (const auto& g : r->model.groups) {
    const auto& sg = dynamic_cast<const SolidGroup&>(*g);
    for (std::size_t e = 0; e < sg.n_elements; ++e) {
      double s[6];
      sg.stress(e, s);
      EXPECT_NEAR(s[0], expect, 0.01 * expect) << g->keyword << " element " << g->element_id[e];
      for (int k = 1; k < 6; ++k) EXPECT_LT(std::abs(s[k]), 0.01 * expect) << g->keyword << " component " << k;
      Index nodes[8];
      int n = 0;
      const VtkCellType t = g->vtk_cell(e, nodes, n);
      EXPECT_EQ(t, g->nodes_per_element == 4 ? VtkCellType::Tetra : VtkCellType::Wedge);
    }
  }
}

// LAW36 tabulated plasticity: sigma = f(eps_p) before failure (1%); at EPS_p_max = 0.03
// the element is deleted, counted for its part, its energy kept in the balance.
TEST(EngineVerification, Law36TabulatedYieldAndErosion) {
  const double E = 0.2;
  auto yield = [](double ep) { return 3e-4 + 2e-3 * ep; };
  {
    auto r = run_in_process("law36_erosion_t2", deck_with_tstop("law36_erosion", 2.0));
    ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
    const ThTable th = read_th(r->out / "law36_erosion_TH_NODE_1.csv");
    const double L = 1.0 + th.rows.back()[th.col("DX")];
    double s[6];
    solid(*r).stress(0, s);
    const double ep = std::log(L) - s[0] / E;
    EXPECT_GT(ep, 0.01);
    EXPECT_NEAR(s[0], yield(ep), 0.01 * s[0]);
    EXPECT_EQ(solid(*r).n_eroded, 0);
  }
  auto r = run_in_process("law36_erosion");
  ASSERT_EQ(r->result.exit_code, 0) << r->result.message;
  const SolidGroup& g = solid(*r);
  EXPECT_EQ(g.n_eroded, 1);
  EXPECT_EQ(g.alive[0], 0);
  EXPECT_GE(g.eps_p[0], 0.03);
  EXPECT_GT(g.energy.eroded, 0.0);
  EXPECT_EQ(g.energy.eroded, g.energy.internal);  // nothing more after deletion
  const ThTable th = read_th(r->out / "law36_erosion_TH_PART_2.csv");
  EXPECT_EQ(th.rows.back()[th.col("part 1 cube ER")], 1.0);
  EXPECT_NE(read_text(r->out / "law36_erosion_0001.out").find("element 1 of part 1 'cube' deleted at t = "), std::string::npos);
}

// Damaged decks found by run_deck_mutation_verification.cpp. A density of 1e30 (a units
// slip) gives a first stable step of 1.3e15 ms, past the end time at once: the run ends after
// that cycle with a warning (the output schedule used to add its interval 1e16 times: a
// hang). A bulk viscosity qb of 1e30 makes the stable step collapse (to 1e-27 ms, with the
// energy error at 1e49 %): the run stops with exit 3 once the step falls below 1e-6 of the first one, naming
// the element (it used to go on for ever). A Young's modulus of 1e30 asks for more than 1e9
// cycles at the first step: stopped with exit 3 (a units slip), not run for years.
TEST(EngineVerification, DamagedTimeStepsEndTheRun) {
  std::string log;
  EXPECT_EQ(run_modified_deck("uniaxial_law2", "huge_step", "  7.850000000000E-06", "        1.000000E+30", log), 0)
      << log;
  EXPECT_NE(log.find("NORMAL TERMINATION"), std::string::npos) << log;
  EXPECT_NE(log.find("is longer than the whole run"), std::string::npos) << log;
  EXPECT_EQ(run_modified_deck("law36_erosion", "collapsing_step",
                              "  1.000000000000E-30  1.000000000000E-30  1.000000000000E-01",
                              "  1.000000000000E-30        1.000000E+30  1.000000000000E-01", log),
            3)
      << log;
  EXPECT_NE(log.find("fell below 1e-06 of the first one"), std::string::npos) << log;
  EXPECT_NE(log.find("element 1 of part 1 'cube'"), std::string::npos) << log;
  // E = 1e30 GPa: a stable step of 1.6e-18 ms, 3e18 cycles to 5 ms: stopped at once.
  EXPECT_EQ(run_modified_deck("uniaxial_law2", "tiny_step", "  2.000000000000E-01  3.000000000000E-01         0",
                              "        1.000000E+30  3.000000000000E-01         0", log),
            3)
      << log;
  EXPECT_NE(log.find("cycles to the end time"), std::string::npos) << log;
}

// /PROP/TYPE14 Isolid 24 takes the coefficient of its viscous hourglass part from dn (0 ->
// 0.1) and not from h, as OpenRadioss reads it (hm_read_prop14.F: IHBE 24: CVIS = dn, QH =
// 0). law34_impact writes h = 0.1 and no dn: with h = 0.05 the run must be the same to the
// last digit (and warn that h is unused), with dn = 0.05 it must differ.
TEST(EngineVerification, Isolid24ViscousCoefficientIsDnAsInOpenRadioss) {
  const std::string name = "law34_impact";
  const std::string prop = "/PROP/TYPE14/1\nsolid: Isolid 24, physical hourglass\n        24\n"
                           "  1.100000000000E+00  5.000000000000E-02  1.000000000000E-01\n";
  auto run = [&](const std::string& tag, const std::string& line1, const std::string& h, std::string& log) {
    const std::string to = "/PROP/TYPE14/1\nsolid: Isolid 24, physical hourglass\n" + line1 +
                           "\n  1.100000000000E+00  5.000000000000E-02" + h + "\n";
    EXPECT_EQ(run_modified_deck(name, tag, prop, to, log), 0) << log;
    const std::filesystem::path out = modified_deck_dir(tag) / "out";
    return read_text(out / (name + "_TH_PART_2.csv")) + read_text(out / (name + "_TH_NODE_1.csv"));
  };
  const std::string dn_blank = "        24", dn_005 = "        24" + std::string(70, ' ') + "  5.000000000000E-02";
  std::string log_ref, log_h, log_dn;
  const std::string ref = run("isolid24_ref", dn_blank, "  1.000000000000E-01", log_ref);
  const std::string h005 = run("isolid24_h", dn_blank, "  5.000000000000E-02", log_h);
  const std::string dn005 = run("isolid24_dn", dn_005, "  1.000000000000E-01", log_dn);
  ASSERT_FALSE(ref.empty());
  EXPECT_TRUE(h005 == ref) << "h changed an Isolid 24 run";
  EXPECT_NE(log_h.find("h is not used by Isolid 24"), std::string::npos) << log_h;
  EXPECT_EQ(log_ref.find("h is not used by Isolid 24"), std::string::npos) << log_ref;
  EXPECT_FALSE(dn005 == ref) << "dn does not act on Isolid 24";
}
