// SPDX-License-Identifier: GPL-3.0-or-later
// Engine adaptor of the shell kernels: an ElementGroup (docs/engine-design.md section 3)
// holding one ShellGroupData (the elements of one part, /SHELL -> Belytschko-Tsay quads,
// /SH3N -> CST+DKT triangles). compute_forces runs the kernel over fixed chunks of
// kChunk computed elements (OpenMP; elements inside a rigid body are not computed), reduces energies and time steps in chunk order, fills the
// nodal stiffness slots (k = 2 m_slot / dt_e^2, rotational 2 I_slot / dt_e^2) and
// reports deleted elements to the core.
#pragma once

#include "hbm/solver/element_group.hpp"
#include "shells/shell_group_data.hpp"

#include <vector>

namespace hbm::solver::shells {

class ShellElementGroup final : public ElementGroup {
 public:
  ShellGroupData data;
  std::vector<double> slot_mass;     // lumped mass per node of element e [mass]
  std::vector<double> slot_inertia;  // rotational inertia per node of element e [mass*length^2]

  // After keyword, part, connectivity, element_id and data (kind, mat, sec, thick) are
  // set: sizes everything, lumps rho t A / npe and m (t^2 + A) / 12 per node from the
  // current positions. Returns the first element with zero area, or kNoIndex.
  Index initialize(const NodalState& nodes);

  std::string_view formulation() const override;
  void compute_forces(const StepContext& step, const NodalState& nodes,
                      GroupStepResult& result) override;
  bool has_force_stages() const override { return true; }
  void force_chunk(std::size_t ch, const StepContext& step, const NodalState& nodes) override;
  void end_forces(GroupStepResult& result) override;
  bool solid_cells() const override { return false; }
  // The chunks run over the computed elements; quad 0.6, triangle 0.85 of a one-point
  // brick (bench-model of 3459ac4: 87 and 123 ns against 146).
  std::size_t n_force_chunks() const override { return n_chunks(computed_.size()); }
  void force_chunk_elements(std::size_t ch, std::vector<Index>& out) const override;
  double relative_element_cost() const override { return nodes_per_element == 4 ? 0.6 : 0.85; }
  void cell_field(CellField field, std::span<double> out) const override;
  std::size_t n_small_strain() const override { return data.n_frozen(); }
  // Drops the elements inside a rigid body from the computed list.
  void deactivate(std::span<const std::uint8_t> inside) override;

 private:
  // Elements computed each cycle (all but the deactivated ones), in element order; the
  // chunks of kChunk run over this list.
  std::vector<std::int32_t> computed_;
  std::vector<ShellKernelTotals> chunk_totals_;
};

}  // namespace hbm::solver::shells
