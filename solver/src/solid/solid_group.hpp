// SPDX-License-Identifier: GPL-3.0-or-later
// Solid element group: 8-node bricks (one-point Flanagan-Belytschko, degenerate prism /
// tetra shapes allowed) or 4-node tetrahedra (constant strain, or with Itetra4 3 the
// average nodal pressure: nodal_pressure_average.hpp), of one part.
// Struct of arrays; the kernel in solid_group.cpp runs per chunk of kChunk elements, the
// brick kernel as loops over the chunk's elements (lanes) that the compiler vectorises.
//
// Hourglass control (bricks), chosen by /PROP/TYPE14 Isolid:
//  - Viscous (Isolid 0/1, the default for every material, as in OpenRadioss): f = -c q gamma,
//    c = h rho c_wave V^(2/3) / 4, q_alpha = sum_I v_I gamma_alpha,I (FB 1981).
//  - Stiffness (Isolid 2): Q += k q dt, k = h (lambda + 2G) V (B:B) / 8, f = -Q gamma.
//  - Physical (Isolid 24): hourglass strains of the linear and
//    bilinear velocity modes in a corotational element frame, deviatoric energy
//    2 G0 dev(eps_hg) only (no volumetric locking: Belytschko & Bindeman 1993 ADS),
//    parasitic shear of the bending modes dropped (no shear locking), closed form for a
//    box with half-lengths a_j (docs/engine-design.md §12). Q accumulated in the
//    corotational frame, so it is objective.
// Bulk viscosity (compression only): q = rho l (qa^2 l dv^2 - qb c dv), dv = tr D < 0.
#pragma once

#include "hbm/solver/element_group.hpp"
#include "solid/nodal_pressure_average.hpp"
#include "solid/small_strain_switch.hpp"
#include "solid/solid_material.hpp"

#include <array>
#include <vector>

namespace hbm::solver {

enum class HourglassForm : std::uint8_t { Viscous, Stiffness, Physical };

class SolidGroup final : public ElementGroup {
 public:
  SolidMaterial material;
  HourglassForm hourglass = HourglassForm::Viscous;
  double hourglass_coef = 0.1;   // h of /PROP/TYPE14
  double qa = 1.1, qb = 0.05;    // bulk viscosity
  int icpre = 0;                 // /PROP/TYPE14 Icpre (Physical form: 1 = deviatoric only)

  // Physical form: energy factors of the hourglass normal strains (see physical_hourglass)
  // and the viscous part, a fraction of the viscous form's coefficient h rho c V^(2/3)/4
  // (OpenRadioss HEPH adds 1/150 of it: engine-design.md §12).
  struct HourglassCoefficients {
    double c1 = 4.0 / 3.0, c2 = -2.0 / 3.0, c3 = 4.0 / 3.0;
    double viscous = 1.0 / 150.0;
  };
  HourglassCoefficients physical_coefficients() const;

  // Per-element state (struct of arrays).
  std::vector<double> volume0;             // [length^3]
  std::vector<double> mass;                // rho0 V0 [mass]
  std::array<std::vector<double>, 6> sig;  // stress (LAW34: long-term part) [stress]
  std::array<std::vector<double>, 6> hist; // LAW34 hereditary deviator [stress]
  std::vector<double> eps_p;               // plastic strain (LAW2/36)
  std::vector<double> eps_rate;            // filtered equivalent strain rate (rate_filter > 0) [1/time]
  std::vector<double> e_int;               // internal energy of the element [energy]
  std::vector<double> e_hg;                // hourglass energy of the element [energy]
  std::array<std::vector<double>, 12> hg;  // hourglass generalized forces Q (3 x 4) [force]
  std::array<std::vector<double>, 12> hg_visc;  // Physical: viscous part of Q (global) [force]
  std::vector<double> q_bulk;              // bulk viscosity pressure of the last cycle [stress]
  // /DT/BRICK/CST (8-node bricks; set before initialize, which sizes the frozen geometry).
  SmallStrainSwitch small_strain;
  // /TETRA4 with Itetra4 3: pressure from the averaged nodal volumes (set nodal_pressure.enabled
  // before initialize).
  NodalPressureAverage nodal_pressure;
  FrozenGeometry frozen_geometry;
  std::size_t n_small_strain() const override { return frozen_geometry.count(); }

  // Size all arrays after n_elements / nodes_per_element / connectivity are set, and
  // compute V0 and mass from the current nodal positions. Returns the local index of
  // the first element with non-positive volume, or kNoIndex.
  Index initialize(const NodalState& nodes);

  std::string_view formulation() const override;
  // One-point brick 1, 4-node tetra 0.35 (bench-model of 3459ac4: 146 and 50 ns).
  double relative_element_cost() const override { return nodes_per_element == 8 ? 1.0 : 0.35; }
  void compute_forces(const StepContext& step, const NodalState& nodes,
                      GroupStepResult& result) override;
  bool has_force_stages() const override { return true; }
  void begin_forces(const StepContext& step, const NodalState& nodes) override;
  void force_chunk(std::size_t ch, const StepContext& step, const NodalState& nodes) override;
  void end_forces(GroupStepResult& result) override;
  void cell_field(CellField field, std::span<double> out) const override;

  // Total stress of element e (LAW34: long-term part + hereditary part).
  void stress(std::size_t e, double s[6]) const;

 private:
  // What one chunk of the last compute_forces adds up (begin_forces sizes it).
  struct ChunkSums {
    double e_int = 0.0, e_hg = 0.0, dt = std::numeric_limits<double>::infinity();
    Index dt_elem = kNoIndex, inverted = kNoIndex;
  };
  std::vector<ChunkSums> chunk_sums_;

  // 8-node bricks: one chunk in batches of elements (lanes), each stage a vectorised loop
  // over the lanes of a batch.
  void compute_brick_chunk(std::size_t chunk, const StepContext& step, const NodalState& nodes,
                           double& e_int_inc, double& e_hg_inc, double& dt_min, Index& dt_elem,
                           Index& inverted);
  // Lanes e0 .. e0+n-1; LaneCount is std::size_t (partly filled batch) or a
  // std::integral_constant (full batch: fixed trip counts, no remainder loops).
  template <class LaneCount>
  void compute_brick_lanes(std::size_t e0, LaneCount lane_count, const StepContext& step,
                           const NodalState& nodes, double& e_int_inc, double& e_hg_inc,
                           double& dt_min, Index& dt_elem, Index& inverted);
  // 4-node tetrahedra: one chunk, in batches of lanes (LAW1, LAW34) or element by element.
  void compute_tetra_chunk(std::size_t chunk, const StepContext& step, const NodalState& nodes,
                           double& e_int_inc, double& dt_min, Index& dt_elem, Index& inverted);
  template <class LaneCount>
  void compute_tetra_lanes(std::size_t e0, LaneCount lane_count, const StepContext& step,
                           const NodalState& nodes, double& e_int_inc, double& dt_min, Index& dt_elem,
                           Index& inverted);
  void compute_tetra_scalar(std::size_t e_begin, std::size_t e_end, const StepContext& step,
                            const NodalState& nodes, double& e_int_inc, double& dt_min, Index& dt_elem,
                            Index& inverted);
};

}  // namespace hbm::solver
