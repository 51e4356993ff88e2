// SPDX-License-Identifier: GPL-3.0-or-later
// Posed variant of the body model: path and consistency with the base model (see posed_model.hpp).
#include "hbm/deckgen/loadcases/posed_model.hpp"

#include <algorithm>
#include <set>
#include <sstream>
#include <stdexcept>

namespace hbm::deckgen::loadcases {

std::filesystem::path posed_model_path(const std::filesystem::path& base_model, const std::string& posed_model) {
  const std::filesystem::path p(posed_model);
  if (p.is_absolute()) return p;
  return (std::filesystem::absolute(base_model).lexically_normal().parent_path().parent_path() / p).lexically_normal();
}

void check_posed_model(const ModelView& base, const ModelView& posed, const std::vector<std::string>& posed_part_prefixes,
                       const std::string& regenerate_command) {
  auto fail = [&](const std::string& what) {
    throw std::runtime_error(posed.path.string() + ": the posed model does not match the base model " + base.path.string() +
                             " (" + what + "); regenerate it: " + regenerate_command);
  };
  if (posed.part_titles != base.part_titles) fail("different parts");
  if (posed.nodes.size() != base.nodes.size()) fail(std::to_string(posed.nodes.size()) + " nodes against " + std::to_string(base.nodes.size()));
  const auto limbs = base.parts_with_prefix(posed_part_prefixes);
  if (limbs.size() != posed_part_prefixes.size()) fail("posed parts not all found");
  const auto limb_list = base.nodes_of(limbs);
  const std::set<std::int64_t> limb_nodes(limb_list.begin(), limb_list.end());
  for (const auto& [pid, list] : base.part_nodes) {
    if (std::find(limbs.begin(), limbs.end(), pid) != limbs.end()) continue;
    auto it = posed.part_nodes.find(pid);
    if (it == posed.part_nodes.end() || it->second != list) fail("elements of part " + base.part_titles.at(pid) + " differ");
    for (std::int64_t n : list) {
      if (limb_nodes.count(n)) continue;  // a node shared with a posed limb moves with it
      auto q = posed.nodes.find(n);
      if (q == posed.nodes.end()) fail("node " + std::to_string(n) + " missing");
      if ((q->second - base.nodes.at(n)).norm() > 1e-6) {
        std::ostringstream os;
        os << "node " << n << " of part " << base.part_titles.at(pid) << " at (" << q->second.transpose() << ") instead of ("
           << base.nodes.at(n).transpose() << ")";
        fail(os.str());
      }
    }
  }
}

}  // namespace hbm::deckgen::loadcases
