// SPDX-License-Identifier: GPL-3.0-or-later
// Anatomical variants of the thoracic organ block (see organ_variants.hpp).
#include "hbm/deckgen/organ_variants.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace hbm::deckgen {
namespace {

// The chest wall the lungs slide on: ribs, costal cartilage, sternum and the thoracic
// flesh (intercostal and pectoral muscle layer, the presternal fat) the block shares nodes
// with, by the budget regions body_mesher gives them.
bool is_chest_wall(const FePart& p) {
  return p.segment == "thorax" && (p.region == "flesh" || p.region == "ribs" || p.region == "cartilage" || p.region == "sternum");
}

int required_part(const FeModel& m, const std::string& name, const char* variant) {
  const int p = m.find_part(name);
  if (p < 0) throw std::invalid_argument(std::string(variant) + ": the model has no part " + name);
  return p;
}

// Calls f(node array, part index) for every solid element (bricks, then tetras).
template <class F>
void for_each_solid(FeModel& m, F&& f) {
  for (std::size_t e = 0; e < m.bricks.size(); ++e) f(m.bricks[e], m.brick_part[e]);
  for (std::size_t e = 0; e < m.tetras.size(); ++e) f(m.tetras[e], m.tetra_part[e]);
}

}  // namespace

std::size_t add_pleura(FeModel& m) {
  const int organs = required_part(m, "thoracic_organs", "pleura");
  const int mediastinum = m.find_part("mediastinum");  // part of the block where the model has it
  auto in_block = [&](int part) { return part == organs || (mediastinum >= 0 && part == mediastinum); };
  // What holds each node: kBlock the organ block, kWall the chest wall, kOther anything else
  // (elements of other parts, springs, rigid bodies). Contact interfaces do not hold a node:
  // the wall keeps the original, and the interfaces on it (clavicle on the rib cage) with it.
  enum : unsigned char { kBlock = 1, kWall = 2, kOther = 4 };
  std::vector<unsigned char> held(m.nodes.size(), 0);
  auto flag_of = [&](int part) -> unsigned char {
    if (in_block(part)) return kBlock;
    return is_chest_wall(m.parts[static_cast<std::size_t>(part)]) ? kWall : kOther;
  };
  auto mark = [&](const auto& elements, const std::vector<int>& part_of) {
    for (std::size_t e = 0; e < elements.size(); ++e)
      for (int n : elements[e]) held[static_cast<std::size_t>(n)] |= flag_of(part_of[e]);
  };
  mark(m.bricks, m.brick_part);
  mark(m.tetras, m.tetra_part);
  mark(m.shells, m.shell_part);
  mark(m.trias, m.tria_part);
  mark(m.springs, m.spring_part);
  for (const FeRigidBody& r : m.rigid_bodies) {
    held[static_cast<std::size_t>(r.main_node)] |= kOther;
    for (int n : r.nodes) held[static_cast<std::size_t>(n)] |= kOther;
  }
  // The block takes a copy of every node it shares with the wall alone, in node order.
  std::vector<int> copy_of(m.nodes.size(), -1);
  std::vector<int> wall_nodes;
  const std::size_t n_before = m.nodes.size();
  for (std::size_t n = 0; n < n_before; ++n)
    if (held[n] == (kBlock | kWall)) {
      copy_of[n] = m.add_node(Eigen::Vector3d(m.nodes[n]));
      wall_nodes.push_back(static_cast<int>(n));
    }
  if (wall_nodes.empty()) throw std::invalid_argument("pleura: the organ block shares no node with the chest wall alone");
  for_each_solid(m, [&](auto& nodes, int part) {
    if (!in_block(part)) return;
    for (int& n : nodes)
      if (copy_of[static_cast<std::size_t>(n)] >= 0) n = copy_of[static_cast<std::size_t>(n)];
  });
  FeInterface f;
  f.id = static_cast<int>(m.interfaces.size()) + 1;
  f.type = 7;
  f.name = "pleura";
  f.secondary = std::move(wall_nodes);
  f.main_parts = {organs};
  if (mediastinum >= 0) f.main_parts.push_back(mediastinum);
  // The wall nodes start on the block's faces: a 0.5 mm gap (Inacti 6 lets the solver take
  // the initial overlap out gently) and no friction (the pleural fluid).
  f.gap = 0.5;
  f.stiffness_factor = 1.0;
  f.friction = 0.0;
  m.interfaces.push_back(std::move(f));
  m.notes.push_back("pleura: the thoracic organ block slides on the chest wall (" + std::to_string(m.interfaces.back().secondary.size()) +
                    " wall nodes on the block, frictionless /INTER/TYPE7; hbm-deckgen --pleura)");
  return m.interfaces.back().secondary.size();
}

std::size_t add_mediastinum(FeModel& m, double half_width, double z_top) {
  std::ostringstream hw;
  hw << half_width;
  if (!(half_width > 0) || !std::isfinite(half_width))
    throw std::invalid_argument("mediastinum: the half width must be a positive number of mm (got " + hw.str() + ")");
  const int organs = required_part(m, "thoracic_organs", "mediastinum");
  const int material = m.find_material("abdominal_organs");
  if (material < 0) throw std::invalid_argument("mediastinum: the model has no material abdominal_organs");
  const int existing = m.find_part("mediastinum");
  // The block's elements (their part entries) and whether each lies in the column, found
  // before the model changes: an error leaves it as it was. A model that has a mediastinum
  // already is re-cut (the block is the thoracic organs and the old column together).
  std::vector<std::pair<int*, bool>> block;
  std::size_t inside = 0;
  for_each_solid(m, [&](const auto& nodes, int& part) {
    if (part != organs && (existing < 0 || part != existing)) return;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int n : nodes) c += m.nodes[static_cast<std::size_t>(n)];
    c /= static_cast<double>(nodes.size());
    const bool in = std::abs(c.y()) < half_width && c.z() < z_top;
    block.push_back({&part, in});
    inside += in ? 1 : 0;
  });
  // The column as the error and the deck's note name it.
  std::ostringstream where;
  where << "within " << hw.str() << " mm of the mid-plane";
  if (std::isfinite(z_top)) where << " and below z = " << std::fixed << std::setprecision(1) << z_top << " mm";
  if (inside == 0) throw std::invalid_argument("mediastinum: no thoracic organ element has its centroid " + where.str());
  int mediastinum = existing;
  if (mediastinum < 0) {
    FePart p = m.parts[static_cast<std::size_t>(organs)];
    p.name = "mediastinum";
    p.material = material;
    mediastinum = m.add_part(p);  // grows m.parts only: the part entries stay valid
  }
  for (auto& [part, in] : block) *part = in ? mediastinum : organs;
  // Under a pleura the column slides on the wall with the rest of the block.
  for (FeInterface& f : m.interfaces)
    if (std::find(f.main_parts.begin(), f.main_parts.end(), organs) != f.main_parts.end() &&
        std::find(f.main_parts.begin(), f.main_parts.end(), mediastinum) == f.main_parts.end())
      f.main_parts.push_back(mediastinum);
  m.notes.push_back("mediastinum: " + std::to_string(inside) + " thoracic organ elements " + where.str() +
                    " take the abdominal organ set (water-like)");
  return inside;
}

}  // namespace hbm::deckgen
