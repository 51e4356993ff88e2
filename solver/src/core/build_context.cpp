// SPDX-License-Identifier: GPL-3.0-or-later
// Build-phase services: id tables (nodes, parts, materials, properties, functions, node
// groups), nodal mass and rotational DOFs, collection of groups / interactions /
// constraints, and diagnostics pointing into the deck.
#include "hbm/solver/build_context.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace hbm::solver {

struct BuildContext::Tables {
  std::unordered_map<std::int64_t, Index> nodes;
  std::unordered_map<std::int64_t, Index> parts;
  std::unordered_map<std::int64_t, const hbm::deck::Card*> materials, properties;
  std::unordered_map<std::int64_t, const FunctionCurve*> functions;
  std::unordered_map<std::int64_t, std::vector<Index>> node_groups;
};

namespace {

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

// Node indices of every element card of a part (for /GRNOD/PART), in deck order.
void nodes_of_part(const hbm::deck::Deck& deck, std::int64_t part_id,
                   const std::unordered_map<std::int64_t, Index>& node_map, std::vector<Index>& out) {
  static constexpr std::string_view kElementKeywords[] = {"/BRICK", "/TETRA4", "/SHELL", "/SH3N", "/SPRING"};
  static constexpr std::string_view kNodeFields[] = {"n1", "n2", "n3", "n4", "n5", "n6", "n7", "n8"};
  for (const auto& kw : kElementKeywords)
    for (const hbm::deck::Card* c : deck.cards_of(kw)) {
      if (c->id != part_id || !c->spec->rows) continue;
      const auto& fields = c->spec->rows->fields;
      for (std::size_t r = 0; r < c->n_rows(); ++r)
        for (const auto& f : kNodeFields) {
          if (std::none_of(fields.begin(), fields.end(), [&](const auto& fs) { return fs.name == f; }))
            continue;
          if (kw == "/SPRING" && f == "n3") continue;  // orientation node, not a spring node
          const std::int64_t id = c->integer(c->row(r), f);
          if (id == 0) continue;
          const auto it = node_map.find(id);
          if (it != node_map.end()) out.push_back(it->second);
        }
    }
}

}  // namespace

BuildContext::BuildContext(const hbm::deck::Deck& starter, const hbm::deck::Deck& engine, Model& model)
    : starter_(starter), engine_(engine), model_(model), tables_(std::make_shared<Tables>()) {
  Tables& t = *tables_;
  // Nodes.
  std::size_t n_nodes = 0;
  for (const hbm::deck::Card* c : starter.cards_of("/NODE")) n_nodes += c->n_rows();
  model.nodes.resize(n_nodes);
  Index next = 0;
  for (const hbm::deck::Card* c : starter.cards_of("/NODE"))
    for (std::size_t r = 0; r < c->n_rows(); ++r) {
      const auto& row = c->row(r);
      const std::int64_t id = c->integer(row, "id");
      if (!t.nodes.emplace(id, next).second) {
        error(*c, row, "id", "node " + std::to_string(id) + " defined twice");
        continue;
      }
      const auto k = static_cast<std::size_t>(next++);
      model.nodes.user_id[k] = id;
      model.nodes.x0.x[k] = model.nodes.x.x[k] = c->real(row, "X");
      model.nodes.x0.y[k] = model.nodes.x.y[k] = c->real(row, "Y");
      model.nodes.x0.z[k] = model.nodes.x.z[k] = c->real(row, "Z");
    }
  if (static_cast<std::size_t>(next) != n_nodes) model.nodes.resize(static_cast<std::size_t>(next));
  // Materials and properties (any /MAT/..., /PROP/... keyword).
  for (const auto& c : starter.cards) {
    if (starts_with(c.keyword(), "/MAT/")) {
      if (!t.materials.emplace(c.id, &c).second) error(c, "material id " + std::to_string(c.id) + " defined twice");
    } else if (starts_with(c.keyword(), "/PROP/")) {
      if (!t.properties.emplace(c.id, &c).second) error(c, "property id " + std::to_string(c.id) + " defined twice");
    }
  }
  // Parts.
  for (const hbm::deck::Card* c : starter.cards_of("/PART")) {
    Part p;
    p.id = c->id;
    p.title = c->title;
    p.prop_id = c->integer(0, "prop_id");
    p.mat_id = c->integer(0, "mat_id");
    p.part_card = c;
    if (p.prop_id != 0) {
      p.prop_card = property(p.prop_id);
      if (!p.prop_card) error(*c, c->lines.at(0), "prop_id", "no property " + std::to_string(p.prop_id));
    }
    // mat_id 0 is valid for spring parts (Radioss springs take their law from the
    // property); the deck checks already refuse it on solid and shell parts.
    if (p.mat_id != 0) {
      p.mat_card = material(p.mat_id);
      if (!p.mat_card) error(*c, c->lines.at(0), "mat_id", "no material " + std::to_string(p.mat_id));
      else p.mat_keyword = std::string(p.mat_card->keyword());
    }
    if (!t.parts.emplace(p.id, static_cast<Index>(model.parts.size())).second) {
      error(*c, "part id " + std::to_string(p.id) + " defined twice");
      continue;
    }
    model.parts.push_back(std::move(p));
  }
  // Functions.
  for (const hbm::deck::Card* c : starter.cards_of("/FUNCT")) {
    std::vector<double> xs, ys;
    for (std::size_t r = 0; r < c->n_rows(); ++r) {
      xs.push_back(c->real(c->row(r), "X"));
      ys.push_back(c->real(c->row(r), "Y"));
      if (r > 0 && !(xs[r] > xs[r - 1]))
        error(*c, c->row(r), "X", "abscissa must increase strictly");
    }
    if (xs.empty()) error(*c, "function without points");
    model.functions.push_back(std::make_unique<FunctionCurve>(c->id, c->title, std::move(xs), std::move(ys)));
    t.functions[c->id] = model.functions.back().get();
  }
  // Node groups.
  for (const hbm::deck::Card* c : starter.cards_of("/GRNOD/NODE")) {
    std::vector<Index> nodes;
    for (std::size_t r = 0; r < c->n_rows(); ++r)
      for (int k = 1; k <= 10; ++k) {
        const std::string f = "id" + std::to_string(k);
        const std::int64_t id = c->integer(c->row(r), f);
        if (id == 0) continue;
        const Index n = node_index(id);
        if (n == kNoIndex)
          error(*c, c->row(r), f, "no node " + std::to_string(id));
        else
          nodes.push_back(n);
      }
    t.node_groups[c->id] = std::move(nodes);
  }
  for (const hbm::deck::Card* c : starter.cards_of("/GRNOD/PART")) {
    std::vector<Index> nodes;
    for (std::size_t r = 0; r < c->n_rows(); ++r)
      for (int k = 1; k <= 10; ++k) {
        const std::string f = "id" + std::to_string(k);
        const std::int64_t id = c->integer(c->row(r), f);
        if (id == 0) continue;
        if (part_index(id) == kNoIndex) error(*c, c->row(r), f, "no part " + std::to_string(id));
        nodes_of_part(starter, id, t.nodes, nodes);
      }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    t.node_groups[c->id] = std::move(nodes);
  }
  for (std::string_view kw : {"/BEGIN", "/END", "/TITLE", "/NODE", "/PART", "/FUNCT", "/GRNOD/NODE", "/GRNOD/PART"})
    claim(kw);
  for (const auto& c : starter.cards)
    if (starts_with(c.keyword(), "/MAT/") || starts_with(c.keyword(), "/PROP/")) claim(c.keyword());
}

Index BuildContext::node_index(std::int64_t id) const {
  const auto it = tables_->nodes.find(id);
  return it == tables_->nodes.end() ? kNoIndex : it->second;
}
Index BuildContext::part_index(std::int64_t id) const {
  const auto it = tables_->parts.find(id);
  return it == tables_->parts.end() ? kNoIndex : it->second;
}
const hbm::deck::Card* BuildContext::material(std::int64_t id) const {
  const auto it = tables_->materials.find(id);
  return it == tables_->materials.end() ? nullptr : it->second;
}
const hbm::deck::Card* BuildContext::property(std::int64_t id) const {
  const auto it = tables_->properties.find(id);
  return it == tables_->properties.end() ? nullptr : it->second;
}
const FunctionCurve* BuildContext::function(std::int64_t id) const {
  const auto it = tables_->functions.find(id);
  return it == tables_->functions.end() ? nullptr : it->second;
}
const std::vector<Index>* BuildContext::node_group(std::int64_t id) const {
  const auto it = tables_->node_groups.find(id);
  return it == tables_->node_groups.end() ? nullptr : &it->second;
}

Index BuildContext::require_node(const hbm::deck::Card& card, const hbm::deck::Row& row,
                                 std::string_view field) {
  const std::int64_t id = card.integer(row, field);
  const Index n = node_index(id);
  if (n == kNoIndex) error(card, row, field, "no node " + std::to_string(id));
  return n;
}

const FunctionCurve* BuildContext::require_function(const hbm::deck::Card& card, const hbm::deck::Row& row,
                                                    std::string_view field, bool optional) {
  const std::int64_t id = card.integer(row, field);
  if (id == 0 && optional) return nullptr;
  const FunctionCurve* f = function(id);
  if (!f) error(card, row, field, "no function " + std::to_string(id));
  return f;
}

const std::vector<Index>* BuildContext::require_node_group(const hbm::deck::Card& card,
                                                           const hbm::deck::Row& row,
                                                           std::string_view field, bool optional) {
  const std::int64_t id = card.integer(row, field);
  if (id == 0 && optional) return nullptr;
  const std::vector<Index>* g = node_group(id);
  if (!g) error(card, row, field, "no node group " + std::to_string(id));
  return g;
}

void BuildContext::add_nodal_mass(Index node, double m) {
  model_.nodes.mass0[static_cast<std::size_t>(node)] += m;
}
void BuildContext::add_nodal_inertia(Index node, double inertia) {
  enable_rotation(node);
  model_.nodes.inertia0[static_cast<std::size_t>(node)] += inertia;
}
void BuildContext::enable_rotation(Index node) { model_.nodes.has_rotation[static_cast<std::size_t>(node)] = 1; }

void BuildContext::add_group(std::unique_ptr<ElementGroup> group) { model_.groups.push_back(std::move(group)); }
void BuildContext::add_interaction(std::unique_ptr<Interaction> i) { model_.interactions.push_back(std::move(i)); }
void BuildContext::add_constraint(std::unique_ptr<Constraint> c) { model_.constraints.push_back(std::move(c)); }

static std::string card_name(const hbm::deck::Card& card) {
  std::string s(card.keyword());
  if (card.id != 0) {  // appended in steps: GCC 12 reports a false -Wrestrict on "/" + std::to_string(..)
    s += '/';
    s += std::to_string(card.id);
  }
  return s;
}

void BuildContext::error(const hbm::deck::Card& card, std::string_view message) {
  const hbm::deck::Deck& d = (card.spec && card.spec->section == hbm::deck::Section::Engine) ? engine_ : starter_;
  messages_.push_back(d.where(card.loc) + ": error: " + card_name(card) + ": " + std::string(message));
  ++n_errors_;
}

void BuildContext::error(const hbm::deck::Card& card, const hbm::deck::Row& row, std::string_view field,
                         std::string_view message) {
  const hbm::deck::Deck& d = (card.spec && card.spec->section == hbm::deck::Section::Engine) ? engine_ : starter_;
  messages_.push_back(d.where(row.loc) + ": error: " + card_name(card) + " field " + std::string(field) +
                      ": " + std::string(message));
  ++n_errors_;
}

void BuildContext::warning(const hbm::deck::Card& card, std::string_view message) {
  const hbm::deck::Deck& d = (card.spec && card.spec->section == hbm::deck::Section::Engine) ? engine_ : starter_;
  messages_.push_back(d.where(card.loc) + ": warning: " + card_name(card) + ": " + std::string(message));
}

void BuildContext::messages_add_error_once(std::string message) {
  message = "error: " + message;
  if (std::find(messages_.begin(), messages_.end(), message) != messages_.end()) return;
  messages_.push_back(std::move(message));
  ++n_errors_;
}

void BuildContext::claim(std::string_view keyword) {
  if (std::find(claimed_.begin(), claimed_.end(), keyword) == claimed_.end()) claimed_.emplace_back(keyword);
}

double Model::total_mass0() const {
  double m = 0.0;
  for (std::size_t i = 0; i < nodes.n_nodes; ++i)
    if (!nodes.is_secondary[i]) m += nodes.mass0[i];
  return m;
}

}  // namespace hbm::solver
