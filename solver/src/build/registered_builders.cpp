// SPDX-License-Identifier: GPL-3.0-or-later
// Expands builders.def into declarations and the ordered builder list.
#include "hbm/solver/build_context.hpp"

namespace hbm::solver {

#define HBM_BUILDER(fn) void fn(BuildContext&);
#include "builders.def"
#undef HBM_BUILDER

const std::vector<BuilderEntry>& registered_builders() {
  static const std::vector<BuilderEntry> list = {
#define HBM_BUILDER(fn) BuilderEntry{#fn, &fn},
#include "builders.def"
#undef HBM_BUILDER
  };
  return list;
}

}  // namespace hbm::solver
