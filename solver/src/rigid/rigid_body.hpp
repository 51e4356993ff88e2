// SPDX-License-Identifier: GPL-3.0-or-later
// /RBODY: a rigid body made of a main node (moved to the centre of mass) and the nodes of
// a secondary node group, as a Constraint of the explicit cycle (constraint.hpp):
//   1. gather_forces: the forces, moments and nodal stiffness of the secondaries are
//      moved to the main node (moment of each force about the main node included) and
//      zeroed on the secondaries; the resultant is kept for /TH/RBODY.
//   2. impose_velocities: translation is the core's velocity update of the main node
//      (its mass is the body mass). Rotation: the spatial angular momentum is kicked,
//      L^{n+1/2} = L^{n-1/2} + dt^n M^n, and the orientation Q (principal frame ->
//      global) advanced over dt^{n+1/2} by the symplectic free-rigid-body splitting of
//      Dullweber, Leimkuhler & McLachlan (1997), see rigid_rotation.hpp; the main node
//      omega is set to the rotation vector of Q^{n+1} Q^{n,T} / dt^{n+1/2}.
//      The main node's scalar `inertia` is set to the Rayleigh quotient
//      omega . J omega / |omega|^2, so that the core's nodal rotational energy
//      0.5 inertia |omega|^2 is the body's 0.5 omega . J omega; rotational mass scaling
//      of the body is done here on the smallest principal moment.
//   3. impose_dependent: each secondary gets v_s = (x_m^{n+1} + Q^{n+1} r_s - x_s^n) / dt,
//      so that the core's position update puts it exactly on the rigid configuration
//      (v_s = v_m + omega x r to first order, without the O(dt^2) radial growth of that
//      formula); omega_s = omega_m. If a later constraint (/BCS) changed the main node
//      omega in stage 2, the rotation follows that omega (exponential map) instead.
// Kick-drift with an exact free flow is a symplectic, momentum-conserving integrator:
// a free tumbling body keeps L to round-off and its energy without drift.
// /TH/RBODY variables, all at the output time t^n: FX FY FZ MX MY MZ (resultant force and
// moment about the centre, global axes; the Radioss default set), and VX VY VZ, WX WY WZ
// (velocity of the centre, angular velocity), AMX AMY AMZ (angular momentum about the
// centre), KE (kinetic energy, translation + rotation); velocities and momenta at t^n
// are the means of the half-step values (as the engine's node velocities and kinetic
// energy), so that sum x^n x m v^n + AM is the exact invariant of the scheme.
// Rigid walls acting on secondaries: WallContactBody (wall_contact_body.hpp), solved in
// rigid_wall_contact.cpp.
#pragma once

#include "hbm/solver/constraint.hpp"
#include "rigid/rigid_mass_properties.hpp"
#include "rigid/wall_contact_body.hpp"

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace hbm::solver::rigid {

class RigidBody final : public Constraint, public WallContactBody {
 public:
  std::int64_t id = 0;
  std::string title;
  Index main = kNoIndex;
  std::vector<Index> secondary;
  std::vector<Eigen::Vector3d> r_body;  // secondary offsets in the principal frame [length]
  double mass = 0;                      // physical body mass [mass]
  Eigen::Vector3d principal = Eigen::Vector3d::Ones();  // principal moments [mass*length^2]
  Eigen::Matrix3d Q = Eigen::Matrix3d::Identity();      // principal frame -> global, at t^n
  Eigen::Vector3d L = Eigen::Vector3d::Zero();          // spatial angular momentum (half step)
  // /DT/NODA/CST rotational scaling: inertia needed per unit rotational stiffness,
  // 0.5 (Tmin / Tsca)^2 (0 without /DT/NODA/CST). Added isotropically to the tensor.
  double rot_scaling_coef = 0;
  double added_inertia = 0;  // cumulative, never decreases [mass*length^2]

  // Build the body from the current nodal masses / positions (main node moved to the
  // centre, its mass0 and inertia0 set, secondaries flagged). Throws
  // std::invalid_argument with the reason if the body is degenerate.
  void assemble(NodalState& nodes, double added_mass, const Eigen::Matrix3d& given_inertia,
                bool include_main_in_centre, bool spherical);

  // Initial motion from the nodal velocities (/INIVEL) of the secondaries and the main
  // node: centre velocity, angular momentum, the main node's v, omega and scalar inertia
  // (Rayleigh quotient, so that the engine's E_kin(t = 0) includes the spin). Called by
  // finish_rigid_bodies after the loads; otherwise on the first gather_forces.
  void start_motion(NodalState& nodes);

  std::string_view kind() const override { return "/RBODY"; }
  std::int64_t user_id() const override { return id; }
  void gather_forces(const StepContext& step, NodalState& nodes) override;
  void impose_velocities(const StepContext& step, NodalState& nodes) override;
  void impose_dependent(const StepContext& step, NodalState& nodes) override;

  // WallContactBody (rigid_wall_contact.cpp).
  const std::vector<Index>& secondary_nodes() const override { return secondary; }
  Eigen::Vector3d predicted_position(const NodalState& nodes, std::size_t j, double dt) const override;
  WallContactWork resolve_wall_contacts(const StepContext& step, NodalState& nodes,
                               std::span<WallContactPoint> points) override;

  std::optional<ThProbe> th_probe(ThKind kind, std::int64_t id,
                                  std::string_view variable) const override;
  std::vector<std::string> th_default_variables(ThKind kind) const override;
  bool owns_th_object(ThKind kind, std::int64_t id) const override;

  // Current diagnostics (also what the probes read).
  Eigen::Vector3d force() const { return force_; }
  Eigen::Vector3d moment() const { return moment_; }
  Eigen::Vector3d velocity() const { return velocity_; }  // v^{n+1/2} of the centre
  Eigen::Vector3d omega() const { return omega_; }        // omega^{n+1/2}
  double kinetic_energy() const;                          // at the half step n+1/2
  // Values at t^n (means of the half steps n-1/2, n+1/2), what /TH/RBODY writes.
  Eigen::Vector3d velocity_at_n() const { return 0.5 * (velocity_prev_ + velocity_); }
  Eigen::Vector3d omega_at_n() const { return 0.5 * (omega_prev_ + omega_); }
  Eigen::Vector3d momentum_at_n() const { return 0.5 * (L_prev_ + L); }
  double kinetic_energy_at_n() const { return 0.5 * (kinetic_prev_ + kinetic_energy()); }
  Eigen::Vector3d inverse_inertia() const { return (principal.array() + added_inertia).inverse().matrix(); }

 private:
  // Q_next from Q and L over dt (exact free flow); the main node's omega and scalar inertia.
  void predict_rotation(NodalState& nodes, double dt);
  bool initialised_ = false;
  Eigen::Matrix3d Q_next_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d omega_written_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_ = Eigen::Vector3d::Zero(), moment_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_ = Eigen::Vector3d::Zero(), omega_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_prev_ = Eigen::Vector3d::Zero(), omega_prev_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d L_prev_ = Eigen::Vector3d::Zero();
  double kinetic_prev_ = 0;
  double mass_used_ = 0;
  Eigen::Vector3d inv_inertia_used_ = Eigen::Vector3d::Ones();
  std::int64_t steps_since_orthonormalize_ = 0;
  // Wall contact scratch (sized on first contact).
  std::vector<std::uint8_t> contact_active_;
  std::vector<Eigen::Vector3d> contact_arm_, contact_x_;
};

}  // namespace hbm::solver::rigid
