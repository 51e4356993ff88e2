// SPDX-License-Identifier: GPL-3.0-or-later
// Element group: the elements of one formulation and one part (hence one material and
// one property), stored as struct of arrays. A group computes, in parallel over fixed
// chunks, the force each element exerts on each of its nodes into group-local "slot"
// buffers (slot s = e * nodes_per_element + k). The core then assembles all slots into
// the nodal arrays through a node->slot incidence built once in the build phase, summing
// each node's slots in (group order, element order): deterministic for any thread count.
// Groups never write nodal arrays.
#pragma once

#include "hbm/solver/nodal_state.hpp"
#include "hbm/solver/step_context.hpp"
#include "hbm/solver/th_probe.hpp"
#include "hbm/solver/types.hpp"

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace hbm::solver {

// VTK cell types written as themselves (VTK file format numbering).
enum class VtkCellType : std::uint8_t {
  Line = 3, Triangle = 5, Quad = 9, Tetra = 10, Hexahedron = 12, Wedge = 13, Pyramid = 14
};

// Per-cell animation fields a group fills (part id and element id come from the base).
enum class CellField : std::uint8_t {
  VonMises,       // von Mises stress [stress]
  PlasticStrain,  // equivalent plastic strain [-]
  Eroded,         // 1 if deleted, else 0
  SpecificEnergy,   // internal energy / element mass [energy/mass] (/ANIM/ELEM/ENER)
  HourglassEnergy,  // hourglass energy of the element [energy] (/ANIM/ELEM/HOURG)
};

// Cumulative energies of a group since t = 0, through the current t^n [energy].
struct GroupEnergy {
  double internal = 0.0;   // stress work incl. elements already deleted
  double hourglass = 0.0;  // work of the hourglass forces
  double eroded = 0.0;     // internal energy held by deleted elements when deleted
                           //   (part of `internal`, reported separately)
};

// What one compute_forces call reports besides the slot buffers.
struct GroupStepResult {
  // Smallest critical element step L/c (no safety factor) and its element; the core
  // applies the 0.9 factor when no /DT/NODA/CST is given [time].
  double dt_min = std::numeric_limits<double>::infinity();
  Index dt_element = kNoIndex;
  // Lowest local index of an element with non-positive volume (Jacobian) this cycle;
  // the core stops the run naming it. kNoIndex if none.
  Index inverted_element = kNoIndex;
};

class ElementGroup : public ThSource {
 public:
  ~ElementGroup() override = default;

  // --- identity and topology (filled by the group's builder) -------------------------
  std::string keyword;            // deck keyword, e.g. "/BRICK", "/TETRA4", "/SHELL"
  Index part = kNoIndex;          // index into Model::parts
  std::size_t n_elements = 0;
  std::size_t nodes_per_element = 0;
  std::vector<Index> connectivity;        // node index per slot (n_elements * npe)
  std::vector<std::int64_t> element_id;   // user id per element
  std::vector<std::uint8_t> alive;        // 0 once deleted (eroded)

  // --- per-cycle outputs (overwritten by compute_forces) -----------------------------
  // Force exerted by the element on its node, i.e. -f_int (+ hourglass, viscosity),
  // per slot [force]. Deleted elements write 0.
  Vec3Soa slot_force;
  // Same for moments; left empty by groups without rotational DOFs [force*length].
  Vec3Soa slot_moment;
  // Nodal stiffness contribution per slot for the nodal time step, defined so that a
  // node shared only by elements like this one gets sqrt(2 m_n / k_n) = element step:
  //   k_slot = 2 * m_slot / dt_e^2, m_slot = physical lumped element mass at the node,
  //   dt_e = critical element step (L/c, no factor) [force/length].
  std::vector<double> slot_stiffness;
  // Rotational counterpart (empty without rotational DOFs) [force*length/rad].
  std::vector<double> slot_rot_stiffness;

  // --- cumulative bookkeeping ---------------------------------------------------------
  GroupEnergy energy;
  std::int64_t n_eroded = 0;               // elements deleted so far
  std::vector<Index> newly_eroded;         // deleted during the last compute_forces;
                                           //   the core logs and clears it

  // Allocate the slot buffers from n_elements and nodes_per_element (call at the end of
  // the builder); `rotational` also allocates the moment buffers.
  void allocate_slots(bool rotational = false);
  bool has_rotation_slots() const { return !slot_moment.x.empty(); }

  // --- elements inside a rigid body ---------------------------------------------------
  // Elements whose nodes all belong to one /RBODY are deactivated by the rigid-body
  // builder, as in OpenRadioss ("all the elements belonging to the rigid body are
  // deactivated"): alive = 0, zero slots (force, moment, stiffness), never computed
  // again, so they give no force, no energy, no time step and no mass scaling; their
  // mass stays on the nodes (lumped at build, hence in the body). The core skips a group
  // whose elements are all deactivated (compute_forces and assembly).
  std::size_t n_deactivated = 0;
  bool all_deactivated() const { return n_elements > 0 && n_deactivated == n_elements; }
  // Deactivates every element e with inside[e] != 0 (size n_elements; call once per group,
  // after the slots are allocated). Groups override it to drop the elements from their
  // kernels (they must call the base); the default leaves the kernel to mask alive = 0.
  virtual void deactivate(std::span<const std::uint8_t> inside);

  // --- sharing the work out between threads (speed only: results never depend on it) --
  // Thread that computes each force chunk when several threads run, set by the core's
  // ThreadPartition so that a thread's elements read and write mostly nodes that the same
  // thread updates (core/thread_partition.cpp); empty: chunks shared out statically.
  std::vector<std::uint8_t> chunk_thread;
  // Number of force chunks compute_forces runs and the elements of chunk ch, in its
  // order. Default: elements ch * kChunk ..; groups that compute a list of elements
  // (shells: the ones not deactivated) override both.
  virtual std::size_t n_force_chunks() const { return n_chunks(n_elements); }
  virtual void force_chunk_elements(std::size_t ch, std::vector<Index>& out) const;
  // Time one element of the group takes per cycle relative to a one-point brick (the
  // whole-model bench, docs/engine-design.md section 14); weighs the work out between
  // threads, nothing else.
  virtual double relative_element_cost() const { return 1.0; }

  // --- behaviour -------------------------------------------------------------------------
  // Formulation name for listings and the bench, e.g. "brick8 FB 1-point".
  virtual std::string_view formulation() const = 0;

  // Compute element forces at t^n from x^n and v^{n-1/2} (dt_prev); update stresses and
  // energies; fill the slot buffers and `result`. Parallel over chunks of kChunk
  // elements; every reduction via per-chunk partials summed in chunk order.
  virtual void compute_forces(const StepContext& step, const NodalState& nodes,
                              GroupStepResult& result) = 0;

  // compute_forces in three stages, so that the core can run the chunks of every large
  // group in one parallel region, each chunk on the thread that owns it: begin_forces
  // (one thread, before any chunk), force_chunk for each ch < n_force_chunks() (any
  // thread, chunks independent of each other), end_forces (one thread, after all
  // chunks: reductions in chunk order, deletions). compute_forces gives the same bits.
  // Groups without the stages return false and are run whole.
  virtual bool has_force_stages() const { return false; }
  virtual void begin_forces(const StepContext& /*step*/, const NodalState& /*nodes*/) {}
  virtual void force_chunk(std::size_t /*ch*/, const StepContext& /*step*/, const NodalState& /*nodes*/) {}
  virtual void end_forces(GroupStepResult& /*result*/) {}

  // VTK cell of element e: writes its distinct node indices to `nodes` (capacity
  // nodes_per_element) and returns the cell type and count (degenerate bricks as wedge
  // or tetra). Default: all nodes, type from nodes_per_element (2 line, 3 triangle,
  // 4 quad for shells / tetra for solids is decided by `solid_cells()`, 8 hexahedron).
  virtual VtkCellType vtk_cell(std::size_t e, Index* nodes, int& n_nodes) const;
  virtual bool solid_cells() const { return true; }

  // Fill one value per element for an animation field; default 0 (Eroded from `alive`).
  virtual void cell_field(CellField field, std::span<double> out) const;

  // Elements switched to the small strain formulation so far (/DT/BRICK/CST,
  // /DT/SHELL/CST); the listing names the parts that have any. Default: none.
  virtual std::size_t n_small_strain() const { return 0; }
};

}  // namespace hbm::solver
