// SPDX-License-Identifier: GPL-3.0-or-later
// Build phase services handed to every builder (one per element / interaction /
// constraint type, listed in solver/src/build/builders.def). A builder reads the cards
// it owns from the decks, resolves ids through this context, adds nodal masses and
// rotational DOFs, and appends its groups, interactions or constraints. Errors are
// collected (file:line, keyword, field) and the run stops after the build phase if any.
#pragma once

#include "hbm/deck/deck.hpp"
#include "hbm/solver/model.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hbm::solver {

class BuildContext {
 public:
  BuildContext(const hbm::deck::Deck& starter, const hbm::deck::Deck& engine, Model& model);

  const hbm::deck::Deck& starter() const { return starter_; }
  const hbm::deck::Deck& engine() const { return engine_; }
  Model& model() { return model_; }
  NodalState& nodes() { return model_.nodes; }

  // --- id resolution (each returns kNoIndex / nullptr when unknown) -------------------
  Index node_index(std::int64_t node_id) const;
  Index part_index(std::int64_t part_id) const;
  const Part& part(Index part) const { return model_.parts[static_cast<std::size_t>(part)]; }
  const hbm::deck::Card* material(std::int64_t mat_id) const;  // any /MAT/... card
  const hbm::deck::Card* property(std::int64_t prop_id) const; // any /PROP/... card
  const FunctionCurve* function(std::int64_t funct_id) const;
  const std::vector<Index>* node_group(std::int64_t grnod_id) const;  // /GRNOD/NODE|PART

  // Resolving variants that record an error at the card's row naming keyword and field
  // when the id is unknown (or 0 when !optional); return kNoIndex / nullptr then.
  Index require_node(const hbm::deck::Card& card, const hbm::deck::Row& row,
                     std::string_view field);
  const FunctionCurve* require_function(const hbm::deck::Card& card, const hbm::deck::Row& row,
                                        std::string_view field, bool optional = false);
  const std::vector<Index>* require_node_group(const hbm::deck::Card& card,
                                               const hbm::deck::Row& row,
                                               std::string_view field, bool optional = false);

  // --- nodal properties ------------------------------------------------------------------
  void add_nodal_mass(Index node, double mass);        // physical lumped mass [mass]
  void add_nodal_inertia(Index node, double inertia);  // also enables rotation [mass*length^2]
  void enable_rotation(Index node);
  // Attribute element mass to a part (for the per-part mass report).
  void add_part_mass(Index part, double mass) { model_.parts[static_cast<std::size_t>(part)].mass0 += mass; }

  // --- results of a builder ----------------------------------------------------------
  void add_group(std::unique_ptr<ElementGroup> group);
  void add_interaction(std::unique_ptr<Interaction> interaction);
  void add_constraint(std::unique_ptr<Constraint> constraint);

  // --- diagnostics ---------------------------------------------------------------------
  // "file:line: error: /MAT/LAW34/3 field K = 0: must be > 0"
  void error(const hbm::deck::Card& card, std::string_view message);
  void error(const hbm::deck::Card& card, const hbm::deck::Row& row, std::string_view field,
             std::string_view message);
  void warning(const hbm::deck::Card& card, std::string_view message);
  // An error not tied to one card (e.g. a required card missing), recorded once.
  void messages_add_error_once(std::string message);
  bool ok() const { return n_errors_ == 0; }
  const std::vector<std::string>& messages() const { return messages_; }

  // Mark a keyword as handled: after all builders ran, any starter card of a keyword
  // no builder claimed is reported as "not supported by the engine" (never ignored).
  void claim(std::string_view keyword);
  const std::vector<std::string>& claimed() const { return claimed_; }

 private:
  const hbm::deck::Deck& starter_;
  const hbm::deck::Deck& engine_;
  Model& model_;
  std::vector<std::string> messages_;
  std::vector<std::string> claimed_;
  std::size_t n_errors_ = 0;
  struct Tables;
  std::shared_ptr<Tables> tables_;  // id maps, built on construction
};

// A builder: reads its cards and adds what it builds. Registered in builders.def.
using BuilderFn = void (*)(BuildContext&);

struct BuilderEntry {
  std::string_view name;
  BuilderFn build;
};

// All builders in execution order (solver/src/build/builders.def).
const std::vector<BuilderEntry>& registered_builders();

// Build phase entry: core tables (nodes, parts, functions, groups of nodes, run control),
// then every registered builder, then the assembly incidence. Returns false with the
// messages in `messages` if the decks cannot be run.
bool build_model(const hbm::deck::Deck& starter, const hbm::deck::Deck& engine, Model& model,
                 std::vector<std::string>& messages);

}  // namespace hbm::solver
