// SPDX-License-Identifier: GPL-3.0-or-later
// Checks deckgen prints and the tests assert: element budget per region and kind, stable
// time step and added mass at t = 0 (nodal mass scaling /DT/NODA/CST), element quality
// per part, and mass properties per segment against the reference targets.
#pragma once

#include "hbm/deckgen/body_mesher.hpp"
#include "hbm/deckgen/fe_model.hpp"
#include "hbm/deckgen/geometry_sources.hpp"

#include <Eigen/Core>

#include <cmath>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace hbm::deckgen {

// Nodal masses lumped from the elements (kg), without rigid-body added masses.
std::vector<double> element_nodal_masses(const FeModel& m);
// Mass of each element (kg), in the order bricks, shells, trias.
double element_mass(const FeModel& m, ElementKind kind, std::size_t e);

// The reference segmentation of the model's mass (Zatsiorsky 2002 / de Leva 1996): torso
// mesh mass is split by the planes of the gamma-scanner segmentation, each through its
// landmark and normal to the body's long axis there (the planes are transverse in the
// standing posture and turn with the body part when it sits): suprasternale and xiphion
// normal to the trunk axis, omphalion normal to the lumbar spine at L3-L4, the hip joint
// centres normal to the pelvis axis (pubic symphysis to mid-ASIS, vertical when standing).
// Tissue on the distal side of a hip plane, the buttock, belongs to that thigh as in the
// gamma-scanner data; every other part keeps its own segment. The mass is taken as the
// solver lumps it (each element's mass in equal shares at its nodes) and each nodal share
// goes to the side of the plane its node lies on: the cut is then exact for the lumped-mass
// model the solver integrates, to half an element of resolution, where assigning whole
// elements by centroid would move a layer's mass across a plane.
class SegmentCuts {
 public:
  struct Plane {
    Eigen::Vector3d point, normal;  // normal points to the proximal (head) side
    double side(const Eigen::Vector3d& x) const { return (x - point).dot(normal); }
  };
  SegmentCuts(const ModelLandmarks& lm, const GeometrySources& g);
  // Calls add(segment, weight) for the segment(s) a nodal mass share at x of a part of
  // segment `part_segment` belongs to (weights sum to 1; points on the mid-sagittal plane
  // below the hips go half to each thigh).
  template <class F>
  void classify(const std::string& part_segment, const Eigen::Vector3d& x, F&& add) const;
  // Point where the trunk centreline (skin ring centres) crosses a cut plane.
  Eigen::Vector3d axis_point(const std::string& plane) const;
  const Plane& plane(const std::string& name) const;  // suprasternale, xiphion, omphalion, hip_r, hip_l, mid_hip

 private:
  std::vector<Eigen::Vector3d> centreline_;
  std::map<std::string, Plane> planes_;
};

template <class F>
void SegmentCuts::classify(const std::string& part_segment, const Eigen::Vector3d& x, F&& add) const {
  if (part_segment != "thorax" && part_segment != "abdomen" && part_segment != "pelvis") {
    add(part_segment, 1.0);
    return;
  }
  if (std::abs(x.y()) < 1e-6 && plane("mid_hip").side(x) < 0) {
    add("femur_r", 0.5);
    add("femur_l", 0.5);
  } else if (x.y() < 0 && plane("hip_r").side(x) < 0) add("femur_r", 1.0);
  else if (x.y() > 0 && plane("hip_l").side(x) < 0) add("femur_l", 1.0);
  else if (plane("omphalion").side(x) < 0) add("pelvis", 1.0);
  else if (plane("xiphion").side(x) < 0) add("abdomen", 1.0);
  else add("thorax", 1.0);
}

// Sets each rigid body's added mass, inertia and main node position so that its segment
// (cut as SegmentCuts does: a thigh includes its buttock tissue) matches the target mass,
// CoG and inertia. Rigid bodies without a target get none. Throws if a segment's elements
// already weigh more than its target.
void assign_rigid_body_masses(FeModel& m, const GeometrySources& g, const ModelLandmarks& lm);

// Centroid of the lowest `share` kg of the mesh neck along its axis (T1 top to C0): the
// lower neck that Zatsiorsky's upper trunk holds (segment_targets.csv neck_share_kg).
Eigen::Vector3d lower_neck_centroid(const FeModel& m, const SegmentCuts& cuts, const ModelLandmarks& lm, double share);

struct BudgetRow {
  std::string region, kind;
  std::size_t count = 0;
};
std::vector<BudgetRow> element_budget(const FeModel& m);

struct TimeStepRow {
  std::string part;
  double dt_min = 0;       // ms, smallest element stable step (L/c), rigid parts excluded
  double length_min = 0;   // mm, its characteristic length
  std::size_t below = 0;   // elements with Tsca * dt < Tmin
  double added_mass = 0;   // kg
  bool rigid = false;
};
struct TimeStepReport {
  double tsca = 0.9, tmin = 1.5e-3;  // ms
  std::vector<TimeStepRow> parts;
  double total_mass = 0, added_mass = 0;  // kg
  double added_ratio() const { return added_mass / total_mass; }
};
// Element stable step dt = L / c (bricks: L = volume / largest face area, c dilatational;
// shells: L = area / longest side, triangles: L = 2 area / longest side, c plate wave).
// Nodal stiffness k_n = sum over elements of 2 m_share / dt_e^2 (springs: their stiffness),
// added mass m_add = k_n/2 (Tmin/Tsca)^2 - m where positive (Radioss /DT/NODA/CST).
TimeStepReport time_step_check(const FeModel& m, double tsca = 0.9, double tmin = 1.5e-3);

// Two levels, as HBM quality criteria are usually stated: every element within the hard
// limits, and at most `soft_share_max` of a part's elements outside the target limits.
struct QualityLimits {
  double brick_jacobian_min = 0.3, brick_aspect_max = 10;            // target
  double brick_jacobian_hard = 0.1, brick_aspect_hard = 15;          // every element
  double shell_jacobian_min = 0.4, shell_aspect_max = 8, shell_warpage_max_deg = 15;  // target
  double shell_jacobian_hard = 0.2, shell_aspect_hard = 12, shell_warpage_hard_deg = 30;
  double tria_aspect_max = 8, tria_aspect_hard = 12;
  // Tetras: longest edge / smallest altitude (1.22 regular; 2.45 for the six tetras of a
  // cube; 1 / collapse in the preprocessors' terms, 30 = collapse 0.04). The flesh's sheared
  // one-layer cells reach 24 on the abdominal flank, with a stable step 4 times the run's.
  double tetra_aspect_max = 8, tetra_aspect_hard = 30;
  double soft_share_max = 0.20;
};
struct QualityRow {
  std::string part, kind;
  std::size_t elements = 0, inverted = 0, failing = 0;  // failing: outside the hard limits
  std::size_t soft_failing = 0;                          // outside the target limits
  double jacobian_min = 1, aspect_max = 1, warpage_max_deg = 0, length_min = 1e30;
};
std::vector<QualityRow> quality_check(const FeModel& m, const QualityLimits& lim = {});

struct MassRow {
  std::string segment;
  double mass = 0, target_mass = 0;
  Eigen::Vector3d cog = Eigen::Vector3d::Zero(), target_cog = Eigen::Vector3d::Zero();
  // Unit segment axis (proximal to distal landmark) for axis targets, zero for link targets.
  // de Leva / Zatsiorsky give a trunk segment's CoM only as a fraction of the distance
  // between its landmarks (standing subjects): the reference fixes the CoG along the axis,
  // not its antero-posterior or lateral place.
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
  double axis_length = 0;  // mm, distance between the landmark points the fraction spans
  Eigen::Vector3d principal = Eigen::Vector3d::Zero(), target_principal = Eigen::Vector3d::Zero();
  bool check_mass = true, check_cog = false, has_target_inertia = false;
  bool has_target_cog = true;  // false for rows without a CoG reference (cog_mode none)
  double mass_error() const { return (mass - target_mass) / target_mass; }
  // The CoG error the reference fixes: along the segment axis for axis targets (signed,
  // positive distal), the full distance for link targets.
  double cog_error() const { return axis.isZero() ? (cog - target_cog).norm() : (cog - target_cog).dot(axis); }
  // Distance of the CoG from the segment axis (information only for axis targets).
  double cog_offset_across() const { return axis.isZero() ? 0.0 : ((cog - target_cog) - (cog - target_cog).dot(axis) * axis).norm(); }
};
struct MassReport {
  double total = 0, total_target = 0;
  std::vector<MassRow> segments;
};
MassReport mass_check(const FeModel& m, const GeometrySources& g, const ModelLandmarks& lm);

// Printing (fixed-width tables); each returns true if every row meets its limit.
bool print_budget(std::ostream& os, const std::vector<BudgetRow>& rows, std::size_t total_min, std::size_t total_max);
bool print_time_step(std::ostream& os, const TimeStepReport& r, double max_added_ratio);
bool print_quality(std::ostream& os, const std::vector<QualityRow>& rows, const QualityLimits& lim = {});
bool quality_ok(const QualityRow& r, const QualityLimits& lim = {});
bool print_mass(std::ostream& os, const MassReport& r, double mass_tol, double cog_tol_mm);

}  // namespace hbm::deckgen
