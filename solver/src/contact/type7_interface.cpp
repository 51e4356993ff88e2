// SPDX-License-Identifier: GPL-3.0-or-later
// Time-history probes of /INTER/TYPE7.
#include "type7_interface.hpp"

namespace hbm::solver::contact {

std::vector<std::string> Type7Interface::th_default_variables(ThKind kind) const {
  if (kind != ThKind::Inter) return {};
  return {"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ", "ECONT"};
}

std::optional<ThProbe> Type7Interface::th_probe(ThKind kind, std::int64_t id,
                                                std::string_view var) const {
  if (kind != ThKind::Inter || id != id_) return std::nullopt;
  using hbm::deck::Dimension;
  ThProbe p;
  p.object = "inter";
  p.id = id_;
  p.title = title_;
  p.variable = std::string(var);
  const PenaltyContact* k = &kernel_;
  p.unit = Dimension::Force;
  if (var == "FNX") p.read = [k] { return k->resultant().normal_force.x; };
  else if (var == "FNY") p.read = [k] { return k->resultant().normal_force.y; };
  else if (var == "FNZ") p.read = [k] { return k->resultant().normal_force.z; };
  else if (var == "FTX") p.read = [k] { return k->resultant().tangential_force.x; };
  else if (var == "FTY") p.read = [k] { return k->resultant().tangential_force.y; };
  else if (var == "FTZ") p.read = [k] { return k->resultant().tangential_force.z; };
  else if (var == "FN") p.read = [k] { return norm(k->resultant().normal_force); };
  else if (var == "FT") p.read = [k] { return norm(k->resultant().tangential_force); };
  else {
    p.unit = Dimension::Energy;
    if (var == "ECONT") p.read = [k] { return -k->work(); };
    else if (var == "EFRIC") p.read = [k] { return k->friction_energy(); };
    else if (var == "EELAS") p.read = [k] { return k->elastic_energy(); };
    else if (var == "EDAMP") p.read = [k] { return k->damping_energy(); };
    else if (var == "NACT") {
      p.unit = Dimension::Count;
      p.read = [k] { return static_cast<double>(k->resultant().n_active); };
    } else return std::nullopt;
  }
  return p;
}

}  // namespace hbm::solver::contact
