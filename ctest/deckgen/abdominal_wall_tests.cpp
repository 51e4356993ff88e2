// SPDX-License-Identifier: GPL-3.0-or-later
// The abdominal wall membrane (abdominal_wall.hpp) on the model built from geometry/: where
// it lies (the organ block's front and flanks, on the flesh cells' inner faces), what holds
// it (the lower rib cage and the pelvic shells), its stiffness against the source, and the
// model without it (hbm-deckgen --no-abdominal-wall).
#include "hbm/deckgen/abdominal_wall.hpp"
#include "hbm/deckgen/body_mesher.hpp"
#include "hbm/deckgen/geometry_sources.hpp"
#include "model_test_support.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

using namespace hbm::deckgen;

namespace {

const GeometrySources& geometry() { return test::committed_geometry(); }

const FeModel& default_model() {
  static const FeModel m = build_body_model(geometry(), MesherOptions{});
  return m;
}

// Nodes of the elements of the parts whose FePart `pick` selects.
template <class Pick>
std::set<int> nodes_of(const FeModel& m, Pick pick) {
  return test::nodes_of(m, [&](int p) { return pick(m.parts[static_cast<std::size_t>(p)]); });
}

bool is_wall(const FePart& p) { return p.name == "abdominal_wall" || p.name == "abdominal_wall_tria"; }
bool is_organ(const FePart& p) { return p.name == "abdominal_organs" || p.name == "abdominal_organs_pelvis"; }

}  // namespace

TEST(AbdominalWall, LiesOnTheOrganBlockAndTheFleshCellsAndIsHeldByRibsAndPelvis) {
  const FeModel& m = default_model();
  const int wall = m.find_part("abdominal_wall");
  ASSERT_GE(wall, 0);
  const std::set<int> layer = nodes_of(m, is_wall), organs = nodes_of(m, is_organ);
  const std::set<int> flesh = nodes_of(m, [](const FePart& p) { return p.region == "flesh" && !is_wall(p); });
  const std::set<int> ribs = nodes_of(m, [](const FePart& p) { return p.region == "ribs" || p.region == "cartilage"; });
  const std::set<int> pelvis = nodes_of(m, [](const FePart& p) { return p.region == "pelvis" && p.kind == ElementKind::Shell; });
  ASSERT_FALSE(layer.empty());
  std::size_t on_flesh = 0, on_ribs = 0, on_pelvis = 0;
  for (int n : layer) {
    EXPECT_TRUE(organs.count(n)) << "layer node " << n + 1 << " is not on the organ block";
    on_flesh += flesh.count(n);
    on_ribs += ribs.count(n);
    on_pelvis += pelvis.count(n);
  }
  // Two faces of the block over one flesh cell become one quad on the cell's inner face, so
  // most layer nodes are flesh nodes (79 % in the committed model; the rest: faces between
  // the lower ribs and single-layer rows at region ends); merging nothing would leave half.
  EXPECT_GE(static_cast<double>(on_flesh), 0.75 * static_cast<double>(layer.size()));
  // Anchored from the lower ribs and costal cartilage to the pelvic ring, as the muscles are.
  EXPECT_GT(on_ribs, 0u);
  EXPECT_GT(on_pelvis, 0u);
  // Front and flanks: every quad's normal points forward or sideways, not back (faces are
  // chosen with n_x > -0.5; a quad over two faces may turn a few degrees further), and the
  // layer spans the abdomen from the pubic crest to the lower ribs.
  Eigen::Vector2d axis = Eigen::Vector2d::Zero();  // the organ block's centre in plan
  for (int n : organs) axis += m.nodes[static_cast<std::size_t>(n)].head<2>() / static_cast<double>(organs.size());
  double z_min = 1e300, z_max = -1e300;
  for (std::size_t e = 0; e < m.shells.size(); ++e) {
    if (m.shell_part[e] != wall) continue;
    const auto& q = m.shells[e];
    auto P = [&](int i) { return m.nodes[static_cast<std::size_t>(q[static_cast<std::size_t>(i)])]; };
    Eigen::Vector3d n = (P(2) - P(0)).cross(P(3) - P(1)).normalized();
    Eigen::Vector3d mid = 0.25 * (P(0) + P(1) + P(2) + P(3));
    if (n.head<2>().dot(mid.head<2>() - axis) < 0) n = -n;  // outward from the block's centre
    EXPECT_GT(n.x(), -0.6) << "quad " << e + 1;
    for (int i = 0; i < 4; ++i) z_min = std::min(z_min, P(i).z()), z_max = std::max(z_max, P(i).z());
  }
  // Down to the pubic crest (quads above the symphysis' height, none in front of the perineum).
  const double z_pubis = geometry().pelvis.at("pubic_symphysis").z();
  EXPECT_GT(z_min, z_pubis - 40.0);
  EXPECT_LT(z_min, z_pubis + 40.0);
  const double z_rib10 = geometry().vertebra("T10").lower.y();  // lower endplate (x, z)
  EXPECT_GT(z_max, z_rib10);
}

// The membrane carries the wall's published tension per unit strain: Foerstemann et al. 2011
// (materials.csv abdominal_wall): 3.4 N/mm transverse and 1.5 N/mm longitudinal at about 6 %
// strain; the isotropic layer takes the mean, E t = (3.4 + 1.5) / 2 / 0.06 = 40.8 N/mm.
TEST(AbdominalWall, MembraneStiffnessIsTheWallsTensionPerUnitStrain) {
  const FeModel& m = default_model();
  const FePart& p = m.parts[static_cast<std::size_t>(m.find_part("abdominal_wall"))];
  const FeMaterial& mat = m.materials[static_cast<std::size_t>(p.material)];
  const double Et_N_per_mm = mat.E * p.thickness * 1e3;  // GPa x mm = kN/mm
  EXPECT_NEAR(Et_N_per_mm, (3.4 + 1.5) / 2 / 0.06, 0.01 * 40.8);
  EXPECT_EQ(mat.law, "LAW1");
}

TEST(AbdominalWall, OptionOffLeavesTheTrunkWallOfFleshAndSkin) {
  MesherOptions o;
  o.abdominal_wall = false;
  const FeModel without = build_body_model(geometry(), o);
  const FeModel& with = default_model();
  EXPECT_LT(without.find_part("abdominal_wall"), 0);
  EXPECT_LT(without.find_material("abdominal_wall"), 0);
  std::size_t layer = 0;
  for (int p : with.shell_part) layer += is_wall(with.parts[static_cast<std::size_t>(p)]) ? 1 : 0;
  for (int p : with.tria_part) layer += is_wall(with.parts[static_cast<std::size_t>(p)]) ? 1 : 0;
  EXPECT_EQ(with.element_count(), without.element_count() + layer);
  EXPECT_EQ(with.nodes.size(), without.nodes.size());  // the layer adds no node
}

TEST(AbdominalWall, RefusesAModelWithoutTheAbdominalOrgansOrAThicknessOfZero) {
  FeModel empty;
  FeMaterial mat;
  mat.law = "LAW1";
  mat.rho = 1e-6;
  mat.E = 0.041;
  mat.nu = 0.45;
  EXPECT_THROW(add_abdominal_wall(empty, mat, 1.0, 0.0), std::invalid_argument);
  FeModel m = default_model();
  EXPECT_THROW(add_abdominal_wall(m, mat, 0.0, 0.0), std::invalid_argument);
}
