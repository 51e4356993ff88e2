// SPDX-License-Identifier: GPL-3.0-or-later
// Geometry of the 8-node brick with one-point (uniform strain) integration,
// Flanagan & Belytschko (1981), IJNME 17:679-706.
//  - Volume gradient b_I = dV/dx_I = integral of grad N_I over the element, computed
//    exactly face by face (divergence theorem): for a bilinear face P1..P4 with
//    a = (-P1+P2+P3-P4)/4, b = (P1-P2+P3-P4)/4, c = (-P1-P2+P3+P4)/4,
//    integral of N_a n dA = a x c + (a x b) s_a / 3 + (b x c) t_a / 3.
//    Then B_I = b_I / V (uniform gradient), V = (1/3) sum_I x_I . b_I. Adjacent
//    elements share face integrals, so the patch test holds on distorted meshes.
//  - Hourglass base vectors h_alpha (eta zeta, xi zeta, xi eta, xi eta zeta) and the
//    FB projection gamma_alpha,I = h_alpha,I - (sum_J h_alpha,J x_J) . B_I.
// Node order: n1-n4 one face, n5-n8 opposite (n5 above n1), reference coordinates
// xi = (-1,1,1,-1,-1,1,1,-1), eta = (-1,-1,1,1,-1,-1,1,1), zeta = (-1,-1,-1,-1,1,1,1,1).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>

namespace hbm::solver::brick {

inline constexpr double kXi[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
inline constexpr double kEta[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
inline constexpr double kZeta[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
inline constexpr double kHourglass[4][8] = {
    {1, 1, -1, -1, -1, -1, 1, 1},    // eta zeta
    {1, -1, -1, 1, -1, 1, 1, -1},    // xi zeta
    {1, -1, 1, -1, 1, -1, 1, -1},    // xi eta
    {-1, 1, -1, 1, 1, -1, 1, -1}};   // xi eta zeta
// Faces with outward normal (s from first to second node, t from second to third).
inline constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                     {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// Lane form of volume_gradient for a batch of elements: arrays [node][lane] of width W,
// lanes 0..n-1. Same face formula; each face is one loop over the lanes (vectorised).
// amax2 receives the largest |a x c|^2 of the faces (face area = 4 sqrt(amax2)), so the
// caller takes the square root only where it needs it. The lane count n is a std::size_t
// (partly filled batch) or a std::integral_constant (full batch: the compiler then sees a
// fixed trip count, so the loops vectorise without remainder code and the small copies
// and fills are inlined).
namespace detail {
// One face (nodes p1..p4, outward normal) of n elements: a = (s-derivative), c =
// (t-derivative), b = twist; adds a x c -+ (a x b)/3 -+ (b x c)/3 to the face nodes' gradients
// (s_a = (-1, 1, 1, -1), t_a = (-1, -1, 1, 1)) and keeps the largest |a x c|^2.
template <class LaneCount>
inline void face_gradient_lanes(LaneCount n, const double* __restrict x1, const double* __restrict x2,
                                const double* __restrict x3, const double* __restrict x4,
                                const double* __restrict y1, const double* __restrict y2,
                                const double* __restrict y3, const double* __restrict y4,
                                const double* __restrict z1, const double* __restrict z2,
                                const double* __restrict z3, const double* __restrict z4,
                                double* __restrict bx1, double* __restrict bx2, double* __restrict bx3,
                                double* __restrict bx4, double* __restrict by1, double* __restrict by2,
                                double* __restrict by3, double* __restrict by4, double* __restrict bz1,
                                double* __restrict bz2, double* __restrict bz3, double* __restrict bz4,
                                double* __restrict amax2) {
  for (std::size_t l = 0; l < n; ++l) {
    const double ax = 0.25 * (-x1[l] + x2[l] + x3[l] - x4[l]);
    const double ay = 0.25 * (-y1[l] + y2[l] + y3[l] - y4[l]);
    const double az = 0.25 * (-z1[l] + z2[l] + z3[l] - z4[l]);
    const double cx = 0.25 * (-x1[l] - x2[l] + x3[l] + x4[l]);
    const double cy = 0.25 * (-y1[l] - y2[l] + y3[l] + y4[l]);
    const double cz = 0.25 * (-z1[l] - z2[l] + z3[l] + z4[l]);
    const double tx = 0.25 * (x1[l] - x2[l] + x3[l] - x4[l]);
    const double ty = 0.25 * (y1[l] - y2[l] + y3[l] - y4[l]);
    const double tz = 0.25 * (z1[l] - z2[l] + z3[l] - z4[l]);
    const double acx = ay * cz - az * cy, acy = az * cx - ax * cz, acz = ax * cy - ay * cx;
    const double abx = (ay * tz - az * ty) / 3.0, aby = (az * tx - ax * tz) / 3.0,
                 abz = (ax * ty - ay * tx) / 3.0;
    const double bcx = (ty * cz - tz * cy) / 3.0, bcy = (tz * cx - tx * cz) / 3.0,
                 bcz = (tx * cy - ty * cx) / 3.0;
    bx1[l] += acx - abx - bcx; by1[l] += acy - aby - bcy; bz1[l] += acz - abz - bcz;
    bx2[l] += acx + abx - bcx; by2[l] += acy + aby - bcy; bz2[l] += acz + abz - bcz;
    bx3[l] += acx + abx + bcx; by3[l] += acy + aby + bcy; bz3[l] += acz + abz + bcz;
    bx4[l] += acx - abx + bcx; by4[l] += acy - aby + bcy; bz4[l] += acz - abz + bcz;
    amax2[l] = std::max(amax2[l], acx * acx + acy * acy + acz * acz);
  }
}
}  // namespace detail

// Volume gradient (bx, by, bz per node), volume, largest face area of one element: the
// face formula of the lane form with one lane.
inline void volume_gradient(const double* x, const double* y, const double* z, double* bx,
                            double* by, double* bz, double& volume, double& max_face_area) {
  for (int i = 0; i < 8; ++i) bx[i] = by[i] = bz[i] = 0.0;
  double amax2 = 0.0;
  for (const auto& f : kFaces) {
    const int p1 = f[0], p2 = f[1], p3 = f[2], p4 = f[3];
    detail::face_gradient_lanes(std::integral_constant<std::size_t, 1>{}, x + p1, x + p2, x + p3, x + p4,
                                y + p1, y + p2, y + p3, y + p4, z + p1, z + p2, z + p3, z + p4, bx + p1, bx + p2, bx + p3, bx + p4, by + p1, by + p2,
                                by + p3, by + p4, bz + p1, bz + p2, bz + p3, bz + p4, &amax2);
  }
  double v = 0.0;
  for (int i = 0; i < 8; ++i) v += x[i] * bx[i] + y[i] * by[i] + z[i] * bz[i];
  volume = v / 3.0;
  max_face_area = 4.0 * std::sqrt(amax2);
}

template <std::size_t W, class LaneCount>
inline void volume_gradient_lanes(LaneCount n, const double (*x)[W], const double (*y)[W],
                                  const double (*z)[W], double (*bx)[W], double (*by)[W],
                                  double (*bz)[W], double* __restrict volume,
                                  double* __restrict amax2) {
  for (int i = 0; i < 8; ++i)
    for (std::size_t l = 0; l < n; ++l) bx[i][l] = by[i][l] = bz[i][l] = 0.0;
  for (std::size_t l = 0; l < n; ++l) amax2[l] = 0.0;
  for (const auto& f : kFaces) {
    const int p1 = f[0], p2 = f[1], p3 = f[2], p4 = f[3];
    detail::face_gradient_lanes(n, x[p1], x[p2], x[p3], x[p4], y[p1], y[p2], y[p3], y[p4], z[p1],
                                z[p2], z[p3], z[p4], bx[p1], bx[p2], bx[p3], bx[p4], by[p1], by[p2],
                                by[p3], by[p4], bz[p1], bz[p2], bz[p3], bz[p4], amax2);
  }
  for (std::size_t l = 0; l < n; ++l) volume[l] = 0.0;
  for (int i = 0; i < 8; ++i)
    for (std::size_t l = 0; l < n; ++l)
      volume[l] += x[i][l] * bx[i][l] + y[i][l] * by[i][l] + z[i][l] * bz[i][l];
  for (std::size_t l = 0; l < n; ++l) volume[l] /= 3.0;
}

}  // namespace hbm::solver::brick
