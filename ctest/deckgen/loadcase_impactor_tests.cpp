// SPDX-License-Identifier: GPL-3.0-or-later
// Impactor mesh of the hub load cases (deckgen/loadcases/impactor_disc.hpp): the rounded
// face edge of 49 CFR 572.36(a) (6 in cylinder, 0.5 in edge radius) as built, checked
// against the analytic surface of revolution (flat disc of radius R - r, quarter torus of
// radius r, cylinder of radius R).
#include "hbm/deckgen/loadcases/impactor_disc.hpp"
#include "hbm/deckgen/loadcases/load_case.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lc = hbm::deckgen::loadcases;

namespace {

const Eigen::Vector3d kCentre(10, -20, 300);
const Eigen::Vector3d kBack = Eigen::Vector3d(0.5, 0.8660254037844386, 0).normalized();  // oblique axis

lc::ImpactorShape probe(int sectors, int fillet_rows) {
  lc::ImpactorShape s;
  s.radius = 76.2;       // 6 in / 2
  s.edge_radius = 12.7;  // 0.5 in
  s.rim_depth = 20;
  s.sectors = sectors;
  s.fillet_rows = fillet_rows;
  return s;
}

// (distance from the axis, set-back along the axis) of a node.
std::pair<double, double> cylindrical(const Eigen::Vector3d& p) {
  const Eigen::Vector3d d = p - kCentre;
  const double s = d.dot(kBack);
  return {(d - s * kBack).norm(), s};
}

}  // namespace

TEST(LoadCaseImpactor, SetbackIsTheQuarterCircleOfTheEdge) {
  const lc::ImpactorShape s = probe(36, 4);
  const double flat = s.radius - s.edge_radius;
  EXPECT_DOUBLE_EQ(s.setback(0), 0);
  EXPECT_DOUBLE_EQ(s.setback(flat), 0);
  EXPECT_NEAR(s.setback(flat + s.edge_radius * std::sin(M_PI / 4)), s.edge_radius * (1 - std::cos(M_PI / 4)), 1e-12);
  EXPECT_NEAR(s.setback(s.radius), s.edge_radius, 1e-12);
  EXPECT_TRUE(std::isinf(s.setback(s.radius + 1e-6)));
}

TEST(LoadCaseImpactor, EveryNodeLiesOnTheSurfaceOfRevolution) {
  const lc::ImpactorShape s = probe(36, 4);
  const lc::ImpactorDisc d = lc::make_impactor_disc(kCentre, kBack, s);
  // centre + (rings + fillet rows + rim rows) rows of sectors nodes
  ASSERT_EQ(d.nodes.size(), 1u + static_cast<std::size_t>((s.rings + s.fillet_rows + s.rim_rows) * s.sectors));
  int flat = 0, fillet = 0, rim = 0;
  for (const auto& p : d.nodes) {
    const auto [rho, back] = cylindrical(p);
    if (back < 1e-9) {
      ++flat;
      EXPECT_LE(rho, s.radius - s.edge_radius + 1e-9);
    } else if (back <= s.edge_radius + 1e-9) {
      ++fillet;  // on the quarter circle of radius r centred at (R - r, r)
      EXPECT_NEAR(std::hypot(rho - (s.radius - s.edge_radius), back - s.edge_radius), s.edge_radius, 1e-9) << "rho " << rho;
      EXPECT_NEAR(back, s.setback(std::min(rho, s.radius)), 1e-6) << "rho " << rho;  // sqrt near the tangent: 1e-6
    } else {
      ++rim;
      EXPECT_NEAR(rho, s.radius, 1e-9);
    }
  }
  EXPECT_EQ(flat, 1 + s.rings * s.sectors);
  EXPECT_EQ(fillet, s.fillet_rows * s.sectors);
  EXPECT_EQ(rim, s.rim_rows * s.sectors);
}

TEST(LoadCaseImpactor, AreaConvergesToTheAnalyticSurface) {
  // pi (R - r)^2 + 2 pi r ((R - r) pi / 2 + r) + 2 pi R L (Pappus for the quarter torus).
  const lc::ImpactorShape s = probe(720, 90);
  const double a = s.radius - s.edge_radius, r = s.edge_radius;
  const double exact = M_PI * a * a + 2 * M_PI * r * (a * M_PI / 2 + r) + 2 * M_PI * s.radius * s.rim_depth;
  const double meshed = lc::make_impactor_disc(kCentre, kBack, s).area();
  EXPECT_NEAR(meshed / exact, 1.0, 1e-4) << meshed << " vs " << exact << " mm^2";
}

TEST(LoadCaseImpactor, NormalsPointOutOfTheImpactor) {
  const lc::ImpactorDisc d = lc::make_impactor_disc(kCentre, kBack, probe(36, 4));
  auto check = [&](const Eigen::Vector3d& n, const Eigen::Vector3d& c) {
    const auto [rho, back] = cylindrical(c);
    const Eigen::Vector3d radial = ((c - kCentre) - back * kBack).normalized();
    if (back < 1e-9)
      EXPECT_LT(n.normalized().dot(kBack), -0.999);  // flat face: towards the body
    else
      EXPECT_GT(n.dot(radial) - n.dot(kBack), 0);   // fillet and rim: away from the axis / the face
  };
  for (const auto& t : d.trias) {
    const auto &p0 = d.nodes[t[0]], &p1 = d.nodes[t[1]], &p2 = d.nodes[t[2]];
    check((p1 - p0).cross(p2 - p0), (p0 + p1 + p2) / 3);
  }
  for (const auto& q : d.quads) {
    const auto &p0 = d.nodes[q[0]], &p1 = d.nodes[q[1]], &p2 = d.nodes[q[2]], &p3 = d.nodes[q[3]];
    check((p2 - p0).cross(p3 - p1), (p0 + p1 + p2 + p3) / 4);
  }
}

TEST(LoadCaseImpactor, SharpEdgeAndBadShapes) {
  lc::ImpactorShape s = probe(24, 4);
  s.edge_radius = 0;  // the sharp-edged disc: face and rim only
  const lc::ImpactorDisc d = lc::make_impactor_disc(kCentre, kBack, s);
  EXPECT_EQ(d.nodes.size(), 1u + static_cast<std::size_t>((s.rings + s.rim_rows) * s.sectors));
  s.edge_radius = s.radius;
  EXPECT_THROW(lc::make_impactor_disc(kCentre, kBack, s), std::invalid_argument);
  s.edge_radius = -1;
  EXPECT_THROW(lc::make_impactor_disc(kCentre, kBack, s), std::invalid_argument);
  s = probe(2, 4);
  EXPECT_THROW(lc::make_impactor_disc(kCentre, kBack, s), std::invalid_argument);
}

TEST(LoadCaseImpactor, CatalogueUsesThePublishedEdgeRadius) {
  for (const auto& c : lc::catalogue()) {
    EXPECT_DOUBLE_EQ(c.edge_radius_mm, 12.7) << c.name;  // 0.5 in, 49 CFR 572.36(a)
    EXPECT_DOUBLE_EQ(c.mass_kg, 23.4) << c.name;
  }
}
