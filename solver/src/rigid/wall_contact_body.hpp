// SPDX-License-Identifier: GPL-3.0-or-later
// A rigid body as seen by a kinematic rigid wall (/RWALL/PLANE) whose secondary nodes
// are secondaries of the body. The wall cannot change the velocity of such a node (the
// body overwrites it in impose_dependent), so it hands the contact points of the body to
// the body, which solves the plastic (e = 0) contact of all of them at once and applies
// the impulses to its own translation and angular momentum (momentum and angular
// momentum about the centre exact). Called in the velocity stage (impose_velocities),
// after the body's own impose_velocities and before its impose_dependent.
//
// Header only (pure interface): the wall in contact/ reaches the body through it, with
// no link dependency on the rigid area.
#pragma once

#include "hbm/solver/nodal_state.hpp"
#include "hbm/solver/step_context.hpp"

#include <Eigen/Dense>

#include <span>
#include <vector>

namespace hbm::solver::rigid {

// One secondary node of the body on one wall. Position constraint at t^{n+1}:
//   normal . x^{n+1} >= floor   (unilateral, impulse along +normal only)
// Tied points (Slide 1) are held at `target` in all three components instead.
// Friction (Slide 2): tangential impulse |p_t| <= fric * p_n (Coulomb), opposing the
// tangential displacement of the step.
struct WallContactPoint {
  std::size_t secondary = 0;  // index in the body's secondary list
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit wall normal (allowed side)
  double floor = 0;           // lowest allowed normal . x^{n+1} [length]
  Eigen::Vector3d target = Eigen::Vector3d::Zero();   // tied: x^{n+1} [length]
  bool tied = false;
  double fric = 0;            // Coulomb coefficient (0: frictionless, infinity: stick)
  // Results of resolve_wall_contacts:
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();  // wall impulse on the node [force*time]
  bool touched = false;       // carried an impulse this step
};

// Work of the wall impulses on the body, split over the two half steps it spans so that
// the engine's energy balance holds at every t^n (see rigid_wall_contact.cpp) [energy].
struct WallContactWork {
  double at_n = 0;     // counted now, at t^n
  double at_next = 0;  // counted at t^{n+1}
};

class WallContactBody {
 public:
  virtual ~WallContactBody() = default;
  virtual const std::vector<Index>& secondary_nodes() const = 0;
  // Position of secondary j at t^{n+1} from the body's current v^{n+1/2} and rotation.
  virtual Eigen::Vector3d predicted_position(const NodalState& nodes, std::size_t j, double dt) const = 0;
  // Solve the contact of all `points` (a complementarity problem over the points that
  // would violate their constraint), apply the impulses to the body, write them into the
  // points. Returns the work of the impulses on the body.
  virtual WallContactWork resolve_wall_contacts(const StepContext& step, NodalState& nodes,
                                       std::span<WallContactPoint> points) = 0;
};

}  // namespace hbm::solver::rigid
