// SPDX-License-Identifier: GPL-3.0-or-later
// What the load-case generator needs to know about a body model deck (for instance
// decks/hbm50/hbm50.inc): node coordinates, part titles, the nodes of each part, and the
// largest ids in use so that load-case objects never collide with model objects.
// The model is read with the deck library (all its checks apply); an include file
// without /BEGIN is read through a wrapper deck that #includes it.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace hbm::deckgen::loadcases {

struct ModelView {
  std::filesystem::path path;
  std::map<std::int64_t, Eigen::Vector3d> nodes;           // node id -> position (mm)
  std::map<std::int64_t, std::string> part_titles;         // part id -> title
  std::map<std::int64_t, std::vector<std::int64_t>> part_nodes;  // part id -> sorted node ids
  std::int64_t max_node_id = 0;
  std::int64_t max_element_id = 0;
  std::int64_t max_object_id = 0;  // largest id of any other card (parts, materials, groups, ...)
  std::string length_unit = "mm", mass_unit = "kg", time_unit = "ms";

  // Parts whose title starts with one of the prefixes (exact title match counts).
  std::vector<std::int64_t> parts_with_prefix(const std::vector<std::string>& prefixes) const;
  // Sorted unique nodes of the given parts.
  std::vector<std::int64_t> nodes_of(const std::vector<std::int64_t>& parts) const;
  // "id title" list of all parts, for error messages.
  std::string part_list() const;
};

// Reads the model. Throws std::runtime_error carrying the deck diagnostics
// (file:line:col: error: ...) when the model deck has errors.
ModelView read_model(const std::filesystem::path& model);

}  // namespace hbm::deckgen::loadcases
