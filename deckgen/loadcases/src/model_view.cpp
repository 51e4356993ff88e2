// SPDX-License-Identifier: GPL-3.0-or-later
// Reads a body model deck into a ModelView (see model_view.hpp).
#include "hbm/deckgen/loadcases/model_view.hpp"

#include "hbm/deck/io.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hbm::deckgen::loadcases {

namespace {

// True when the first keyword line of the file is /BEGIN (a complete starter deck).
bool starts_with_begin(const std::filesystem::path& p) {
  std::ifstream in(p);
  if (!in) throw std::runtime_error(p.string() + ": cannot open the model deck");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (line[0] == '/') return line.rfind("/BEGIN", 0) == 0;
  }
  return false;
}

std::string wrapper_text(const std::filesystem::path& model) {
  using namespace hbm::deck;
  Deck d;
  d.section = Section::Starter;
  CardBuilder(d, "/BEGIN", 0, "model")
      .set_int(0, "Invers", 2024)
      .set_text(1, "mass", "kg").set_text(1, "length", "mm").set_text(1, "time", "ms")
      .set_text(2, "mass", "kg").set_text(2, "length", "mm").set_text(2, "time", "ms")
      .commit();
  std::ostringstream os;
  write_card(os, d.cards.back(), d);
  os << "#include " << std::filesystem::absolute(model).lexically_normal().string() << "\n/END\n";
  return os.str();
}

}  // namespace

ModelView read_model(const std::filesystem::path& model) {
  using namespace hbm::deck;
  const bool complete = starts_with_begin(model);
  ReadResult r = complete ? read_deck(model, Section::Starter)
                          : read_deck_text(wrapper_text(model), model.string() + " (wrapper)", Section::Starter);
  if (!r.ok()) {
    std::ostringstream os;
    print_diagnostics(os, r);
    throw std::runtime_error("the model deck " + model.string() + " has errors:\n" + os.str());
  }
  const Deck& d = r.deck;
  ModelView v;
  v.path = model;
  v.length_unit = d.work_units.length;
  v.mass_unit = d.work_units.mass;
  v.time_unit = d.work_units.time;
  for (const Card* c : d.cards_of("/NODE"))
    for (std::size_t i = 0; i < c->n_rows(); ++i) {
      const Row& row = c->row(i);
      const std::int64_t id = c->integer(row, "id");
      v.nodes[id] = Eigen::Vector3d(c->real(row, "X"), c->real(row, "Y"), c->real(row, "Z"));
      v.max_node_id = std::max(v.max_node_id, id);
    }
  for (const Card* c : d.cards_of("/PART")) v.part_titles[c->id] = c->title;
  struct ElementKw { const char* kw; int n; };
  static constexpr ElementKw kElements[] = {{"/BRICK", 8}, {"/TETRA4", 4}, {"/SHELL", 4}, {"/SH3N", 3}, {"/SPRING", 2}};
  for (const ElementKw& e : kElements)
    for (const Card* c : d.cards_of(e.kw)) {
      auto& list = v.part_nodes[c->id];
      for (std::size_t i = 0; i < c->n_rows(); ++i) {
        const Row& row = c->row(i);
        v.max_element_id = std::max(v.max_element_id, c->integer(row, "id"));
        static constexpr const char* kN[] = {"n1", "n2", "n3", "n4", "n5", "n6", "n7", "n8"};
        for (int k = 0; k < e.n; ++k) {
          const std::int64_t n = c->integer(row, kN[k]);
          if (n > 0) list.push_back(n);
        }
      }
    }
  for (auto& [p, list] : v.part_nodes) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  for (const Card& c : d.cards) {
    const std::string_view kw = c.keyword();
    bool element = false;
    for (const ElementKw& e : kElements) element = element || kw == e.kw;
    if (!element && kw != "/NODE") v.max_object_id = std::max(v.max_object_id, c.id);
  }
  return v;
}

std::vector<std::int64_t> ModelView::parts_with_prefix(const std::vector<std::string>& prefixes) const {
  std::vector<std::int64_t> out;
  for (const auto& [id, title] : part_titles)
    for (const auto& p : prefixes)
      if (title.rfind(p, 0) == 0) {
        out.push_back(id);
        break;
      }
  return out;
}

std::vector<std::int64_t> ModelView::nodes_of(const std::vector<std::int64_t>& parts) const {
  std::vector<std::int64_t> out;
  for (std::int64_t p : parts) {
    auto it = part_nodes.find(p);
    if (it != part_nodes.end()) out.insert(out.end(), it->second.begin(), it->second.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::string ModelView::part_list() const {
  std::string s;
  for (const auto& [id, title] : part_titles) s += "  " + std::to_string(id) + " " + title + "\n";
  return s;
}

}  // namespace hbm::deckgen::loadcases
