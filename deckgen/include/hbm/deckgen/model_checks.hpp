// SPDX-License-Identifier: GPL-3.0-or-later
// Checks deckgen prints and the tests assert: element budget per region and kind, stable
// time step and added mass at t = 0 (nodal mass scaling /DT/NODA/CST), element quality
// per part, and mass properties per segment against the reference targets.
#pragma once

#include "hbm/deckgen/body_mesher.hpp"
#include "hbm/deckgen/fe_model.hpp"
#include "hbm/deckgen/geometry_sources.hpp"

#include <Eigen/Core>

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace hbm::deckgen {

// Nodal masses lumped from the elements (kg), without rigid-body added masses.
std::vector<double> element_nodal_masses(const FeModel& m);
// Mass of each element (kg), in the order bricks, shells, trias.
double element_mass(const FeModel& m, ElementKind kind, std::size_t e);

// Sets each rigid body's added mass and inertia so that its segment matches the target
// (mass and inertia about the target CoG); moves nothing. Rigid bodies without a target
// get none. Throws if a segment's elements already weigh more than its target.
void assign_rigid_body_masses(FeModel& m, const GeometrySources& g);

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
  Eigen::Vector3d principal = Eigen::Vector3d::Zero(), target_principal = Eigen::Vector3d::Zero();
  bool check_mass = true, check_cog = false, has_target_inertia = false;
  double mass_error() const { return (mass - target_mass) / target_mass; }
  double cog_error() const { return (cog - target_cog).norm(); }
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
