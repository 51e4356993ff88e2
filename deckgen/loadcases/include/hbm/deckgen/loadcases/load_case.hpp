// SPDX-License-Identifier: GPL-3.0-or-later
// Pendulum (hub) impact load cases on the body model: the catalogue of validation cases
// (Lebarbe & Petit 2012 frontal hub, Viano 1989 oblique thorax and lateral pelvis) and the
// generator that writes a Radioss deck pair NAME_0000.rad / NAME_0001.rad which
// #includes the model, adds a rigid shell impactor with a rounded face edge (/RBODY,
// /INIVEL/TRA, rotations fixed), a /INTER/TYPE7 contact impactor face vs skin (and the limbs
// in the impactor's path), time histories named as the corridor
// cases expect ("impactor", "T8", "sternum"), and the fixed-step run control of the model
// (/DT/NODA/CST 0.9 1.5e-3, /STOP DMmax 0.01). Frame of the model: x forward, y left, z up.
#pragma once

#include "hbm/deckgen/loadcases/model_view.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace hbm::deckgen::loadcases {

enum class Target {
  MidSternum,        // impactor axis horizontal through the middle of the sternum's height, y = 0
  XiphoidCentre,     // axis through the torso centre at the level of the sternum's lower end
  GreaterTrochanter  // axis through the greater trochanter landmark on the struck side
};

struct LoadCaseSpec {
  std::string name;           // deck name and folder, e.g. hub_frontal_6p7
  std::string title;
  std::string reference;      // the test series the corridor comes from
  std::string corridor_case;  // case file for hbm-corridors, relative to the repository root
  double speed_m_s = 0;       // = mm/ms
  double mass_kg = 23.4;
  // Outer diameter of the impactor cylinder; the flat part of the face is this less twice
  // the edge radius (49 CFR 572.36(a): 6 in cylinder, flat face, 0.5 in edge radius).
  double face_diameter_mm = 152;
  double edge_radius_mm = 12.7;
  // Approach direction in the horizontal plane, measured from +x (front) towards +y (left):
  // 0 frontal, 90 lateral from the left, 60 = 30 deg forward of lateral (oblique).
  double approach_deg = 0;
  Target target = Target::MidSternum;
  std::string trochanter_landmark = "greater_trochanter_l";
  std::vector<std::string> contact_part_prefixes{"skin_"};  // the struck surface: aim and footprint
  // Other parts whose nodes are impactor contact secondaries: limbs in the impactor's path
  // (the hanging arm in the oblique thorax cases, the thigh in the pelvis case). The face is
  // placed clear of these too, so a limb ahead of the skin is struck first.
  std::vector<std::string> limb_part_prefixes;
  // Posed variant of the model for this case (posed_model.hpp), relative to the folder that
  // holds the base model's folder; empty: the base model as given (--model). The variant
  // must equal the base model except for the nodes of posed_part_prefixes.
  std::string posed_model;
  std::vector<std::string> posed_part_prefixes;
  std::string posed_model_options;  // the hbm-deckgen options that pose it, e.g. "--joint shoulder_l=-60"
  std::string posture;              // one line for the deck header
  // The hbm-deckgen command, run from the repository root, that writes the posed variant
  // beside decks/hbm50/ ("" without one).
  std::string posed_model_command() const;
  std::string spine_level = "T8";
  double tstop_ms = 60;
  double initial_clearance_mm = 3;  // impactor surface to the nearest contact node in its footprint
  double contact_gap_mm = 1;        // /INTER/TYPE7 Gapmin
  double friction = 0.2;            // impactor face on skin
  // Contact damping as a fraction of critical (Radioss VIS_S). Critical damping: with the
  // default 0.05 the skin nodes, far softer than the penalty, bounce off the face and the
  // sampled impactor force is mostly zero between impulses (seen on the stand-in body).
  double contact_damping = 1.0;
  double th_interval_ms = 0.01;     // /TFILE (100 kHz: the CFC 180 filter sees no aliasing)
  double anim_interval_ms = 5;
};

// The validation cases of issue 8 (names: hub_frontal_4p3, hub_frontal_6p7,
// hub_oblique_4p4, hub_oblique_6p5, hub_oblique_9p5, hub_pelvis_lateral_5p2).
const std::vector<LoadCaseSpec>& catalogue();
const LoadCaseSpec* find_case(const std::string& name);

struct GeneratedCase {
  std::filesystem::path starter, engine;
  Eigen::Vector3d face_centre, travel;   // travel: unit direction of motion
  double first_contact_ms = 0;           // (clearance - gap) / speed
  std::int64_t impactor_main_node = 0, spine_node = 0, sternum_node = 0;
  double spine_node_distance_mm = 0;     // from the vertebral body centre
  std::size_t contact_nodes = 0, footprint_contact_nodes = 0;  // struck skin and limbs together
  std::size_t limb_contact_nodes = 0;    // of which nodes of the limb parts
  std::string nearest_part;              // part of the contact node that sets the face position
  double impactor_mass_kg = 0;           // shells + added mass on the rigid body
  std::vector<std::string> warnings;
};

// Writes DIR/NAME_0000.rad and DIR/NAME_0001.rad (DIR = out_dir) from the model at
// model_path (included by a path relative to DIR) and the landmarks in geometry_dir.
// The folder is written under a temporary name, both decks are read back and checked
// with the deck library (following the #include), and only then renamed into place:
// on any error nothing is left and std::runtime_error explains why.
GeneratedCase generate_load_case(const LoadCaseSpec& spec, const ModelView& model,
                                 const std::filesystem::path& model_path,
                                 const std::filesystem::path& geometry_dir, const std::filesystem::path& out_dir);

void print_generated(std::ostream& os, const LoadCaseSpec& spec, const GeneratedCase& g);

}  // namespace hbm::deckgen::loadcases
