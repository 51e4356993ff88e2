// SPDX-License-Identifier: GPL-3.0-or-later
// Closest point on triangles and (possibly warped) quadrilateral contact segments.
#include "segment_projection.hpp"

namespace hbm::solver::contact {

TriangleClosest closest_point_on_triangle(V3 p, V3 a, V3 b, V3 c) {
  // Ericson 5.1.5: test the vertex, edge and face Voronoi regions in turn.
  const V3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {a, 1, 0, 0, false};
  const V3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {b, 0, 1, 0, false};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return {a + t * ab, 1 - t, t, 0, false};
  }
  const V3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {c, 0, 0, 1, false};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return {a + t * ac, 1 - t, 0, t, false};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + t * (c - b), 0, 1 - t, t, false};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {a + v * ab + w * ac, 1 - v - w, v, w, true};
}

SegmentProjection project_on_segment(V3 p, const std::array<V3, 4>& x, bool is_triangle) {
  SegmentProjection best;
  if (is_triangle) {
    const TriangleClosest t = closest_point_on_triangle(p, x[0], x[1], x[2]);
    best.point = t.point;
    best.weight = {t.u, t.v, t.w, 0.0};
    best.distance = norm(p - t.point);
    best.normal = normalized(cross(x[1] - x[0], x[2] - x[0]));
    best.interior = t.interior;
    return best;
  }
  const V3 centre = 0.25 * (x[0] + x[1] + x[2] + x[3]);
  double best_d2 = 0;
  for (int k = 0; k < 4; ++k) {
    const int ia = k, ib = (k + 1) & 3;
    const TriangleClosest t = closest_point_on_triangle(p, x[ia], x[ib], centre);
    const V3 d = p - t.point;
    const double d2 = dot(d, d);
    if (k == 0 || d2 < best_d2) {
      best_d2 = d2;
      best.point = t.point;
      const double wc = 0.25 * t.w;
      best.weight = {wc, wc, wc, wc};
      best.weight[ia] += t.u;
      best.weight[ib] += t.v;
      best.normal = normalized(cross(x[ib] - x[ia], centre - x[ia]));
      // Only the outer edge (a, b) of a sub-triangle is on the quad's boundary: the
      // point is inside the quad when the centre weight is positive.
      best.interior = t.w > 0;
    }
  }
  best.distance = std::sqrt(best_d2);
  return best;
}

V3 segment_area_vector(const std::array<V3, 4>& x, bool is_triangle) {
  if (is_triangle) return 0.5 * cross(x[1] - x[0], x[2] - x[0]);
  return 0.5 * cross(x[2] - x[0], x[3] - x[1]);
}

}  // namespace hbm::solver::contact
