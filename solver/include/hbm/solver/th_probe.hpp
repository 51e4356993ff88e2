// SPDX-License-Identifier: GPL-3.0-or-later
// Time-history probes. The core reads the /TH/... cards of the starter deck; for each
// (object kind, object id, variable name) it asks the object's owner (an element group,
// an interaction or a constraint; /TH/NODE and /TH/PART are answered by the core) for a
// probe: the column label, its unit and a reader called at every /TFILE output.
// Readers are not in the hot loop; std::function is fine here.
#pragma once

#include "hbm/deck/schema.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hbm::solver {

// The /TH/<kind> keyword the probe answers.
enum class ThKind : std::uint8_t { Node, Part, Spring, Inter, Rbody, Rwall, Beam, Shell, Brick };

// One CSV column. The header is written as
//   "<object> <id> <title> <variable> [<unit>]"   e.g. "node 1201 sternum DX [mm]"
// with the unit text derived from `unit` and the deck's /BEGIN work units.
struct ThProbe {
  std::string object;         // "node", "part", "spring", "inter", "rbody", "rwall"
  std::int64_t id = 0;        // user id
  std::string title;          // object title (may be empty)
  std::string variable;       // "DX", "FN", "IE" ...
  hbm::deck::Dimension unit = hbm::deck::Dimension::None;
  std::function<double()> read;  // value at the output time (forces as forces)
};

// Implemented by every owner of time-history objects.
class ThSource {
 public:
  virtual ~ThSource() = default;
  // Probe for one variable of one object, or nullopt when this owner does not own the
  // object (the core then asks the next owner) or knows no such variable (the core
  // reports a deck error naming the /TH card and the variable).
  virtual std::optional<ThProbe> th_probe(ThKind kind, std::int64_t id,
                                          std::string_view variable) const {
    return std::nullopt;
  }
  // Variables written for the name "DEF" (the default set), empty if none.
  virtual std::vector<std::string> th_default_variables(ThKind kind) const { return {}; }
  // True when this owner owns object `id` of `kind` (used for "unknown id" errors).
  virtual bool owns_th_object(ThKind kind, std::int64_t id) const { return false; }
};

}  // namespace hbm::solver
