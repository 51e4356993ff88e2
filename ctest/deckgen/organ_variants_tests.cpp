// SPDX-License-Identifier: GPL-3.0-or-later
// The thoracic organ block (organ_variants.hpp) on the model built from geometry/: the lungs
// and the water-like mediastinum of thoracic_organs.csv (the default) and its re-cut
// (hbm-deckgen --mediastinum), the seed's undifferentiated block (--undifferentiated-organs)
// with a water-like band over its whole height, the pleura (--pleura): what each moves, what
// it must leave alone, the mass, and the lungs' bulk modulus from the air in them.
#include "hbm/deckgen/geometry_sources.hpp"
#include "hbm/deckgen/body_mesher.hpp"
#include "hbm/deckgen/model_checks.hpp"
#include "hbm/deckgen/organ_variants.hpp"
#include "model_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>

using namespace hbm::deckgen;

namespace {

const GeometrySources& geometry() { return test::committed_geometry(); }
using test::nodes_of;

// The seed's undifferentiated, air-filled thoracic organ block (hbm-deckgen
// --undifferentiated-organs): what the band and pleura variants start from.
const FeModel& seed_model() {
  static const FeModel m = [] {
    MesherOptions o;
    o.lungs = false;
    ModelLandmarks lm;
    FeModel x = build_body_model(geometry(), o, &lm);
    assign_rigid_body_masses(x, geometry(), lm);
    return x;
  }();
  return m;
}

// The default model: the block is the lungs and the mediastinum of thoracic_organs.csv.
const FeModel& lungs_model() {
  static const FeModel m = [] {
    ModelLandmarks lm;
    FeModel x = build_body_model(geometry(), MesherOptions{}, &lm);
    assign_rigid_body_masses(x, geometry(), lm);
    return x;
  }();
  return m;
}

bool chest_wall(const std::string& part) {
  return part == "flesh_thorax" || part == "flesh_presternal" || part == "costal_cartilage" || part == "sternum" || part.rfind("rib_", 0) == 0;
}

double part_mass(const FeModel& m, int part) {
  double sum = 0;
  for (std::size_t e = 0; e < m.bricks.size(); ++e)
    if (m.brick_part[e] == part) sum += element_mass(m, ElementKind::Brick, e);
  for (std::size_t e = 0; e < m.tetras.size(); ++e)
    if (m.tetra_part[e] == part) sum += element_mass(m, ElementKind::Tetra, e);
  return sum;
}

// Which block elements lie in the column of half width hw below z_top; checks the model's
// parts against it and returns how many are in the mediastinum.
std::size_t check_column(const FeModel& m, double hw, double z_top) {
  const int organs = m.find_part("thoracic_organs"), med = m.find_part("mediastinum");
  std::size_t in_med = 0;
  for (std::size_t e = 0; e < m.bricks.size(); ++e) {
    if (m.brick_part[e] != med && m.brick_part[e] != organs) continue;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int n : m.bricks[e]) c += m.nodes[static_cast<std::size_t>(n)] / 8;
    const bool in = std::abs(c.y()) < hw && c.z() < z_top;
    EXPECT_EQ(m.brick_part[e] == med, in) << "brick " << e + 1 << " at y " << c.y() << ", z " << c.z();
    in_med += m.brick_part[e] == med ? 1 : 0;
  }
  return in_med;
}

// Volume of a part's solids (its mass over its density).
double part_volume(const FeModel& m, int part) {
  return part_mass(m, part) / m.materials[static_cast<std::size_t>(m.parts[static_cast<std::size_t>(part)].material)].rho;
}

}  // namespace

TEST(OrganVariants, PleuraDetachesTheBlockFromTheChestWallAndKeepsItOnTheSpine) {
  FeModel m = seed_model();
  const int organs = m.find_part("thoracic_organs");
  ASSERT_GE(organs, 0);
  ASSERT_LT(m.find_part("mediastinum"), 0);  // the seed's undifferentiated block
  auto is_organs = [&](int p) { return p == organs; };
  auto is_wall = [&](int p) { return chest_wall(m.parts[static_cast<std::size_t>(p)].name); };
  auto is_other = [&](int p) { return !is_organs(p) && !is_wall(p); };
  const std::set<int> block_before = nodes_of(m, is_organs), wall_before = nodes_of(m, is_wall);
  std::set<int> shared_with_wall, hilum;  // block nodes the wall uses; block nodes other parts use
  std::set_intersection(block_before.begin(), block_before.end(), wall_before.begin(), wall_before.end(),
                        std::inserter(shared_with_wall, shared_with_wall.end()));
  const std::set<int> other_before = nodes_of(m, is_other);
  std::set_intersection(block_before.begin(), block_before.end(), other_before.begin(), other_before.end(),
                        std::inserter(hilum, hilum.end()));
  ASSERT_FALSE(shared_with_wall.empty());
  ASSERT_FALSE(hilum.empty());
  const std::size_t nodes_before = m.nodes.size(), elements_before = m.element_count(), ifaces_before = m.interfaces.size();
  const FeModel before = m;

  const std::size_t detached = add_pleura(m);

  // Every node the block shared with the wall alone got a copy at the same place.
  EXPECT_EQ(m.nodes.size(), nodes_before + detached);
  EXPECT_EQ(m.element_count(), elements_before);
  const std::set<int> block_after = nodes_of(m, is_organs), wall_after = nodes_of(m, is_wall);
  std::set<int> still_shared;
  std::set_intersection(block_after.begin(), block_after.end(), wall_after.begin(), wall_after.end(),
                        std::inserter(still_shared, still_shared.end()));
  // Left shared with the wall: only nodes some other part (spine, discs, inlet fascia,
  // abdominal organs) or spring also holds.
  for (int n : still_shared) EXPECT_TRUE(hilum.count(n)) << "block node " << n << " still on the wall alone";
  EXPECT_EQ(detached + still_shared.size(), shared_with_wall.size());
  // The hilum is untouched: the block still uses every node it shared with other parts.
  for (int n : hilum) EXPECT_TRUE(block_after.count(n)) << "block lost node " << n;
  // The wall and every other part keep their nodes; the copies coincide with the originals.
  EXPECT_EQ(wall_after, wall_before);
  EXPECT_EQ(nodes_of(m, is_other), other_before);
  for (std::size_t e = 0; e < m.bricks.size(); ++e)
    for (int k = 0; k < 8; ++k)
      EXPECT_EQ((m.nodes[static_cast<std::size_t>(m.bricks[e][k])] - before.nodes[static_cast<std::size_t>(before.bricks[e][k])]).norm(), 0.0);
  // A frictionless contact of the wall nodes on the block's surface.
  ASSERT_EQ(m.interfaces.size(), ifaces_before + 1);
  const FeInterface& f = m.interfaces.back();
  EXPECT_EQ(f.name, "pleura");
  EXPECT_EQ(f.type, 7);
  EXPECT_EQ(f.friction, 0.0);
  EXPECT_EQ(f.main_parts, std::vector<int>{organs});
  EXPECT_EQ(f.secondary.size(), detached);
  for (int n : f.secondary) {
    EXPECT_TRUE(shared_with_wall.count(n));
    EXPECT_FALSE(block_after.count(n));
  }
  // Same elements, same places: the mass of the block is unchanged.
  EXPECT_NEAR(part_mass(m, organs), part_mass(before, organs), 1e-12);
}

TEST(OrganVariants, MediastinumIsTheWaterLikeBandWithinItsHalfWidth) {
  FeModel m = seed_model();
  const int organs = m.find_part("thoracic_organs");
  const int abdominal = m.find_material("abdominal_organs");
  ASSERT_GE(organs, 0);
  ASSERT_GE(abdominal, 0);
  const double block_mass = part_mass(m, organs);
  const double rho_air_filled = m.materials[static_cast<std::size_t>(m.parts[static_cast<std::size_t>(organs)].material)].rho;
  const double rho_water_like = m.materials[static_cast<std::size_t>(abdominal)].rho;
  const double half_width = 25.0;

  const std::size_t moved = add_mediastinum(m, half_width);

  const int med = m.find_part("mediastinum");
  ASSERT_GE(med, 0);
  EXPECT_EQ(m.parts[static_cast<std::size_t>(med)].material, abdominal);
  EXPECT_EQ(m.parts[static_cast<std::size_t>(med)].segment, "thorax");
  std::size_t in_med = 0;
  for (std::size_t e = 0; e < m.bricks.size(); ++e) {
    if (m.brick_part[e] != med && m.brick_part[e] != organs) continue;
    double y = 0;
    for (int n : m.bricks[e]) y += m.nodes[static_cast<std::size_t>(n)].y();
    y /= 8;
    if (m.brick_part[e] == med) {
      ++in_med;
      EXPECT_LT(std::abs(y), half_width);
    } else {
      EXPECT_GE(std::abs(y), half_width);
    }
  }
  EXPECT_EQ(in_med, moved);
  EXPECT_GT(moved, 0u);
  // The band's volume V now weighs rho_water V instead of rho_air-filled V.
  const double band_volume = part_mass(m, med) / rho_water_like;
  EXPECT_NEAR(part_mass(m, organs) + part_mass(m, med), block_mass + band_volume * (rho_water_like - rho_air_filled),
              1e-9 * block_mass);
}

TEST(OrganVariants, DefaultBlockIsTheLungsAndTheSourcesWaterLikeMediastinum) {
  const FeModel& m = lungs_model();
  const GeometrySources& g = geometry();
  const int med = m.find_part("mediastinum");
  ASSERT_GE(med, 0);
  EXPECT_EQ(m.parts[static_cast<std::size_t>(med)].material, m.find_material("abdominal_organs"));
  EXPECT_EQ(m.parts[static_cast<std::size_t>(med)].segment, "thorax");
  EXPECT_EQ(m.materials[static_cast<std::size_t>(m.parts[static_cast<std::size_t>(m.find_part("thoracic_organs"))].material)].name, "lungs");
  // Gleeson 2001's mean width 63.1 mm, from the T4 upper endplate down (thoracic_organs.csv).
  EXPECT_DOUBLE_EQ(g.mediastinum.half_width, 31.55);
  EXPECT_GT(check_column(m, g.mediastinum.half_width, g.vertebra(g.mediastinum.top_vertebra).upper.y()), 0u);
}

// The air-filled lungs' bulk modulus is that of their air with the glottis closed (adiabatic:
// K = gamma p0 / phi_air) for 3 l of functional residual capacity in the mesh's lungs, the
// organ block less its mediastinum (materials.csv): a wider column leaves less lung for the air.
TEST(OrganVariants, LungBulkModulusIsTheirAirsWithTheGlottisClosed) {
  const FeModel& m = lungs_model();
  const double v_lungs = part_volume(m, m.find_part("thoracic_organs"));  // mm^3
  const double phi_air = 3.0e6 / v_lungs;
  const double k_air_gpa = 1.4 * 0.101325 / phi_air * 1e-3;
  const FeMaterial& lungs = m.materials[static_cast<std::size_t>(m.parts[static_cast<std::size_t>(m.find_part("thoracic_organs"))].material)];
  EXPECT_NEAR(lungs.K, k_air_gpa, 0.02 * k_air_gpa) << "lungs " << v_lungs * 1e-6 << " l";
}

TEST(OrganVariants, MediastinumRecutKeepsTheBlock) {
  FeModel m = lungs_model();
  const GeometrySources& g = geometry();
  const int organs = m.find_part("thoracic_organs"), med = m.find_part("mediastinum");
  const double z_top = g.vertebra(g.mediastinum.top_vertebra).upper.y();
  const double block_volume = part_volume(m, organs) + part_volume(m, med);
  const std::size_t parts_before = m.parts.size(), in_before = check_column(m, g.mediastinum.half_width, z_top);

  const std::size_t in_after = add_mediastinum(m, 25.0, z_top);

  EXPECT_EQ(m.parts.size(), parts_before);  // the same part, re-cut
  EXPECT_EQ(m.find_part("mediastinum"), med);
  EXPECT_EQ(check_column(m, 25.0, z_top), in_after);
  EXPECT_LT(in_after, in_before);
  EXPECT_NEAR(part_volume(m, organs) + part_volume(m, med), block_volume, 1e-9 * block_volume);
}

TEST(OrganVariants, BadHalfWidthAndMissingPartsAreErrors) {
  FeModel m = seed_model();
  EXPECT_THROW(add_mediastinum(m, 0.0), std::invalid_argument);
  EXPECT_THROW(add_mediastinum(m, -3.0), std::invalid_argument);
  FeModel empty;
  EXPECT_THROW(add_mediastinum(empty, 25.0), std::invalid_argument);
  try {
    add_pleura(empty);
    FAIL() << "no error for a model without thoracic organs";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("thoracic_organs"), std::string::npos) << e.what();
  }
}

TEST(OrganVariants, MediastinumSlidesWithTheBlockUnderThePleura) {
  {  // a band cut after the pleura joins its contact
    FeModel m = seed_model();
    const int organs = m.find_part("thoracic_organs");
    const std::size_t detached = add_pleura(m);
    add_mediastinum(m, 25.0);
    const int med = m.find_part("mediastinum");
    const FeInterface& f = m.interfaces.back();
    ASSERT_EQ(f.name, "pleura");
    EXPECT_EQ(f.main_parts, (std::vector<int>{organs, med}));
    EXPECT_EQ(f.secondary.size(), detached);
  }
  {  // the lungs' mediastinum is part of the block the pleura detaches, and a re-cut keeps it so
    FeModel m = lungs_model();
    const int organs = m.find_part("thoracic_organs"), med = m.find_part("mediastinum");
    add_pleura(m);
    add_mediastinum(m, 25.0);
    const FeInterface& f = m.interfaces.back();
    ASSERT_EQ(f.name, "pleura");
    EXPECT_EQ(f.main_parts, (std::vector<int>{organs, med}));
  }
}
