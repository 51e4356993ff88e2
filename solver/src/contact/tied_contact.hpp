// SPDX-License-Identifier: GPL-3.0-or-later
// /INTER/TYPE2 tied contact: secondary nodes glued to a main surface with a
// non-matching mesh, kinematically (Radioss TYPE2 formulation).
//
// Build: each secondary node s is projected once on the closest main segment (within
// dsearch); the shape function values N_i of the projection are kept. The node's
// physical mass is lumped onto the segment nodes, m_i += N_i m_s, and s is flagged
// secondary (excluded from M0, the velocity update and mass scaling).
// Each cycle: gather_forces moves the force and nodal stiffness of s onto the segment,
// f_i += N_i f_s, k_i += N_i k_s, f_s = 0; impose_dependent sets v_s = sum N_i v_i.
// Since sum N_i = 1, the total force and the total momentum
// sum_i (m_i + N_i m_s) v_i are exactly those of the unconstrained system: momentum is
// exchanged exactly through the interface.
#pragma once

#include "contact_surface.hpp"
#include "hbm/solver/constraint.hpp"
#include "vec3.hpp"

#include <array>
#include <string>
#include <vector>

namespace hbm::solver::contact {

struct TiedLink {
  Index secondary = kNoIndex;
  std::array<Index, 4> main{};       // segment nodes
  std::array<double, 4> weight{};    // N_i at the projection (sum 1)
  double distance = 0;               // secondary node to segment at build [length]
};

class TiedContact : public Constraint {
 public:
  // Projects each node on the closest segment of `main`; nodes farther than `dsearch`
  // (> 0) are returned in `untied` and not linked. Positions: nodes.x (= x0 at build).
  TiedContact(std::int64_t id, std::string title, const ContactSurface& main,
              const std::vector<Index>& secondary, double dsearch, const NodalState& nodes,
              std::vector<Index>& untied);

  std::string_view kind() const override { return "/INTER/TYPE2"; }
  std::int64_t user_id() const override { return id_; }

  // Lumps the secondary masses on the main nodes and flags the secondaries (build phase,
  // after every element added its mass). Call once.
  void transfer_mass(NodalState& nodes) const;

  void gather_forces(const StepContext& step, NodalState& nodes) override;
  void impose_dependent(const StepContext& step, NodalState& nodes) override;

  std::optional<ThProbe> th_probe(ThKind kind, std::int64_t id,
                                  std::string_view variable) const override;
  std::vector<std::string> th_default_variables(ThKind kind) const override;
  bool owns_th_object(ThKind kind, std::int64_t id) const override {
    return kind == ThKind::Inter && id == id_;
  }

  const std::vector<TiedLink>& links() const { return links_; }
  V3 transferred_force() const { return force_; }  // sum of f_s moved this cycle [force]

 private:
  std::int64_t id_;
  std::string title_;
  std::vector<TiedLink> links_;
  V3 force_;
};

}  // namespace hbm::solver::contact
