// SPDX-License-Identifier: GPL-3.0-or-later
// ShellElementGroup: chunked, deterministic driver of the shell kernels inside the
// engine (see shell_element_group.hpp).
#include "shells/shell_element_group.hpp"

#include "core/parallel_loop.hpp"

#include <algorithm>
#include <cmath>

namespace hbm::solver::shells {

Index ShellElementGroup::initialize(const NodalState& nodes) {
  const std::size_t npe = nodes_per_element;
  data.n = n_elements;
  data.kind = npe == 4 ? ShellKind::QuadBT : ShellKind::TriaDKT;
  data.conn.assign(connectivity.begin(), connectivity.end());
  data.user_id = element_id;
  data.part.assign(n_elements, part);
  data.allocate();
  allocate_slots(true);
  slot_mass.assign(n_elements, 0.0);
  slot_inertia.assign(n_elements, 0.0);
  computed_.resize(n_elements);
  for (std::size_t e = 0; e < n_elements; ++e) computed_[e] = static_cast<std::int32_t>(e);
  chunk_totals_.assign(n_chunks(n_elements), {});
  Index bad = kNoIndex;
  for (std::size_t e = 0; e < n_elements; ++e) {
    const Index* c = &connectivity[e * npe];
    auto p = [&](std::size_t k) {
      const auto i = static_cast<std::size_t>(c[k]);
      return std::array<double, 3>{nodes.x.x[i], nodes.x.y[i], nodes.x.z[i]};
    };
    std::array<double, 3> a, b;
    const auto p0 = p(0), p1 = p(1), p2 = p(2);
    if (npe == 4) {
      const auto p3 = p(3);
      for (int k = 0; k < 3; ++k) { a[k] = p2[k] - p0[k]; b[k] = p3[k] - p1[k]; }
    } else {
      for (int k = 0; k < 3; ++k) { a[k] = p1[k] - p0[k]; b[k] = p2[k] - p0[k]; }
    }
    const double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2],
                 cz = a[0] * b[1] - a[1] * b[0];
    const double A = 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
    if (!(A > 0) && bad == kNoIndex) bad = static_cast<Index>(e);
    const double t = data.thick[e];
    data.area[e] = A;
    slot_mass[e] = data.mat.rho * t * A / static_cast<double>(npe);
    slot_inertia[e] = slot_mass[e] * (t * t + A) / 12.0;
  }
  return bad;
}

std::string_view ShellElementGroup::formulation() const {
  return data.kind == ShellKind::QuadBT ? "shell4 Belytschko-Tsay (BWC warping, hourglass)"
                                        : "shell3 CST membrane + DKT bending";
}

void ShellElementGroup::force_chunk_elements(std::size_t ch, std::vector<Index>& out) const {
  out.assign(computed_.begin() + static_cast<std::ptrdiff_t>(std::min(computed_.size(), ch * kChunk)),
             computed_.begin() + static_cast<std::ptrdiff_t>(std::min(computed_.size(), (ch + 1) * kChunk)));
}

// One chunk of the computed list: forces into the slots, the chunk's totals into
// chunk_totals_[ch] (any thread; chunks touch disjoint elements and slots).
void ShellElementGroup::force_chunk(std::size_t ch, const StepContext& step, const NodalState& nodes) {
  const ShellNodalView nv{nodes.x.x.data(),     nodes.x.y.data(),     nodes.x.z.data(),
                          nodes.v.x.data(),     nodes.v.y.data(),     nodes.v.z.data(),
                          nodes.omega.x.data(), nodes.omega.y.data(), nodes.omega.z.data()};
  const ShellSlotOut out{slot_force.x.data(),  slot_force.y.data(),  slot_force.z.data(),
                         slot_moment.x.data(), slot_moment.y.data(), slot_moment.z.data()};
  const double dt = step.dt_prev;
  const std::size_t npe = nodes_per_element;
  const std::size_t k0 = ch * kChunk, k1 = std::min(computed_.size(), k0 + kChunk);
  const std::span<const std::int32_t> list(computed_.data() + k0, k1 - k0);
  chunk_totals_[ch] = data.kind == ShellKind::QuadBT ? quad_bt_forces(data, nv, out, dt, list)
                                                     : tria_dkt_forces(data, nv, out, dt, list);
  for (const std::int32_t el : list) {
    const auto e = static_cast<std::size_t>(el);
    const double dte = data.dt_elem[e];
    const bool live = !data.deleted[e] && dte < 1e299;
    const double k = live ? 2.0 * slot_mass[e] / (dte * dte) : 0.0;
    const double kr = live ? 2.0 * slot_inertia[e] / (dte * dte) : 0.0;
    for (std::size_t s = e * npe; s < (e + 1) * npe; ++s) {
      slot_stiffness[s] = k;
      slot_rot_stiffness[s] = kr;
    }
  }
}

// The chunks' totals in chunk order (independent of the thread that ran a chunk).
void ShellElementGroup::end_forces(GroupStepResult& result) {
  const std::size_t n_computed = computed_.size();
  for (std::size_t ch = 0; ch < chunk_totals_.size(); ++ch) {
    const ShellKernelTotals& t = chunk_totals_[ch];
    energy.internal += t.de_int;
    energy.hourglass += t.de_hg;
    if (t.dt_min < result.dt_min) {
      result.dt_min = t.dt_min;
      result.dt_element = static_cast<Index>(t.dt_element);
    }
    if (result.inverted_element == kNoIndex && t.inverted >= 0)
      result.inverted_element = static_cast<Index>(t.inverted);
    if (t.newly_deleted) {
      const std::size_t k0 = ch * kChunk, k1 = std::min(n_computed, k0 + kChunk);
      for (std::size_t k = k0; k < k1; ++k) {
        const auto e = static_cast<std::size_t>(computed_[k]);
        if (data.deleted[e] && alive[e]) {
          alive[e] = 0;
          ++n_eroded;
          newly_eroded.push_back(static_cast<Index>(e));
          energy.eroded += data.eint[e];
        }
      }
    }
  }
}

void ShellElementGroup::compute_forces(const StepContext& step, const NodalState& nodes,
                                       GroupStepResult& result) {
  parallel_loop(chunk_totals_.size(), true, [&](std::size_t ch) { force_chunk(ch, step, nodes); }, chunk_thread);
  end_forces(result);
}

void ShellElementGroup::deactivate(std::span<const std::uint8_t> inside) {
  ElementGroup::deactivate(inside);
  computed_.clear();
  for (std::size_t e = 0; e < n_elements; ++e)
    if (e >= inside.size() || !inside[e]) computed_.push_back(static_cast<std::int32_t>(e));
  chunk_totals_.assign(n_chunks(computed_.size()), {});
}

void ShellElementGroup::cell_field(CellField field, std::span<double> out) const {
  for (std::size_t e = 0; e < n_elements && e < out.size(); ++e) {
    switch (field) {
      case CellField::VonMises: out[e] = data.von_mises(e); break;
      case CellField::PlasticStrain: out[e] = data.max_epsp(e); break;
      case CellField::Eroded: out[e] = alive[e] ? 0.0 : 1.0; break;
      case CellField::SpecificEnergy: {
        const double m = slot_mass[e] * static_cast<double>(nodes_per_element);  // rho t A
        out[e] = m > 0.0 ? data.eint[e] / m : 0.0;
        break;
      }
      case CellField::HourglassEnergy: out[e] = data.ehg[e]; break;
    }
  }
}

}  // namespace hbm::solver::shells
