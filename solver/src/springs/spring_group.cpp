// SPDX-License-Identifier: GPL-3.0-or-later
// Common part of the spring groups: state allocation, nodal stiffness for the time step,
// energy sum and the /TH/SPRING probes.
#include "springs/spring_group.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hbm::solver::springs {

double damped_nodal_stiffness(double k, double c, double m) {
  if (c <= 0) return k;
  if (m <= 0) return std::numeric_limits<double>::infinity();
  // dt_c = 2 m_r / (sqrt(m_r k + c^2/4) + c/2), m_r = m/2; k_eq = 2 m / dt_c^2.
  const double mr = 0.5 * m;
  const double den = std::sqrt(mr * k + 0.25 * c * c) + 0.5 * c;
  return 2.0 * m * den * den / (4.0 * mr * mr);
}

void SpringGroup::init_state() {
  n_dofs = prop.dofs.size();
  state.assign(n_elements * n_dofs, SpringDofState{});
  out_force.assign(n_elements, {});
  out_def.assign(n_elements, {});
  law_scale.resize(n_elements);
  for (std::size_t e = 0; e < n_elements; ++e)
    law_scale[e] = prop.per_length ? 1.0 / length0[e] : 1.0;
  reported_broken_.assign(n_elements, 0);
  compute_bounds();
}

void SpringGroup::compute_bounds() {
  k_trans = c_trans = k_rot = c_rot = 0;
  for (std::size_t d = 0; d < prop.dofs.size(); ++d) {
    const SpringDofLaw& law = prop.dofs[d];
    const double k = law.stiffness_bound(), c = std::abs(law.C);
    if (d < 3) { k_trans = std::max(k_trans, k); c_trans = std::max(c_trans, c); }
    else       { k_rot = std::max(k_rot, k);     c_rot = std::max(c_rot, c); }
  }
}

double SpringGroup::element_energy(std::size_t e) const {
  double w = 0;
  for (std::size_t d = 0; d < n_dofs; ++d) w += state[e * n_dofs + d].energy;
  return prop.per_length ? w * length0[e] : w;
}

void SpringGroup::sum_energy() {
  ChunkedSum sum;
  sum.reset(n_chunks(n_elements));
  for (std::size_t c = 0; c < n_chunks(n_elements); ++c) {
    const std::size_t end = std::min(n_elements, (c + 1) * kChunk);
    double s = 0;
    for (std::size_t e = c * kChunk; e < end; ++e) s += element_energy(e);
    sum.slot(c) = s;
  }
  energy.internal = sum.total();
}

void SpringGroup::element_stiffness(std::size_t e, const NodalState& nodes, double extra_rot_k,
                                    double& dt_min, Index& dt_element) {
  const double s = law_scale[e];  // per-length laws: k [force] per strain -> k/l0
  for (std::size_t k = 0; k < 2; ++k) {
    const std::size_t slot = e * nodes_per_element + k;
    const auto n = static_cast<std::size_t>(connectivity[slot]);
    const double m = nodes.mass[n];
    const double kt = alive[e] ? damped_nodal_stiffness(k_trans * s, c_trans * s, m) : 0.0;
    slot_stiffness[slot] = kt;
    if (kt > 0 && m > 0) {
      const double dt = std::sqrt(2.0 * m / kt);
      if (dt < dt_min) { dt_min = dt; dt_element = static_cast<Index>(e); }
    }
    if (!slot_rot_stiffness.empty()) {
      const double j = nodes.inertia[n];
      const double kr = alive[e] ? damped_nodal_stiffness(k_rot * s + extra_rot_k, c_rot * s, j) : 0.0;
      slot_rot_stiffness[slot] = kr;
      if (kr > 0 && j > 0) {
        const double dt = std::sqrt(2.0 * j / kr);
        if (dt < dt_min) { dt_min = dt; dt_element = static_cast<Index>(e); }
      }
    }
  }
}

void SpringGroup::finish_step(const std::vector<double>& chunk_dt,
                              const std::vector<Index>& chunk_el,
                              const std::vector<std::uint8_t>& chunk_broke,
                              GroupStepResult& result) {
  for (std::size_t c = 0; c < chunk_dt.size(); ++c) {
    if (chunk_dt[c] < result.dt_min) { result.dt_min = chunk_dt[c]; result.dt_element = chunk_el[c]; }
    if (!chunk_broke[c]) continue;
    const std::size_t end = std::min(n_elements, (c + 1) * kChunk);
    for (std::size_t e = c * kChunk; e < end; ++e) {
      if (alive[e] || reported_broken_[e]) continue;
      reported_broken_[e] = 1;
      newly_eroded.push_back(static_cast<Index>(e));
      ++n_eroded;
      energy.eroded += element_energy(e);
    }
  }
  sum_energy();
}

std::size_t SpringGroup::index_of(std::int64_t id) const {
  const auto it = std::find(element_id.begin(), element_id.end(), id);
  return it == element_id.end() ? n_elements : static_cast<std::size_t>(it - element_id.begin());
}

bool SpringGroup::owns_th_object(ThKind kind, std::int64_t id) const {
  return kind == ThKind::Spring && index_of(id) < n_elements;
}

std::vector<std::string> SpringGroup::th_default_variables(ThKind kind) const {
  if (kind != ThKind::Spring) return {};
  return {"OFF", "FX", "FY", "FZ", "MX", "MY", "MZ", "LX", "LY", "LZ", "RX", "RY", "RZ", "IE"};
}

std::optional<ThProbe> SpringGroup::th_probe(ThKind kind, std::int64_t id,
                                             std::string_view variable) const {
  if (kind != ThKind::Spring) return std::nullopt;
  const std::size_t e = index_of(id);
  if (e >= n_elements) return std::nullopt;
  using hbm::deck::Dimension;
  ThProbe p;
  p.object = "spring";
  p.id = id;
  p.title = part_title;
  p.variable = std::string(variable);
  static constexpr std::string_view kForce[6] = {"FX", "FY", "FZ", "MX", "MY", "MZ"};
  static constexpr std::string_view kDef[6] = {"LX", "LY", "LZ", "RX", "RY", "RZ"};
  for (int i = 0; i < 6; ++i) {
    if (variable == kForce[i]) {
      p.unit = i < 3 ? Dimension::Force : Dimension::Moment;
      p.read = [this, e, i] { return out_force[e][static_cast<std::size_t>(i)]; };
      return p;
    }
    if (variable == kDef[i]) {
      p.unit = i < 3 ? Dimension::Length : Dimension::Angle;
      p.read = [this, e, i] { return out_def[e][static_cast<std::size_t>(i)]; };
      return p;
    }
  }
  if (variable == "IE") {
    p.unit = Dimension::Energy;
    p.read = [this, e] { return element_energy(e); };
    return p;
  }
  if (variable == "OFF") {
    p.unit = Dimension::None;
    p.read = [this, e] { return alive[e] ? 1.0 : 0.0; };
    return p;
  }
  return std::nullopt;
}

SpringGroup::ChunkScratch& SpringGroup::chunk_scratch(std::size_t nc) {
  scratch_.dt.assign(nc, std::numeric_limits<double>::infinity());
  scratch_.el.assign(nc, kNoIndex);
  scratch_.broke.assign(nc, 0);
  return scratch_;
}

}  // namespace hbm::solver::springs
