// SPDX-License-Identifier: GPL-3.0-or-later
// Projection of a point on a contact segment: closest point, distance and the weights
// (shape function values) that spread a force applied at the closest point onto the
// segment's nodes. Triangles are exact; a quadrilateral, which may be warped, is split
// into four triangles around its centre node x_c = (x1+x2+x3+x4)/4 (as Radioss does for
// TYPE7), so the weights of a point in sub-triangle (a, b, c) with barycentric
// coordinates (u, v, w) are N_a = u + w/4, N_b = v + w/4, N_others = w/4. The weights are
// non-negative and sum to 1 exactly, so a force F at the closest point becomes N_i F on
// the nodes with the same resultant and moment: momentum is exchanged exactly.
#pragma once

#include "vec3.hpp"

#include <array>

namespace hbm::solver::contact {

struct SegmentProjection {
  V3 point;                      // closest point on the segment
  std::array<double, 4> weight;  // N_i of the 4 segment nodes (triangle: weight[3] = 0)
  double distance = 0;           // |x - point|
  V3 normal;                     // unit normal of the (sub-)triangle holding the point,
                                 //   oriented like the segment's n1-n2-n3 ordering
  bool interior = false;         // point strictly inside the (sub-)triangle, not on an edge
};

// Closest point on triangle (a, b, c) to p, barycentric (u, v, w): point = u a + v b + w c.
// Ericson, Real-Time Collision Detection (2005), section 5.1.5, Voronoi-region tests.
struct TriangleClosest {
  V3 point;
  double u = 0, v = 0, w = 0;
  bool interior = false;
};
TriangleClosest closest_point_on_triangle(V3 p, V3 a, V3 b, V3 c);

// Closest point on a segment given by its corner positions; triangle when `is_triangle`.
SegmentProjection project_on_segment(V3 p, const std::array<V3, 4>& corner, bool is_triangle);

// Area-weighted normal of a segment: triangle (x2-x1)x(x3-x1)/2; quadrilateral
// (x3-x1)x(x4-x2)/2 (the exact area of a plane quad, the mean plane of a warped one).
V3 segment_area_vector(const std::array<V3, 4>& corner, bool is_triangle);

}  // namespace hbm::solver::contact
