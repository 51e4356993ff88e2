// SPDX-License-Identifier: GPL-3.0-or-later
// Contact surface extraction: outer faces of solids, shell segments, segment stiffness.
#include "contact_surface.hpp"

#include "segment_projection.hpp"
#include "vec3.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace hbm::solver::contact {

namespace {

// Brick faces in Radioss numbering, each ordered so that its normal points out of a
// positively numbered brick (n1-n4 counter-clockwise seen from n5-n8 side is not
// assumed: orientation is fixed afterwards against the centroid).
constexpr int kBrickFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                   {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

V3 at(Index i, const std::vector<double>& x, const std::vector<double>& y,
      const std::vector<double>& z) {
  const auto k = static_cast<std::size_t>(i);
  return {x[k], y[k], z[k]};
}

// Distinct nodes of a face in cyclic order (consecutive duplicates removed).
int distinct_face_nodes(const std::array<Index, 8>& n, const int* f, std::array<Index, 4>& out) {
  int m = 0;
  for (int k = 0; k < 4; ++k) {
    const Index id = n[static_cast<std::size_t>(f[k])];
    bool seen = false;
    for (int j = 0; j < m; ++j) seen = seen || out[static_cast<std::size_t>(j)] == id;
    if (!seen) out[static_cast<std::size_t>(m++)] = id;
  }
  return m;
}

}  // namespace

void ContactSurface::append(const ContactSurface& o) {
  nodes.insert(nodes.end(), o.nodes.begin(), o.nodes.end());
  k0.insert(k0.end(), o.k0.begin(), o.k0.end());
  thickness.insert(thickness.end(), o.thickness.begin(), o.thickness.end());
  one_sided.insert(one_sided.end(), o.one_sided.begin(), o.one_sided.end());
  depth.insert(depth.end(), o.depth.begin(), o.depth.end());
}

double brick_volume(const std::array<Index, 8>& n, const std::vector<double>& x,
                    const std::vector<double>& y, const std::vector<double>& z) {
  double v = 0;
  for (const auto& f : kBrickFaces) {
    std::array<Index, 4> d{};
    const int m = distinct_face_nodes(n, f, d);
    if (m < 3) continue;
    std::array<V3, 4> c{};
    for (int k = 0; k < 4; ++k) c[static_cast<std::size_t>(k)] = at(d[static_cast<std::size_t>(std::min(k, m - 1))], x, y, z);
    const bool tri = m == 3;
    const V3 centre = tri ? (1.0 / 3.0) * (c[0] + c[1] + c[2]) : 0.25 * (c[0] + c[1] + c[2] + c[3]);
    v += dot(centre, segment_area_vector(c, tri));
  }
  return std::abs(v) / 3.0;
}

ContactSurface solid_outer_faces(const std::vector<SolidForSurface>& solids,
                                 const std::vector<double>& x, const std::vector<double>& y,
                                 const std::vector<double>& z) {
  struct FaceUse {
    std::size_t element;
    std::array<Index, 4> nodes;  // cyclic, nodes[3] == nodes[2] for a triangle
    int count;
  };
  std::map<std::array<Index, 4>, FaceUse> faces;  // key: sorted distinct nodes
  for (std::size_t e = 0; e < solids.size(); ++e) {
    for (const auto& f : kBrickFaces) {
      std::array<Index, 4> d{};
      const int m = distinct_face_nodes(solids[e].nodes, f, d);
      if (m < 3) continue;
      if (m == 3) d[3] = d[2];
      std::array<Index, 4> key = d;
      if (m == 3) key[3] = kNoIndex;
      std::sort(key.begin(), key.end());
      auto [it, inserted] = faces.try_emplace(key, FaceUse{e, d, 0});
      ++it->second.count;
    }
  }
  ContactSurface s;
  for (auto& [key, use] : faces) {
    if (use.count != 1) continue;
    const SolidForSurface& el = solids[use.element];
    std::array<V3, 4> c{};
    for (std::size_t k = 0; k < 4; ++k) c[k] = at(use.nodes[k], x, y, z);
    const bool tri = use.nodes[3] == use.nodes[2];
    V3 area = segment_area_vector(c, tri);
    const V3 centre = tri ? (1.0 / 3.0) * (c[0] + c[1] + c[2]) : 0.25 * (c[0] + c[1] + c[2] + c[3]);
    V3 el_centre{};
    for (Index id : el.nodes) el_centre += 0.125 * at(id, x, y, z);
    if (dot(area, centre - el_centre) < 0) {  // reverse to point outward
      if (tri) std::swap(use.nodes[1], use.nodes[2]), use.nodes[3] = use.nodes[2];
      else std::swap(use.nodes[1], use.nodes[3]);
    }
    const double a = norm(area);
    const double vol = brick_volume(el.nodes, x, y, z);
    s.nodes.push_back(use.nodes);
    s.k0.push_back(vol > 0 ? 0.5 * el.bulk_modulus * a * a / vol : 0.0);
    s.thickness.push_back(0.0);
    s.one_sided.push_back(1);
    s.depth.push_back(a > 0 ? 0.5 * vol / a : 0.0);  // half the element depth under the face
  }
  return s;
}

ContactSurface shell_segments(const std::vector<ShellForSurface>& shells) {
  ContactSurface s;
  for (const ShellForSurface& sh : shells) {
    s.nodes.push_back(sh.nodes);
    s.k0.push_back(0.5 * sh.young * sh.thickness);
    s.thickness.push_back(sh.thickness);
    s.one_sided.push_back(0);
    s.depth.push_back(0.0);
  }
  return s;
}

}  // namespace hbm::solver::contact
