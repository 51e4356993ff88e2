// SPDX-License-Identifier: GPL-3.0-or-later
// /INTER/TYPE7 penalty node-to-surface contact: secondary nodes against the segments of
// a main surface, self-contact when the nodes belong to that surface.
//
// Per cycle, for each secondary node s, the closest candidate segment with a positive
// penetration p = gap - d is found (d: distance to the closest point; signed along the
// outward normal for solid faces, which lets a node that went past the face still be
// pushed out, down to `depth`). Normal force (Radioss TYPE7 law, stiffness rising as the
// node approaches a shell mid-surface): K(p) = Kp g / (g - p), F = K p, until the tangent
// dF/dp reaches Kmax, then linear with slope Kmax;
// solid faces use the linear law F = Kp p. Kp = Stfac K0 (Istf=0) or Stfac (Istf=1)
// or K0 combined with the secondary side (Istf 2-5), bounded by Stmin/Stmax and by the
// fixed-step cap Kcap = 2 f m_s (Tsca/dt)^2 (m_s: the node's mass this cycle, added mass
// included) so that the contact alone never pulls the node's nodal step
// dt_n = Tsca sqrt(2 m / k) under the fixed step (f = cap fraction).
// Inacti 5/6: an initially penetrated node starts with its gap reduced to (95 % of) its
// distance, which then grows back as it moves away (no initial kick). The same holds for a
// node that enters a gap during the run deeper than kEntryJump of it in one cycle (past a
// segment's edge, not by approaching it), or whose closest segment changes to one whose
// pair potential exceeds the last cycle's by more than such an entry would make (a stiffer
// element's face at the same depth): "initial" is the first cycle of the penetration,
// as LS-DYNA's IGNORE = 1 reads it; OpenRadioss applies Inacti at t = 0 only.
// Damping (VIS_S, fraction of critical): F_d = -2 VIS_S sqrt(K m*) v_n, m* the reduced
// mass of node and segment; the total normal force is kept compressive. Coulomb friction
// (Fric), regularised as OpenRadioss's TYPE7 (i7for3.F) by Iform: 1 (its default) viscous,
// F_t = -min(VISF sqrt(2 K m_s) |v_t|, mu F_n) v_t / |v_t| with m_s the secondary node's mass
// and no history; 2 incremental, an elastic-plastic tangential spring F_t += -K v_t dt,
// |F_t| <= mu F_n. The force on s is F; the segment nodes get -N_i F (N_i: weights at the
// closest point), so linear momentum is exchanged exactly.
//
// Search: candidate (node, segment) pairs within gap + margin are collected with a
// bucket grid at a sort; the list stays valid while every node involved moved less than
// half the margin since that sort (relative motion < margin), tracked each cycle.
#pragma once

#include "bucket_grid.hpp"
#include "contact_surface.hpp"
#include "segment_projection.hpp"
#include "hbm/solver/nodal_state.hpp"
#include "vec3.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace hbm::solver::contact {

struct PenaltyContactParams {
  int istf = 0;            // 0: Kp = Stfac K0 (main side), 1: Kp = Stfac, 2..5: K0 of both
                           //   sides combined (2 mean, 3 max, 4 min, 5 in series)
  double stfac = 1.0;      // stiffness scale factor (Istf != 1) or stiffness (Istf = 1)
  double stmin = 0.0;      // lower bound on Kp (0: none) [force/length]
  double stmax = 0.0;      // upper bound on K (0: none) [force/length]
  double fric = 0.0;       // Coulomb coefficient
  int friction_form = 1;   // Iform: 1 viscous (OpenRadioss's default), 2 incremental spring
  double visf = 1.0;       // VISF: critical damping coefficient of the viscous friction
  int igap = 0;            // 0: constant gap = gapmin; 1: variable gap from thicknesses
  double gapmin = 0.0;     // [length]
  double gap_scale = 1.0;  // Fscalegap (Igap 1)
  double gapmax = 0.0;     // upper bound on the variable gap (0: none) [length]
  double tstart = 0.0, tstop = std::numeric_limits<double>::infinity();  // [time]
  double vis_s = 0.05;     // normal damping, fraction of critical
  double fixed_dt = 0.0;   // fixed engine step (/DT/NODA/CST Tmin), 0: no cap [time]
  double tsca = 0.9;       // /DT/NODA/CST Tsca
  double cap_fraction = 0.5;  // share of the nodal stiffness budget the contact may take
  double margin = 0.0;     // search margin (0: half the mean segment edge) [length]
  int inacti = 0;          // initial penetrations: 0 none; 5 gap of a penetrated node reduced
                           //   to its distance, 6 to 95 % of it (OpenRadioss), growing back
                           //   as the node moves away
};

// Global results of one interface this cycle (time histories, listing).
struct ContactResultant {
  V3 normal_force;        // sum of normal forces on the secondary nodes [force]
  V3 tangential_force;    // sum of friction forces on the secondary nodes [force]
  int n_active = 0;       // secondary nodes in contact
};

class PenaltyContact {
 public:
  // `secondary`: node indices; `node_gap`: per-node secondary gap gs (Igap 1: half the
  // thickest shell at the node, empty otherwise); `node_k0`: per-node secondary stiffness
  // (Istf 2..5, empty otherwise).
  PenaltyContact(ContactSurface main, std::vector<Index> secondary, PenaltyContactParams p,
                 const NodalState& nodes, std::vector<double> node_gap = {},
                 std::vector<double> node_k0 = {});

  // Adds contact forces to nodes.force (nodes.force_ext is left alone: contact forces
  // are internal to the model) and contact stiffness to nodes.stiffness. Positions x^n,
  // velocities v^{n-1/2}; dt_prev = t^n - t^{n-1}, the step v^{n-1/2} acted over (0 at
  // the first cycle): friction slip and dissipation use v^{n-1/2} dt_prev.
  void add_forces(NodalState& nodes, double time, double dt_prev);

  // Work of the contact forces on the nodes through t^n [energy]. The normal law is
  // conservative with potential U(p), so its work is exactly -U(p^n) (no quadrature
  // error at contact onset and release, where a trapezoid over a force jump would
  // leave a residue); friction and damping add their dissipation increments:
  //   W = -(U(p^n) + E_friction + E_damping) = -energy().
  double work() const { return -energy(); }
  // The same work integrated by the trapezoid 0.5 (f^{n-1} + f^n) . v^{n-1/2} dt_prev
  // (diagnostic: tends to work() as the step goes to zero).
  double trapezoid_work() const { return work_; }

  // Energies [energy]: elastic (stored in the penalty springs now), friction (stored in
  // the tangential springs + dissipated so far), damping (dissipated so far).
  double elastic_energy() const { return elastic_energy_; }
  double friction_energy() const { return friction_stored_ + friction_dissipated_; }
  double damping_energy() const { return damping_dissipated_; }
  double energy() const { return elastic_energy() + friction_energy() + damping_energy(); }
  const ContactResultant& resultant() const { return resultant_; }
  // Smallest nodal step sqrt(2 m / k_n) over the nodes in contact this cycle, with k_n
  // the assembled stiffness including the contact's (infinity if none) [time]. The
  // engine's element-step mode takes it into account (times Tsca).
  double critical_step() const { return critical_step_; }

  // Search statistics (bench, tests).
  std::size_t n_sorts() const { return n_sorts_; }
  std::size_t n_candidates() const { return cand_segment_.size(); }
  std::size_t n_secondary() const { return secondary_.size(); }
  double margin() const { return margin_; }
  std::size_t n_entry_caps() const { return n_entry_caps_; }
  // Inacti 5/6: a penetration gained in one cycle beyond this fraction of the gap is an
  // entry (past an edge), not an approach (add_forces).
  static constexpr double kEntryJump = 0.2;
  double gap_of_pair(std::size_t secondary_slot, Index segment) const;
  const ContactSurface& surface() const { return surf_; }

  // Penalty law (exposed for tests): force and potential at penetration p, gap g.
  static double law_force(double p, double g, double kp, double kmax, bool linear);
  static double law_energy(double p, double g, double kp, double kmax, bool linear);
  // dF/dp of law_force, and the penetration where the shell law's tangent reaches kmax.
  static double law_stiffness(double p, double g, double kp, double kmax, bool linear);
  static double law_tangent_limit(double g, double kp, double kmax);

 private:
  void sort(const NodalState& nodes);
  bool needs_sort(const NodalState& nodes) const;
  void update_segment_cache(const NodalState& nodes);
  // Projection of secondary slot i (position xs) on candidate segment seg: false if the
  // cheap bounds or the one-sided depth rule reject it; else the projection, the pair's
  // gap, the signed distance (negative past a solid face) and the push direction.
  bool project_candidate(const NodalState& nodes, std::size_t i, Index seg, const V3& xs,
                         SegmentProjection& pr, double& g, double& signed_d, V3& n) const;
  // Inacti 5/6: reduced gap of slot i at the first active cycle (+inf if not penetrated).
  double initial_gap_cap(const NodalState& nodes, std::size_t i, const V3& xs) const;
  // Penalty stiffness kp and its cap kmax of secondary slot i against segment seg (Istf,
  // Stfac, Stmin, Stmax and the fixed-step cap of the node's mass).
  std::pair<double, double> pair_stiffness(const NodalState& nodes, std::size_t i, Index seg) const;
  double gap_cap_factor() const { return p_.inacti == 6 ? 0.95 : 1.0; }
  double pair_power(const NodalState& nodes, std::size_t slot, V3 f, Index seg,
                    const std::array<double, 4>& w) const;

  ContactSurface surf_;
  std::vector<Index> secondary_;
  PenaltyContactParams p_;
  std::vector<double> node_gap_, node_k0_;
  double cap_per_mass_ = 0;            // K cap / nodal mass [1/time^2]
  double margin_ = 0;
  double max_gap_ = 0;

  // Self-contact exclusion: per secondary node, the segments it must never hit (its own
  // segments and their edge/corner neighbours), CSR sorted.
  std::vector<std::uint32_t> excl_start_;
  std::vector<Index> excl_seg_;

  // Candidates (CSR over secondary nodes) and the positions of all tracked nodes at the
  // last sort.
  std::vector<std::uint32_t> cand_start_;
  std::vector<Index> cand_segment_;
  std::vector<Index> tracked_;
  std::vector<double> sort_x_, sort_y_, sort_z_;
  BucketGrid grid_;
  std::vector<Box> boxes_;
  std::size_t n_sorts_ = 0;
  // Segments that are a candidate of some secondary node (sorted, set by sort()): the
  // only ones whose per-cycle geometry is read.
  std::vector<Index> cand_segments_used_;
  // Per-cycle segment geometry for the cheap rejection test (valid for the candidate
  // segments only).
  std::vector<V3> seg_centre_, seg_normal_;
  std::vector<double> seg_warp_, seg_radius_;

  // Friction state per secondary node.
  std::vector<V3> tangential_;
  std::vector<double> pair_friction_stored_;

  double elastic_energy_ = 0, friction_stored_ = 0, friction_dissipated_ = 0;
  double damping_dissipated_ = 0;
  double work_ = 0;
  double critical_step_ = std::numeric_limits<double>::infinity();
  ContactResultant resultant_;

  // Last cycle's force on each secondary node, its segment and weights (work update).
  std::vector<V3> prev_force_;
  std::vector<Index> prev_segment_;
  std::vector<double> prev_pen_;       // penetration of the last cycle (0: not in contact)
  std::vector<double> prev_energy_;    // penalty potential of the last cycle's pair (0: none)
  std::size_t n_entry_caps_ = 0;       // Inacti 5/6: gaps reduced at an entry during the run
  std::vector<std::array<double, 4>> prev_weight_;
  std::vector<double> prev_damping_, prev_vn_;  // damping force (along prev normal), v_n
  // Viscous friction (Iform 1) of the last cycle and the relative velocity it was computed
  // from: its dissipation is accounted next cycle, as the damping's.
  std::vector<V3> prev_friction_, prev_vrel_;
  std::vector<V3> prev_normal_;
  // Inacti 5/6: per secondary slot, upper bound on the gap of its pairs (+inf: none);
  // set at the first active cycle (gap_cap_set_), then only raised.
  std::vector<double> gap_cap_;
  bool gap_cap_set_ = false;
};

}  // namespace hbm::solver::contact
