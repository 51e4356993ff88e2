// SPDX-License-Identifier: GPL-3.0-or-later
// Spring element groups: the /SPRING elements of one part, whose property is
// /PROP/TYPE4 (axial, 1 DOF), /PROP/TYPE8 (general, 6 uncoupled DOFs in a skew or the
// global frame) or /PROP/TYPE13 (beam-type, 6 DOFs in a frame that follows its nodes).
// All elements of a group share one property, hence one set of DOF laws; each element
// keeps the history of each DOF (struct of arrays by DOF). The common part here: the
// property, the per-element history and outputs, the nodal stiffness for the time step,
// and the /TH/SPRING probes (OFF, FX FY FZ MX MY MZ local forces and moments, LX LY LZ
// elongations, RX RY RZ rotations, IE internal energy).
#pragma once

#include "hbm/solver/element_group.hpp"
#include "springs/spring_dof_law.hpp"

#include <Eigen/Dense>

#include <array>
#include <optional>
#include <cstdint>
#include <string>
#include <vector>

namespace hbm::solver::springs {

enum class SpringType : std::uint8_t { Axial = 4, General = 8, Beam = 13 };

// One spring property card, resolved (curves point into the model's /FUNCT storage).
struct SpringProperty {
  std::int64_t id = 0;
  std::string title;
  SpringType type = SpringType::Axial;
  double mass = 0;       // spring mass, split half to each node [mass]
  double inertia = 0;    // spring inertia, half to each node (TYPE8/13) [mass*length^2]
  bool per_length = false;  // Ileng = 1: inputs per unit length, laws in strain
  Eigen::Matrix3d skew = Eigen::Matrix3d::Identity();  // TYPE8 frame / TYPE13 reference (columns)
  bool has_skew = false;
  std::vector<SpringDofLaw> dofs;  // 1 (TYPE4) or 6: X Y Z RX RY RZ
};

// Effective nodal stiffness of a spring of stiffness k and damping c on a node of mass
// m, such that sqrt(2 m / k_eq) is the exact critical step of two equal masses joined by
// the damped spring: dt = 2 m_r / (sqrt(m_r k + c^2/4) + c/2), m_r = m/2 (damped
// oscillator, central difference stability limit). c = 0 gives k_eq = k.
double damped_nodal_stiffness(double k, double c, double m);

class SpringGroup : public ElementGroup {
 public:
  SpringProperty prop;
  std::string part_title;
  std::size_t n_dofs = 1;
  std::vector<SpringDofState> state;   // e * n_dofs + dof
  std::vector<double> length0;         // initial length |x2 - x1| [length]
  std::vector<double> law_scale;       // 1 / length0 when per_length, else 1
  std::vector<std::array<double, 6>> out_force;  // local FX FY FZ MX MY MZ
  std::vector<std::array<double, 6>> out_def;    // local LX LY LZ RX RY RZ

  // Allocate per-element state after connectivity and length0 are known.
  void init_state();

  // Internal energy of element e [energy].
  double element_energy(std::size_t e) const;

  std::optional<ThProbe> th_probe(ThKind kind, std::int64_t id,
                                  std::string_view variable) const override;
  std::vector<std::string> th_default_variables(ThKind kind) const override;
  bool owns_th_object(ThKind kind, std::int64_t id) const override;

 protected:
  // Sum the element energies in chunk order into energy.internal (deterministic).
  void sum_energy();
  // Translational / rotational stiffness bounds and damping of the property.
  double k_trans = 0, c_trans = 0, k_rot = 0, c_rot = 0;
  void compute_bounds();
  // Fill slot stiffness for element e from the current nodal masses/inertias and
  // update the group's critical step.
  void element_stiffness(std::size_t e, const NodalState& nodes, double extra_rot_k,
                         double& dt_min, Index& dt_element);
  std::size_t index_of(std::int64_t id) const;
  // After the chunk loop: reduce the per-chunk critical steps in chunk order, record the
  // elements that broke this cycle (newly_eroded, n_eroded, eroded energy) and sum the
  // internal energy.
  void finish_step(const std::vector<double>& chunk_dt, const std::vector<Index>& chunk_el,
                   const std::vector<std::uint8_t>& chunk_broke, GroupStepResult& result);
  std::vector<std::uint8_t> reported_broken_;
  // Per-chunk critical step, its element and the broke flag, reused every cycle (no
  // allocation in the step): chunk_scratch(nc) resets them for nc chunks.
  struct ChunkScratch {
    std::vector<double> dt;
    std::vector<Index> el;
    std::vector<std::uint8_t> broke;
  };
  ChunkScratch& chunk_scratch(std::size_t nc);
  ChunkScratch scratch_;
};

}  // namespace hbm::solver::springs
