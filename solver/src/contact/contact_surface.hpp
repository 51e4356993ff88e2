// SPDX-License-Identifier: GPL-3.0-or-later
// A contact surface: the segments of a main surface (/SURF/PART, /SURF/SEG), each a
// triangle or a quadrilateral, with what the penalty law needs from the element under
// it: the reference stiffness K0 (Radioss TYPE7 Istf=0, Reference Guide "Interface
// stiffness": shells K0 = 0.5 Stfac E t, solids K0 = 0.5 Stfac B A^2 / V with B the bulk
// modulus, A the face area, V the element volume; Stfac is applied by the interface),
// the shell thickness (for gaps from thickness), and whether the segment is one-sided
// (outer face of a solid, normal pointing out of the material) or two-sided (shell).
//
// Outer faces of solids are the faces used by exactly one element of the listed solids;
// they are oriented outward with respect to their element's centroid, so the surface
// of a closed solid has consistent outward normals whatever the element numbering.
#pragma once

#include "hbm/solver/types.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace hbm::solver::contact {

struct ContactSurface {
  std::vector<std::array<Index, 4>> nodes;  // triangle: nodes[3] == nodes[2]
  std::vector<double> k0;                   // segment stiffness without Stfac [force/length]
  std::vector<double> thickness;            // shell thickness, 0 for solid faces [length]
  std::vector<std::uint8_t> one_sided;      // 1: solid outer face (outward normal)
  std::vector<double> depth;                // one-sided: deepest penetration still treated
                                            //   as contact (half the element's size) [length]

  std::size_t size() const { return nodes.size(); }
  bool is_triangle(std::size_t s) const { return nodes[s][3] == nodes[s][2]; }
  void append(const ContactSurface& other);
};

// A solid element as the surface builder needs it: 8 nodes in Radioss /BRICK order
// (n1-n4 one face, n5-n8 the opposite one; repeated nodes make prisms, pyramids and
// tetrahedra) and its material bulk modulus [stress]. A /TETRA4 is passed as
// n1 n2 n3 n3 n4 n4 n4 n4.
struct SolidForSurface {
  std::array<Index, 8> nodes;
  double bulk_modulus = 0;
};

// A shell element: 4 nodes (triangle: n4 == n3), Young's modulus and thickness.
struct ShellForSurface {
  std::array<Index, 4> nodes;
  double young = 0;
  double thickness = 0;
};

// Faces used by exactly one element of `solids`, oriented outward, with K0 from their
// element. Positions are the initial coordinates (x, y, z arrays indexed by node).
ContactSurface solid_outer_faces(const std::vector<SolidForSurface>& solids,
                                 const std::vector<double>& x, const std::vector<double>& y,
                                 const std::vector<double>& z);

// One segment per shell, two-sided, K0 = 0.5 E t.
ContactSurface shell_segments(const std::vector<ShellForSurface>& shells);

// Volume of a (possibly degenerate) brick from the divergence theorem over its faces,
// V = 1/3 sum_f c_f . A_f (c_f face centroid, A_f outward area vector) [length^3].
double brick_volume(const std::array<Index, 8>& n, const std::vector<double>& x,
                    const std::vector<double>& y, const std::vector<double>& z);

}  // namespace hbm::solver::contact
