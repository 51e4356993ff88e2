// SPDX-License-Identifier: GPL-3.0-or-later
// The abdominal wall's musculo-aponeurotic layer (see abdominal_wall.hpp).
#include "hbm/deckgen/abdominal_wall.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace hbm::deckgen {
namespace {

// The six faces of a brick (node order of FeModel::bricks: 0-3 one end, 4-7 the other).
constexpr std::array<std::array<int, 4>, 6> kBrickFaces{
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};

}  // namespace

AbdominalWallLayer add_abdominal_wall(FeModel& m, FeMaterial material, double thickness_mm, double z_pubis) {
  if (!(thickness_mm > 0) || !std::isfinite(thickness_mm))
    throw std::invalid_argument("abdominal wall: the layer thickness must be a positive number of mm");
  const int organs = m.find_part("abdominal_organs");
  if (organs < 0) throw std::invalid_argument("abdominal wall: the model has no part abdominal_organs");
  const int organs_pelvis = m.find_part("abdominal_organs_pelvis");
  auto is_organ = [&](int p) { return p == organs || (organs_pelvis >= 0 && p == organs_pelvis); };
  auto is_flesh = [&](int p) { return m.parts[static_cast<std::size_t>(p)].region == "flesh"; };

  // What holds each node: the flesh, and the other parts (not organ, not flesh) by index.
  std::vector<char> in_flesh(m.nodes.size(), 0);
  std::vector<std::vector<int>> other(m.nodes.size());
  auto hold = [&](const auto& elements, const std::vector<int>& part_of) {
    for (std::size_t e = 0; e < elements.size(); ++e) {
      const int p = part_of[e];
      if (is_organ(p)) continue;
      for (int n : elements[e]) {
        if (is_flesh(p)) in_flesh[static_cast<std::size_t>(n)] = 1;
        else other[static_cast<std::size_t>(n)].push_back(p);
      }
    }
  };
  hold(m.bricks, m.brick_part);
  hold(m.tetras, m.tetra_part);
  hold(m.shells, m.shell_part);
  hold(m.trias, m.tria_part);
  for (auto& parts : other) {
    std::sort(parts.begin(), parts.end());
    parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
  }

  // Boundary faces of the organ block: faces one organ brick has, with that brick's centroid.
  struct Face {
    std::array<int, 4> nodes, sorted;
    Eigen::Vector3d centroid_of_brick;
  };
  std::map<std::array<int, 4>, int> count;  // sorted node indices -> organ bricks with the face
  std::vector<Face> faces;
  for (std::size_t e = 0; e < m.bricks.size(); ++e) {
    if (!is_organ(m.brick_part[e])) continue;
    const auto& h = m.bricks[e];
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int n : h) c += m.nodes[static_cast<std::size_t>(n)];
    c /= 8.0;
    for (const auto& f : kBrickFaces) {
      std::array<int, 4> q{h[static_cast<std::size_t>(f[0])], h[static_cast<std::size_t>(f[1])], h[static_cast<std::size_t>(f[2])],
                           h[static_cast<std::size_t>(f[3])]};
      std::array<int, 4> key = q;
      std::sort(key.begin(), key.end());
      ++count[key];
      faces.push_back({q, key, c});
    }
  }

  auto P = [&](int n) -> const Eigen::Vector3d& { return m.nodes[static_cast<std::size_t>(n)]; };
  std::vector<std::array<int, 4>> layer;
  for (const Face& f : faces) {
    if (count[f.sorted] != 1 || std::adjacent_find(f.sorted.begin(), f.sorted.end()) != f.sorted.end()) continue;
    int flesh_nodes = 0;
    for (int n : f.nodes) flesh_nodes += in_flesh[static_cast<std::size_t>(n)];
    if (flesh_nodes < 2) continue;
    // Lies on another part if one part holds all four nodes.
    std::vector<int> common = other[static_cast<std::size_t>(f.nodes[0])];
    for (int i = 1; i < 4 && !common.empty(); ++i) {
      const auto& o = other[static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(i)])];
      std::vector<int> both;
      std::set_intersection(common.begin(), common.end(), o.begin(), o.end(), std::back_inserter(both));
      common.swap(both);
    }
    if (!common.empty()) continue;
    const Eigen::Vector3d mid = 0.25 * (P(f.nodes[0]) + P(f.nodes[1]) + P(f.nodes[2]) + P(f.nodes[3]));
    Eigen::Vector3d nrm = (P(f.nodes[2]) - P(f.nodes[0])).cross(P(f.nodes[3]) - P(f.nodes[1]));
    if (nrm.dot(mid - f.centroid_of_brick) < 0) nrm = -nrm;
    nrm.normalize();
    if (nrm.x() <= -0.5 || nrm.z() <= -0.7) continue;  // the back (column side), the block's floor
    if (mid.z() < z_pubis) continue;                     // below the symphysis: in front of the perineum
    layer.push_back(f.nodes);
  }
  if (layer.empty()) throw std::invalid_argument("abdominal wall: no face of the abdominal organ block faces the trunk-wall flesh");

  // The tetra flesh rests on every other level of the block's surface (body_mesher.cpp
  // build_tetra_flesh): two faces that share an edge of nodes the flesh does not hold become
  // one quad over the two layers, on the flesh cell's inner face.
  std::map<std::pair<int, int>, std::vector<std::size_t>> faces_of_edge;
  auto edge = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  for (std::size_t i = 0; i < layer.size(); ++i)
    for (int k = 0; k < 4; ++k) faces_of_edge[edge(layer[i][static_cast<std::size_t>(k)], layer[i][static_cast<std::size_t>((k + 1) % 4)])].push_back(i);
  std::vector<char> used(layer.size(), 0);
  std::vector<std::array<int, 4>> merged;
  for (std::size_t i = 0; i < layer.size(); ++i) {
    if (used[i]) continue;
    used[i] = 1;
    const auto& f = layer[i];
    bool done = false;
    for (int k = 0; k < 4 && !done; ++k) {
      const int p0 = f[static_cast<std::size_t>(k)], p1 = f[static_cast<std::size_t>((k + 1) % 4)];
      if (in_flesh[static_cast<std::size_t>(p0)] || in_flesh[static_cast<std::size_t>(p1)]) continue;
      for (std::size_t j : faces_of_edge[edge(p0, p1)]) {
        if (used[j]) continue;
        // f = p0 p1 p2 p3; g's nodes next to p0 and p1 (not on the shared edge) close the quad.
        const int p2 = f[static_cast<std::size_t>((k + 2) % 4)], p3 = f[static_cast<std::size_t>((k + 3) % 4)];
        const auto& g = layer[j];
        int next_to_p0 = -1, next_to_p1 = -1;
        for (int a = 0; a < 4; ++a) {
          const int here = g[static_cast<std::size_t>(a)], prev = g[static_cast<std::size_t>((a + 3) % 4)], next = g[static_cast<std::size_t>((a + 1) % 4)];
          if (here == p0 || here == p1) continue;
          if (prev == p0 || next == p0) next_to_p0 = here;
          if (prev == p1 || next == p1) next_to_p1 = here;
        }
        if (next_to_p0 < 0 || next_to_p1 < 0) continue;
        merged.push_back({p2, p3, next_to_p0, next_to_p1});
        used[j] = 1;
        done = true;
        break;
      }
    }
    if (!done) merged.push_back(f);
  }
  layer.swap(merged);

  material.name = "abdominal_wall";
  const int mat = m.add_material(material);
  FePart quad_part;
  quad_part.name = "abdominal_wall";
  quad_part.kind = ElementKind::Shell;
  quad_part.material = mat;
  quad_part.thickness = thickness_mm;
  quad_part.segment = "abdomen";
  quad_part.region = "flesh";
  FePart tria_part = quad_part;
  tria_part.name = "abdominal_wall_tria";
  tria_part.kind = ElementKind::Tria;
  const int qp = m.add_part(quad_part);
  int tp = -1;  // made with the first triangle

  AbdominalWallLayer out;
  std::set<int> layer_nodes;
  for (const auto& q : layer) {
    const Eigen::Vector3d &a = P(q[0]), &b = P(q[1]), &c = P(q[2]), &d = P(q[3]);
    out.area_mm2 += 0.5 * (c - a).cross(d - b).norm();
    layer_nodes.insert(q.begin(), q.end());
    if (quad_warpage_deg(a, b, c, d) <= 15) {
      m.shells.push_back(q);
      m.shell_part.push_back(qp);
      m.shell_thick.push_back(0);
      ++out.quads;
      continue;
    }
    std::array<int, 3> t1{q[0], q[1], q[3]}, t2{q[1], q[2], q[3]};  // along the shorter diagonal
    if ((c - a).norm() <= (d - b).norm()) t1 = {q[0], q[1], q[2]}, t2 = {q[0], q[2], q[3]};
    if (tp < 0) tp = m.add_part(tria_part);
    for (const auto& t : {t1, t2}) {
      m.trias.push_back(t);
      m.tria_part.push_back(tp);
      m.tria_thick.push_back(0);
    }
    out.trias += 2;
  }
  out.mass_kg = material.rho * thickness_mm * out.area_mm2;
  for (int n : layer_nodes) {
    bool rib = false, pelvis = false;
    for (int p : other[static_cast<std::size_t>(n)]) {
      const FePart& part = m.parts[static_cast<std::size_t>(p)];
      rib = rib || part.region == "ribs" || part.region == "cartilage";
      pelvis = pelvis || (part.region == "pelvis" && part.kind == ElementKind::Shell);
    }
    out.rib_nodes += rib ? 1 : 0;
    out.pelvis_nodes += pelvis ? 1 : 0;
  }
  std::ostringstream note;
  note << std::fixed << std::setprecision(3) << "abdominal wall: " << out.quads << " quads and " << out.trias
       << " triangles on the abdominal organ block's front and flanks, " << std::setprecision(0) << out.area_mm2
       << " mm^2; anchored at " << out.rib_nodes << " rib cage and " << out.pelvis_nodes
       << " pelvic shell nodes; its mass " << std::setprecision(3) << out.mass_kg
       << " kg is also in the flesh it lies in (materials.csv abdominal_wall)";
  m.notes.push_back(note.str());
  return out;
}

}  // namespace hbm::deckgen
