// SPDX-License-Identifier: GPL-3.0-or-later
// Structured O-grid of a trunk-like body region (torso, neck): at each level along the
// spine, an inner rectangular block (m x m cells, m = N/4) surrounded by three rings of N
// nodes: ring 1 on the inner wall (rib cage / abdominal wall / pelvic ring), ring 2 in the
// flesh, ring 3 on the skin. Ring 0 is the block boundary. Level surfaces pass through the
// vertebral endplate centres and are tilted by the rib inclination (anterior end lower);
// away from the spine they relax towards evenly spaced heights so that thin disc layers
// stay thin only near the spine. The grid owns node numbering and builds the hexahedra
// of one layer cell by cell; the body mesher decides what each cell is.
#pragma once

#include "hbm/deckgen/fe_model.hpp"
#include "hbm/deckgen/geometry_sources.hpp"

#include <array>
#include <string>
#include <vector>

namespace hbm::deckgen {

struct GridLevel {
  std::string name;
  double x_spine = 0, z_spine = 0;  // vertebral body centre line at this level
  double tilt = 0;                  // rad, level surface descends anteriorly
  double body_radius = 15;          // mm: within it the level follows the endplate exactly
};

struct GridParams {
  int n = 32;                 // nodes around (multiple of 8)
  double flesh_fraction = 0.45;  // ring 2 between wall and skin
  double relax_length = 15;   // mm: decay length of the endplate-following zone
  double block_front = 0.72;  // inner block front at this fraction of the wall depth
  double block_half_width = 0.5;  // inner block half-width / wall half-width
  double block_corner_back = 0.0;   // block back corners at this fraction of the wall depth (0: straight back edge)
};

class TrunkGrid {
 public:
  TrunkGrid(FeModel& model, const SectionTable& sections, std::vector<GridLevel> levels, GridParams p);

  int n() const { return p_.n; }
  int m() const { return p_.n / 4; }
  int levels() const { return static_cast<int>(levels_.size()); }
  const GridLevel& level(int l) const { return levels_[static_cast<std::size_t>(l)]; }
  // Node index of ring r (0..3) at angular position j (taken modulo N) of level l.
  int ring_node(int l, int r, int j) const;
  // Node index of the inner block node (a, b), a = 0 at the back, b = 0 on the right.
  int block_node(int l, int a, int b) const;
  // Hexahedron of ring layer r (0..2, between rings r and r+1), angular cell j (nodes j,
  // j+1), layer l (levels l, l+1); node order with positive volume.
  std::array<int, 8> ring_cell(int l, int r, int j) const;
  std::array<int, 8> block_cell(int l, int a, int b) const;
  // Quad on ring r between angular nodes j, j+1 and levels l, l+1, normal pointing outwards.
  std::array<int, 4> ring_face(int l, int r, int j) const { return ring_face_span(l, l + 1, r, j); }
  // The same between levels l_bottom and l_top (a face spanning several layers).
  std::array<int, 4> ring_face_span(int l_bottom, int l_top, int r, int j) const;
  // Cell spanning layers: the 8 given nodes (n1-n4 on the lower level, n5-n8 above them)
  // reordered to a positive volume as ring_cell orders its own.
  std::array<int, 8> oriented_cell(const std::array<int, 8>& h) const { return oriented(h); }
  // All node indices of level l.
  std::vector<int> level_nodes(int l) const;
  // Back midline angular index (N/2): the spine column is the cells j = N/2-1 and N/2 of
  // ring layers 0 and 1.
  int back() const { return p_.n / 2; }
  bool is_column_cell(int r, int j) const;
  // The level surface height at a horizontal point (used for neck-torso interfaces).
  double level_height(int l, double x, double y) const;

 private:
  std::array<int, 8> oriented(std::array<int, 8> h) const;
  void enforce_min_thickness();
  FeModel& model_;
  const SectionTable& sections_;
  std::vector<GridLevel> levels_;
  std::vector<double> z_uniform_;
  GridParams p_;
  std::vector<int> first_;  // first node index of each level
};

// Superellipse point at arc-length fraction s in [0, 1] of the left half (s = 0 front
// midline, s = 1 back midline), centre x_c, half-depth hd (x), half-width hw (y); the
// widest point (half-width hw) lies widest_forward ahead of the centre (0: symmetric).
Eigen::Vector2d superellipse_half_point(double x_c, double hd, double hw, double n, double s, double widest_forward = 0);

}  // namespace hbm::deckgen
