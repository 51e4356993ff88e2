// SPDX-License-Identifier: GPL-3.0-or-later
// /INTER/TYPE7 as an engine Interaction: the PenaltyContact kernel plus identity,
// energy bookkeeping (E_contact = -work of the contact forces) and time histories.
// /TH/INTER variables (forces on the secondary side, i.e. exerted by the main surface
// on the secondary nodes): FNX FNY FNZ (normal), FTX FTY FTZ (friction), FN, FT
// (magnitudes) [force]; ECONT contact energy (-work), EFRIC friction energy, EELAS
// penalty energy stored now, EDAMP damping energy [energy]; NACT nodes in contact.
#pragma once

#include "hbm/solver/interaction.hpp"
#include "penalty_contact.hpp"

#include <string>

namespace hbm::solver::contact {

class Type7Interface : public Interaction {
 public:
  Type7Interface(std::int64_t id, std::string title, PenaltyContact kernel)
      : id_(id), title_(std::move(title)), kernel_(std::move(kernel)) {}

  std::string_view kind() const override { return "/INTER/TYPE7"; }
  std::int64_t user_id() const override { return id_; }
  WorkKind work_kind() const override { return WorkKind::Contact; }
  void add_forces(const StepContext& step, NodalState& nodes) override {
    kernel_.add_forces(nodes, step.time, step.dt_prev);
  }
  double work() const override { return kernel_.work(); }
  double critical_step() const override { return kernel_.critical_step(); }

  std::optional<ThProbe> th_probe(ThKind kind, std::int64_t id,
                                  std::string_view variable) const override;
  std::vector<std::string> th_default_variables(ThKind kind) const override;
  bool owns_th_object(ThKind kind, std::int64_t id) const override {
    return kind == ThKind::Inter && id == id_;
  }

  const PenaltyContact& kernel() const { return kernel_; }
  PenaltyContact& kernel() { return kernel_; }

 private:
  std::int64_t id_;
  std::string title_;
  PenaltyContact kernel_;
};

}  // namespace hbm::solver::contact
