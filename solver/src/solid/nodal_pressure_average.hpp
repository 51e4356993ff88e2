// SPDX-License-Identifier: GPL-3.0-or-later
// Average nodal pressure for 4-node tetrahedra (/PROP/TYPE14 Itetra4 3): the volumetric
// strain is taken at the nodes, not in the element (Bonet & Burton 1998, "A simple average
// nodal pressure tetrahedral element for incompressible and nearly incompressible dynamic
// explicit applications", Commun. Numer. Meth. Engng 14:437-449).
//
// Each node n of the group owns a quarter of the volume of every tetra around it:
// V_n = sum_e V_e / 4 (V0_n likewise at t = 0), J_n = V_n / V0_n. A tetra's pressure is the
// mean over its four nodes of the material's pressure at J_n; for the hypoelastic bulk of
// every solid law here (dp = -K tr(D) dt) that is p_e = -K (1/4) sum_n ln J_n. The forces
// still use the element's own volume gradient, f_I = -(dev s - p_e I) b_I, so the pressure
// work is sum_e p_e dV_e = sum_n p_n dV_n: the potential of the nodal volumes, energy
// conserving. With one pressure per node instead of one per tetra the mesh no longer
// carries about one volume constraint per element, which locks constant strain tetras as
// nu -> 1/2 (a tetra mesh has ~5-6 tetras per node). The deviator stays element-constant.
// Averaging is over the tetras of the group (one part): nodes shared with other parts take
// only this part's volumes.
#pragma once

#include "hbm/solver/types.hpp"
#include "solid/small_strain_switch.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hbm::solver {

struct NodalState;

class NodalPressureAverage {
 public:
  bool enabled = false;

  // Group-local node numbering and V0_n from the tetras' initial volumes.
  void setup(const std::vector<Index>& connectivity, const std::vector<double>& volume0);

  // Current nodal volumes from the tetras of the group (alive or not: a deleted tetra keeps
  // its share frozen at V0, so it neither pulls nor pushes its nodes), then each tetra's
  // mean ln J_n into mean_log_j. A node whose volume is not positive (only around inverted
  // tetras, which stop the run) counts ln J = 0. A tetra switched to small strain counts the
  // volume of its frozen shape (its volume at the switch): from the switch on it neither pulls
  // nor pushes its nodes' volumes and carries its own pressure (a flattened tetra's frozen
  // gradients would turn small normal velocities into large volume changes).
  void update(const NodalState& nodes, const std::vector<Index>& connectivity, const std::vector<std::uint8_t>& alive,
              const FrozenGeometry& frozen);

  double mean_log_j(std::size_t e) const { return mean_log_j_[e]; }

 private:
  std::vector<Index> local_;     // per connectivity slot: group-local node
  std::vector<double> v0_, v_;   // per local node [length^3]
  std::vector<double> log_j_;    // per local node: ln(V_n / V0_n)
  std::vector<double> volume0_;  // per tetra (frozen share of a deleted one)
  std::vector<double> mean_log_j_;
};

}  // namespace hbm::solver
