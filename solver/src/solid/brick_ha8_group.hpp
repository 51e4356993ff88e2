// SPDX-License-Identifier: GPL-3.0-or-later
// Fully integrated 8-node brick without hourglass modes and without volumetric locking,
// /PROP/TYPE14 Isolid 14 (OpenRadioss HA8, Inpts 222, constant pressure Icpre 1):
//  - deviatoric stress at 2 x 2 x 2 Gauss points, each with its own stress and material
//    history (LAW34 hereditary deviator), Jaumann rate with the point's own spin;
//  - volumetric strain rate and pressure constant over the element: the mean dilatation
//    tr D_bar = sum_I v_I . b_I / V with the exact volume gradient b_I (Nagtegaal, Parks &
//    Rice 1974; B-bar, Hughes 1980; b_I as in Flanagan & Belytschko 1981). The point rate
//    of deformation is D_g = dev(D_g) + tr(D_bar)/3 I, so K/G -> infinity does not lock.
//  - internal force f_I = -sum_g dV_g dev(sigma_g) B_Ig - (sigma_m_bar - q) b_I with
//    sigma_m_bar the volume mean of the point mean stresses and q the bulk viscosity on
//    tr D_bar. 2-point Gauss integrates the trilinear brick's volume and volume gradient
//    exactly, so sum_g dV_g B_Ig = b_I: linear fields are reproduced on distorted meshes.
//  - no hourglass forces (hourglass energy identically 0); internal energy by the
//    trapezoidal stress power on the mid-step configuration like the one-point kernel;
//    element time step and nodal stiffness from the one-point brick's Rayleigh estimate.
// Per-point state is struct of arrays: value (component k, point g, element e) at
// [(k * 8 + g) * n_elements + e].
#pragma once

#include "hbm/solver/element_group.hpp"
#include "solid/small_strain_switch.hpp"
#include "solid/solid_material.hpp"

#include <vector>

namespace hbm::solver {

class BrickHa8Group final : public ElementGroup {
 public:
  static constexpr int kPoints = 8;

  SolidMaterial material;
  double qa = 1.1, qb = 0.05;  // bulk viscosity (on the mean dilatation)
  // Icpre 1 (default here): constant pressure, mean dilatation. Icpre 0: volumetric rate
  // and pressure at the Gauss points as well (plain full integration: locks as nu -> 1/2).
  bool constant_pressure = true;

  std::vector<double> volume0;  // [length^3]
  std::vector<double> mass;     // rho0 V0 [mass]
  std::vector<double> sig;      // 6 x 8 per element: stress (LAW34: long-term part) [stress]
  std::vector<double> hist;     // 6 x 8 per element: LAW34 hereditary deviator [stress]
  std::vector<double> eps_p;    // 8 per element: plastic strain (LAW2/36)
  std::vector<double> eps_rate; // 8 per element: filtered strain rate (rate_filter > 0) [1/time]
  std::vector<double> e_int;    // internal energy of the element [energy]
  std::vector<double> q_bulk;   // bulk viscosity pressure of the last cycle [stress]
  // /DT/BRICK/CST (set before initialize, which sizes the frozen geometry).
  SmallStrainSwitch small_strain;
  FrozenGeometry frozen_geometry;
  std::size_t n_small_strain() const override { return frozen_geometry.count(); }

  // Size the arrays (after n_elements / connectivity) and compute V0 and mass. Returns
  // the first element with a non-positive Jacobian at a Gauss point, or kNoIndex.
  Index initialize(const NodalState& nodes);

  std::string_view formulation() const override { return "brick8 HA8 2x2x2 Gauss, constant pressure"; }
  // About 7 one-point bricks (docs/engine-design.md section 12.1).
  double relative_element_cost() const override { return 7.0; }
  void compute_forces(const StepContext& step, const NodalState& nodes,
                      GroupStepResult& result) override;
  void cell_field(CellField field, std::span<double> out) const override;

  std::size_t at(int k, int g, std::size_t e) const {
    return (static_cast<std::size_t>(k) * kPoints + static_cast<std::size_t>(g)) * n_elements + e;
  }
  // Total stress at Gauss point g of element e (LAW34: long-term + hereditary part).
  void point_stress(std::size_t e, int g, double s[6]) const;
  // Mean of the 8 point stresses.
  void stress(std::size_t e, double s[6]) const;

 private:
  void compute_chunk(std::size_t chunk, const StepContext& step, const NodalState& nodes,
                     double& e_int_inc, double& dt_min, Index& dt_elem, Index& inverted);
};

}  // namespace hbm::solver
