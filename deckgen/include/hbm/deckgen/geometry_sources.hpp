// SPDX-License-Identifier: GPL-3.0-or-later
// All geometry sources of the body model, read from geometry/ and checked: spine
// landmarks, trunk/neck/head/limb envelopes, rib cage, pelvis landmarks, materials, joints,
// segment targets and the URDF skeleton. Units as in the files (mm, kg, MPa, kg/m^3);
// FeModel conversion to kg-mm-ms happens in the mesher.
#pragma once

#include "hbm/deckgen/rib_fracture.hpp"
#include "hbm/deckgen/skeleton.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace hbm::deckgen {

struct VertebraLandmarks {
  std::string name;          // C1..C7, T1..T12, L1..L5, S1
  Eigen::Vector2d upper;     // (x, z) upper endplate centre, mm
  Eigen::Vector2d lower;     // (x, z) lower endplate centre
  int line = 0;
};

// One trunk or neck section: skin and inner wall superellipses (torso_sections.csv).
struct TrunkSection {
  double z = 0;
  double half_width = 0, half_depth = 0, exponent = 2, back = 0;
  double widest_forward = 0;  // mm: skin's widest point ahead of the depth centre (optional column widest_forward_mm)
  double wall_half_width = 0, wall_depth = 0, wall_exponent = 2;
};

class SectionTable {
 public:
  std::vector<TrunkSection> rows;  // increasing z
  TrunkSection at(double z) const; // linear interpolation, constant beyond the ends
};

struct HeadEnvelope {
  double ax = 0, ay = 0, az = 0, centre_above_cog = 0;
};

struct LimbSection {
  double fraction = 0, half_width = 0, half_depth = 0, exponent = 2;
};

enum class CartilageKind { Sternum, CostalMargin, None };

struct RibSpec {
  int index = 0;                   // 1..12
  std::string vertebra;            // T1..T12
  double inclination_deg = 0;
  double end_fraction = 0;
  CartilageKind cartilage = CartilageKind::None;
  // anatomical section at head / mid / anterior end
  double height[3] = {0, 0, 0}, width[3] = {0, 0, 0}, cortical[3] = {0, 0, 0};
  int line = 0;
};

struct MaterialSpec {
  std::string name, law;  // LAW1 or LAW34
  double density = 0;     // kg/m^3
  double e_or_k = 0;      // MPa
  double nu = 0;
  double g0 = 0, ginf = 0;  // MPa
  double beta = 0;          // 1/s
  std::string source;
  int line = 0;
};

struct JointSpec {
  std::string name, kind;   // TYPE8 or TYPE4
  double k[3] = {0, 0, 0};  // N/mm
  double kr[3] = {0, 0, 0}; // N*m/rad
  double c_trans = 0, c_rot = 0;
  int line = 0;
};

struct SegmentTarget {
  std::string name;
  double mass = 0;
  std::string cog_mode;  // link | axis
  double axis_fraction = 0;
  bool check_mass = true, check_cog = false;
  // Mass of the reference segment that the mesh holds in its neck segment (optional column
  // neck_share_kg): `mass` is the reference segment less it, and an axis CoG target is the
  // reference point with it taken out at the mesh neck's lowest neck_share kg.
  double neck_share = 0;
  std::string source;
  int line = 0;
};

struct ShellSection {
  double total_thickness = 0, cortical = 0, height = 0, width = 0, core_density = 0;
  double joint_gap = 0;  // joint bands: the joint space the band stands for (mm)
  int line = 0;
};

// The water-like mediastinum inside the thoracic organ block (thoracic_organs.csv).
struct MediastinumSpec {
  double half_width = 0;     // mm from the mid-plane
  std::string top_vertebra;  // the column starts below this vertebra's upper endplate
  int line = 0;
};

struct GeometrySources {
  std::filesystem::path dir;
  std::vector<VertebraLandmarks> spine;   // C1..S1 top to bottom
  SectionTable torso, neck;
  HeadEnvelope head;
  std::map<std::string, std::vector<LimbSection>> limbs;  // humerus, forearm, femur, tibia, foot
  std::vector<RibSpec> ribs;              // 12
  std::map<std::string, Eigen::Vector3d> pelvis;  // landmarks, both sides
  std::map<std::string, Eigen::Vector3d> limb_points;  // wrist, ankle, heel, toe (_r, _l)
  std::map<std::string, MaterialSpec> materials;
  std::map<std::string, JointSpec> joints;
  std::vector<SegmentTarget> targets;
  std::map<std::string, ShellSection> shell_sections;
  std::map<std::string, double> disc_stiffness;  // N/mm, by disc name (T1T2 ... L5S1)
  RibBoneFailure rib_bone;                        // rib_fracture.csv (E: materials.csv rib_cortical)
  MediastinumSpec mediastinum;                    // thoracic_organs.csv
  Skeleton skeleton;

  const VertebraLandmarks& vertebra(const std::string& name) const;
  const MaterialSpec& material(const std::string& name) const;
  const JointSpec& joint(const std::string& name) const;
};

// Reads every file of `dir`; throws SourceError (file:line: field: message) on the first
// problem.
GeometrySources load_geometry(const std::filesystem::path& dir);

// Individual readers (used by load_geometry and the tests).
std::vector<VertebraLandmarks> read_spine(const std::filesystem::path& file);
SectionTable read_sections(const std::filesystem::path& file);
std::vector<RibSpec> read_ribs(const std::filesystem::path& file);
std::map<std::string, MaterialSpec> read_materials(const std::filesystem::path& file);

}  // namespace hbm::deckgen
