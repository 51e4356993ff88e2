// SPDX-License-Identifier: GPL-3.0-or-later
// Construction of a spring group from a resolved property and its elements: initial
// lengths, per-element history, frames (TYPE13), slot buffers. Used by the /SPRING
// builder and by the tests; nodal masses and inertias are the caller's (the builder adds
// them through the BuildContext, see spring_nodal_share()).
#pragma once

#include "springs/spring_group.hpp"

#include <memory>

namespace hbm::solver::springs {

// Mass and inertia a spring gives to each of its two nodes (half of the property's,
// times the initial length when the property is per unit length).
struct SpringNodalShare {
  double mass = 0;     // [mass]
  double inertia = 0;  // [mass*length^2]
};
SpringNodalShare spring_nodal_share(const SpringProperty& prop, double length0);

// True when some rotational DOF of a 6-DOF property has a stiffness, damping or curve.
bool has_rotational_law(const SpringProperty& prop);

// `orientation` (TYPE13 only, optional): per element the node n3 whose position gives
// the initial local y axis (kNoIndex: from the skew or the global axes).
std::unique_ptr<SpringGroup> make_spring_group(const SpringProperty& prop, Index part,
                                               std::vector<Index> connectivity,
                                               std::vector<std::int64_t> element_ids,
                                               const NodalState& nodes,
                                               const std::vector<Index>* orientation = nullptr);

}  // namespace hbm::solver::springs
