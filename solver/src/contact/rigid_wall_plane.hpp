// SPDX-License-Identifier: GPL-3.0-or-later
// /RWALL/PLANE: infinite plane rigid wall acting on the velocities (a kinematic
// condition, as Radioss rigid walls are), fixed or moving.
//
// After v^{n+1/2} is known, a secondary node whose predicted distance to the wall
// d^{n+1} = d^n + dt (v - V_w) . n would become negative gets its relative normal
// velocity set to -max(d^n, 0)/dt: it lands on the wall at t^{n+1} and never goes
// through. Slide = 0: only the normal velocity changes; Slide = 1 (tied): once touched,
// the node moves with the wall; Slide = 2: Coulomb friction on the impulse, the
// tangential relative velocity drops by at most fric |dv_n| (so a block sliding under
// gravity decelerates at fric g).
//
// A moving wall is a model node (node_id) carrying the wall mass; the wall point M
// follows it, the normal keeps its direction. Node and wall velocities are solved
// together so that momentum is exact: with targets r_i = -max(d_i, 0)/dt,
//   V_n' = (M V_n + sum m_i (v_in - r_i)) / (M + sum m_i),  v_in' = V_n' + r_i,
// and tangential (friction, tied) impulses are applied back to the wall node.
// Wall force (time histories): the force of the model on the wall,
//   F = -sum m_i (v_i' - v_i) / dt^n over the secondary nodes [force].
//
// Secondary nodes that are secondaries of a rigid body (/RBODY) cannot take a velocity
// change (the body imposes theirs after this stage). For them the wall states per node
// the same condition, x^{n+1} . n >= min(d^n, 0) from the wall (tied: x^{n+1} fixed;
// Slide 2: Coulomb), and the body solves all its touching nodes at once
// (rigid::WallContactBody, a projected Gauss-Seidel over the points): the impulses go to
// the body's translation and angular momentum, their work into the reaction work. Needs
// the rigid bodies registered before the wall (builders.def) so that the body's own
// velocity update has run. Fixed walls only (a moving wall with rigid-body secondaries
// is a deck error).
#pragma once

#include "hbm/solver/constraint.hpp"
#include "rigid/wall_contact_body.hpp"
#include "vec3.hpp"

#include <string>
#include <vector>

namespace hbm::solver::contact {

struct RigidWallPlaneParams {
  std::int64_t id = 0;
  std::string title;
  int slide = 0;           // 0 sliding, 1 tied, 2 sliding with friction
  double fric = 0.0;       // Coulomb coefficient (Slide 2)
  V3 point;                // M (fixed wall) [length]
  V3 normal{0, 0, 1};      // unit normal, from M towards M1: the allowed side
  Index wall_node = kNoIndex;  // moving wall: its node (M follows it)
};

class RigidWallPlane : public Constraint {
 public:
  RigidWallPlane(RigidWallPlaneParams p, std::vector<Index> secondary);
  // Secondary nodes of `body` (indices into body.secondary_nodes()) on this wall.
  void add_body(rigid::WallContactBody& body, const std::vector<std::size_t>& body_secondaries);

  std::string_view kind() const override { return "/RWALL/PLANE"; }
  std::int64_t user_id() const override { return p_.id; }
  // Stage 1: remembers v^{n-1/2} of the secondary nodes (and wall node) for the
  // reaction work; stage 2: the wall condition on v^{n+1/2}.
  void gather_forces(const StepContext& step, NodalState& nodes) override;
  void impose_velocities(const StepContext& step, NodalState& nodes) override;
  double reaction_work() const override { return reaction_work_; }

  std::optional<ThProbe> th_probe(ThKind kind, std::int64_t id,
                                  std::string_view variable) const override;
  std::vector<std::string> th_default_variables(ThKind kind) const override;
  bool owns_th_object(ThKind kind, std::int64_t id) const override {
    return kind == ThKind::Rwall && id == p_.id;
  }

  V3 normal_force() const { return fn_; }       // on the wall, this cycle [force]
  V3 tangential_force() const { return ft_; }   // on the wall, this cycle [force]
  const std::vector<Index>& secondary() const { return secondary_; }
  std::size_t n_body_nodes() const { return body_points_.size(); }

 private:
  // Rigid-body secondaries: solved by their body (see the header comment).
  // Adds the work of this step to reaction_work_ and pending_work_ (counted at t^{n+1}).
  void impose_on_bodies(const StepContext& step, NodalState& nodes, V3 wall_x);
  double pending_work_ = 0;  // body work of the last step's impulses due at t^{n+1}
  struct BodyOnWall {
    rigid::WallContactBody* body = nullptr;
    std::size_t first = 0, count = 0;  // range in body_points_
  };
  std::vector<BodyOnWall> bodies_;
  std::vector<rigid::WallContactPoint> body_points_;
  std::vector<Index> body_point_node_;
  std::vector<std::uint8_t> body_point_tied_;

  RigidWallPlaneParams p_;
  std::vector<Index> secondary_;
  std::vector<std::uint8_t> tied_;  // Slide 1: node stuck to the wall
  std::vector<double> r_;           // scratch: target relative normal velocity
  std::vector<std::uint8_t> hit_;   // scratch: node in contact this cycle
  std::vector<V3> v_prev_;          // v^{n-1/2} of each secondary node
  V3 wall_v_prev_;
  V3 fn_, ft_;
  double reaction_work_ = 0;
};

}  // namespace hbm::solver::contact
