// SPDX-License-Identifier: GPL-3.0-or-later
// Contact geometry: closest point on triangles and warped quads (weights reproduce the
// point, sum to 1), outer faces of a brick block (count, outward orientation through the
// divergence theorem), bucket-grid candidates equal to a brute-force box test.
#include "contact/bucket_grid.hpp"
#include "contact/contact_surface.hpp"
#include "contact/segment_projection.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace hbm::solver;
using namespace hbm::solver::contact;

TEST(ContactGeometry, TriangleRegions) {
  const V3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  // Interior: projection along z, barycentric exact.
  TriangleClosest t = closest_point_on_triangle({0.25, 0.25, 2}, a, b, c);
  EXPECT_TRUE(t.interior);
  EXPECT_NEAR(t.point.z, 0, 1e-15);
  EXPECT_NEAR(t.u, 0.5, 1e-15);
  EXPECT_NEAR(t.v, 0.25, 1e-15);
  EXPECT_NEAR(t.w, 0.25, 1e-15);
  // Beyond vertex a, beyond edge bc (closest point (0.5,0.5,0)).
  t = closest_point_on_triangle({-1, -1, 0.3}, a, b, c);
  EXPECT_FALSE(t.interior);
  EXPECT_DOUBLE_EQ(t.u, 1.0);
  t = closest_point_on_triangle({1, 1, 0}, a, b, c);
  EXPECT_NEAR(t.point.x, 0.5, 1e-15);
  EXPECT_NEAR(t.point.y, 0.5, 1e-15);
  EXPECT_NEAR(t.v, 0.5, 1e-15);
  EXPECT_NEAR(t.w, 0.5, 1e-15);
}

TEST(ContactGeometry, WarpedQuadWeightsReproducePoint) {
  // A warped quad: corner 3 lifted by 0.3. For any query point the weights are >= 0,
  // sum to 1 and interpolate the closest point (so forces keep their moment).
  const std::array<V3, 4> q = {V3{0, 0, 0}, V3{2, 0, 0}, V3{2, 2, 0.3}, V3{0, 2, 0}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 3);
  for (int k = 0; k < 200; ++k) {
    const V3 p{u(rng), u(rng), u(rng) - 1};
    const SegmentProjection pr = project_on_segment(p, q, false);
    double sum = 0;
    V3 x{};
    for (int j = 0; j < 4; ++j) {
      EXPECT_GE(pr.weight[j], -1e-14);
      sum += pr.weight[j];
      x += pr.weight[j] * q[j];
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    EXPECT_NEAR(norm(x - pr.point), 0.0, 1e-13);
    EXPECT_NEAR(pr.distance, norm(p - pr.point), 1e-13);
  }
  // Over the centre of a flat quad: weights 1/4, distance = height.
  const std::array<V3, 4> f = {V3{0, 0, 0}, V3{2, 0, 0}, V3{2, 2, 0}, V3{0, 2, 0}};
  const SegmentProjection c = project_on_segment({1, 1, 0.7}, f, false);
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(c.weight[j], 0.25, 1e-15);
  EXPECT_NEAR(c.distance, 0.7, 1e-15);
  EXPECT_NEAR(c.normal.z, 1.0, 1e-15);
  EXPECT_TRUE(c.interior);
  // Over a point of the flat quad: bilinear-like weights still sum to 1, the point is exact.
  const SegmentProjection e = project_on_segment({0.5, 1.5, -0.2}, f, false);
  EXPECT_NEAR(e.point.x, 0.5, 1e-15);
  EXPECT_NEAR(e.point.y, 1.5, 1e-15);
  EXPECT_NEAR(e.normal.z, 1.0, 1e-15);
}

namespace {
// n x n x n brick block of unit cubes; node (i,j,k) index = i + (n+1)(j + (n+1)k).
struct Block {
  std::vector<double> x, y, z;
  std::vector<SolidForSurface> solids;
};
Block make_block(int n, bool mirrored) {
  Block b;
  const int m = n + 1;
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        b.x.push_back(i);
        b.y.push_back(j);
        b.z.push_back(k);
      }
  auto id = [m](int i, int j, int k) { return static_cast<Index>(i + m * (j + m * k)); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        SolidForSurface s;
        s.nodes = {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                   id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        if (mirrored) {  // inverted numbering (left-handed): orientation must still be outward
          std::swap(s.nodes[1], s.nodes[3]);
          std::swap(s.nodes[5], s.nodes[7]);
        }
        s.bulk_modulus = 2.0;
        b.solids.push_back(s);
      }
  return b;
}
}  // namespace

TEST(ContactGeometry, OuterFacesOfBrickBlock) {
  for (bool mirrored : {false, true}) {
    const Block b = make_block(3, mirrored);
    const ContactSurface s = solid_outer_faces(b.solids, b.x, b.y, b.z);
    ASSERT_EQ(s.size(), 6u * 9u);  // 6 sides x 3x3 faces, interior faces dropped
    // Divergence theorem: sum of outward area vectors = 0, 1/3 sum c.A = volume 27.
    V3 area{};
    double vol = 0;
    for (std::size_t f = 0; f < s.size(); ++f) {
      std::array<V3, 4> c{};
      for (int k = 0; k < 4; ++k) {
        const auto i = static_cast<std::size_t>(s.nodes[f][k]);
        c[k] = {b.x[i], b.y[i], b.z[i]};
      }
      const V3 a = segment_area_vector(c, false);
      area += a;
      vol += dot(0.25 * (c[0] + c[1] + c[2] + c[3]), a) / 3.0;
      // K0 = 0.5 B A^2 / V = 0.5 * 2 * 1 / 1 for unit cubes; depth = half the cube.
      EXPECT_NEAR(s.k0[f], 1.0, 1e-14);
      EXPECT_NEAR(s.depth[f], 0.5, 1e-14);
      EXPECT_EQ(s.one_sided[f], 1);
    }
    EXPECT_NEAR(norm(area), 0.0, 1e-12);
    EXPECT_NEAR(vol, 27.0, 1e-12);
  }
}

TEST(ContactGeometry, DegenerateBricksGiveTriangles) {
  // A tetrahedron written as a degenerate brick n1 n2 n3 n3 n4 n4 n4 n4: 4 triangles.
  std::vector<double> x = {0, 1, 0, 0}, y = {0, 0, 1, 0}, z = {0, 0, 0, 1};
  SolidForSurface t;
  t.nodes = {0, 1, 2, 2, 3, 3, 3, 3};
  t.bulk_modulus = 1;
  const ContactSurface s = solid_outer_faces({t}, x, y, z);
  ASSERT_EQ(s.size(), 4u);
  for (std::size_t f = 0; f < 4; ++f) EXPECT_TRUE(s.is_triangle(f));
  EXPECT_NEAR(brick_volume(t.nodes, x, y, z), 1.0 / 6.0, 1e-15);
}

TEST(ContactGeometry, BucketGridMatchesBruteForce) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 10), s(0.05, 1.5);
  std::vector<Box> boxes;
  for (int k = 0; k < 500; ++k) {
    const V3 c{u(rng), u(rng), u(rng)};
    const V3 h{s(rng), s(rng), s(rng)};
    boxes.push_back({c - h, c + h});
  }
  BucketGrid g;
  g.build(boxes, 1.0);
  for (int q = 0; q < 2000; ++q) {
    const V3 p{u(rng) * 1.1 - 0.5, u(rng) * 1.1 - 0.5, u(rng) * 1.1 - 0.5};
    std::vector<Index> found, brute;
    g.for_each_containing(p, boxes, [&](Index b) { found.push_back(b); });
    for (std::size_t b = 0; b < boxes.size(); ++b)
      if (boxes[b].contains(p)) brute.push_back(static_cast<Index>(b));
    std::sort(found.begin(), found.end());
    ASSERT_EQ(found, brute);
  }
}
