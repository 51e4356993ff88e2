// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL-based surface tools (see surface_tools.hpp).
#include "hbm/deckgen/surface_tools.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <map>

namespace hbm::deckgen {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

Mesh to_cgal(const TriSurface& s) {
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  v.reserve(s.points.size());
  for (const auto& p : s.points) v.push_back(m.add_vertex(K::Point_3(p.x(), p.y(), p.z())));
  for (const auto& t : s.triangles) {
    auto f = m.add_face(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])], v[static_cast<std::size_t>(t[2])]);
    (void)f;  // a null face means a non-manifold input; check_surface reports it as open
  }
  return m;
}

}  // namespace

namespace {

// Faces used by exactly one element, each as the quad the element gives it (a triangle with
// n4 = n3). kFaces: the element's faces, K nodes each, outward-oriented.
template <std::size_t NPE, std::size_t F, std::size_t K>
std::vector<std::array<int, 4>> boundary_faces(const std::vector<std::array<int, NPE>>& elements, const int (&kFaces)[F][K]) {
  std::map<std::array<int, K>, std::pair<int, std::array<int, 4>>> count;
  for (const auto& el : elements)
    for (const auto& f : kFaces) {
      std::array<int, K> key{};
      for (std::size_t i = 0; i < K; ++i) key[i] = el[static_cast<std::size_t>(f[i])];
      std::array<int, 4> q{key[0], key[1], key[2], key[K - 1]};
      std::sort(key.begin(), key.end());
      auto& e = count[key];
      e.first++;
      e.second = q;
    }
  std::vector<std::array<int, 4>> out;
  for (const auto& [key, e] : count)
    if (e.first == 1) out.push_back(e.second);
  return out;
}

}  // namespace

std::vector<std::array<int, 4>> hex_boundary_faces(const std::vector<std::array<int, 8>>& hexes) {
  // Faces with outward normals for the convention n1-n4 bottom (counter-clockwise seen from
  // the top), n5-n8 top.
  static constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  return boundary_faces(hexes, kFaces);
}

std::vector<std::array<int, 4>> tet_boundary_faces(const std::vector<std::array<int, 4>>& tets) {
  // Outward faces of a positively oriented tetra (n2 - n1) . ((n3 - n1) x (n4 - n1)) > 0.
  static constexpr int kFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return boundary_faces(tets, kFaces);
}

TriSurface triangulate(const std::vector<Eigen::Vector3d>& nodes, const std::vector<std::array<int, 4>>& quads) {
  TriSurface s;
  std::map<int, int> local;
  auto id = [&](int n) {
    auto it = local.find(n);
    if (it != local.end()) return it->second;
    int k = static_cast<int>(s.points.size());
    s.points.push_back(nodes[static_cast<std::size_t>(n)]);
    local[n] = k;
    return k;
  };
  for (const auto& q : quads) {
    int a = id(q[0]), b = id(q[1]), c = id(q[2]), d = id(q[3]);
    if (q[2] == q[3]) {
      s.triangles.push_back({a, b, c});
      continue;
    }
    double d1 = (s.points[static_cast<std::size_t>(a)] - s.points[static_cast<std::size_t>(c)]).norm();
    double d2 = (s.points[static_cast<std::size_t>(b)] - s.points[static_cast<std::size_t>(d)]).norm();
    if (d1 <= d2) {
      s.triangles.push_back({a, b, c});
      s.triangles.push_back({a, c, d});
    } else {
      s.triangles.push_back({a, b, d});
      s.triangles.push_back({b, c, d});
    }
  }
  return s;
}

SurfaceReport check_surface(const TriSurface& s) {
  SurfaceReport r;
  Mesh m = to_cgal(s);
  r.triangles = m.number_of_faces();
  r.closed = r.triangles == s.triangles.size() && CGAL::is_closed(m);
  r.self_intersecting = PMP::does_self_intersect(m);
  if (r.closed) r.volume = PMP::volume(m);
  return r;
}

std::vector<double> distance_to_surface(const TriSurface& s, const std::vector<Eigen::Vector3d>& queries) {
  Mesh m = to_cgal(s);
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
  Tree tree(faces(m).first, faces(m).second, m);
  tree.accelerate_distance_queries();
  std::vector<double> out(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i)
    out[i] = std::sqrt(tree.squared_distance(K::Point_3(queries[i].x(), queries[i].y(), queries[i].z())));
  return out;
}

std::vector<bool> inside_surface(const TriSurface& s, const std::vector<Eigen::Vector3d>& queries) {
  Mesh m = to_cgal(s);
  std::vector<bool> out(queries.size(), false);
  if (!CGAL::is_closed(m)) return out;
  CGAL::Side_of_triangle_mesh<Mesh, K> side(m);
  for (std::size_t i = 0; i < queries.size(); ++i)
    out[i] = side(K::Point_3(queries[i].x(), queries[i].y(), queries[i].z())) == CGAL::ON_BOUNDED_SIDE;
  return out;
}

}  // namespace hbm::deckgen
