// SPDX-License-Identifier: GPL-3.0-or-later
// Builds the 50th percentile male driver model (FeModel) from the geometry sources:
// torso and neck O-grids (organs, flesh, spine columns, skin), rib cage strips (SH3N),
// sternum and costal cartilage, pelvis cortex with sacroiliac and pubic joints, rigid
// acetabula and trochanters, clavicles (deformable shells), rigid scapulae, head and limbs
// (shell envelopes in rigid bodies carrying the reference mass and inertia), spring joints
// (/PROP/TYPE8) and neck ligaments (/PROP/TYPE4), contact interfaces.
#pragma once

#include "hbm/deckgen/fe_model.hpp"
#include "hbm/deckgen/geometry_sources.hpp"
#include "hbm/deckgen/rib_strip.hpp"  // the equivalent rib strip the rib cage is made of

#include <map>
#include <string>

namespace hbm::deckgen {

struct MesherOptions {
  int torso_around = 32;  // nodes around the torso (multiple of 8)
  int neck_around = 16;   // nodes around the neck (multiple of 8)
  int limb_around = 12;   // nodes around a limb envelope
  double limb_ring_spacing = 45;  // mm between limb envelope rings (32 before the tetra flesh, 40 before the abdominal wall took elements)
  int head_cells = 6;     // cube-sphere cells per cube face edge
  int clavicle_around = 6, clavicle_along = 8;
  // Torso flesh as one layer of average nodal pressure tetras over cells two layers high
  // (body_mesher.cpp build_tetra_flesh); false: two rings of one-point bricks, whose
  // hourglass energy issue #8 does not accept (docs/engine-design.md §12.10).
  bool flesh_tetra = true;
  // Rib fracture model (rib_fracture.hpp): elastoplastic rib strips deleted at the failure
  // strain of a subject of this age [years]; < 0: elastic ribs (the default model).
  double rib_fracture_age = -1;
  // The thoracic organ block as the lungs (materials.csv lungs) and a water-like mediastinum
  // (thoracic_organs.csv; organ_variants.hpp), the default since 2026-11-25; false: the
  // seed's undifferentiated, air-filled block (materials.csv thoracic_organs). The
  // mediastinum's half width (mm), <= 0: the source's.
  bool lungs = true;
  double mediastinum_half_width = -1;
  // The abdominal wall's musculo-aponeurotic membrane (abdominal_wall.hpp), the default since
  // 2026-11-25; false: the trunk wall of flesh and skin alone (hbm-deckgen --no-abdominal-wall).
  bool abdominal_wall = true;
};

// Landmarks of the built model used by the checks (region boundaries for the trunk CoG).
struct ModelLandmarks {
  std::map<std::string, Eigen::Vector3d> boundary_centres;  // "T1_upper", "T12_lower", "L5_lower", "seat", "C0"
  // Surface landmarks of the Zatsiorsky / de Leva trunk segmentation located on the mesh
  // (front midline skin nodes): "suprasternale" (top of the sternum), "xiphion" (bottom of
  // the sternum), "omphalion" (L3-L4 level).
  std::map<std::string, Eigen::Vector3d> points;
  // Centres of the torso skin rings, one per torso level from the seat upwards.
  std::vector<Eigen::Vector3d> trunk_centreline;
  std::map<std::string, std::string> region_of_segment;
  std::vector<int> skin_outer_faces_first;  // unused placeholder for exports
};

FeModel build_body_model(const GeometrySources& g, const MesherOptions& opt, ModelLandmarks* landmarks = nullptr);

// Sandwich plate (two cortices tc on a core, total thickness T) as one shell: per unit width
// I = (T^3 - (T - 2 tc)^3) / 12 and A = 2 tc of the cortices; a shell of thickness
// t = sqrt(12 I / A) and modulus E A / t (modulus_scale = A / t) has the cortices' membrane
// and bending stiffness. A core of no stiffness carries only mass; tc >= T / 2 is a solid plate
// (t = T, modulus unchanged).
struct EquivalentPlate {
  double thickness = 0;      // t (mm)
  double modulus_scale = 0;  // E_eq / E_cortex
};
EquivalentPlate sandwich_plate(double total, double cortical);

}  // namespace hbm::deckgen
