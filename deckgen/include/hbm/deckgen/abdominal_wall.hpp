// SPDX-License-Identifier: GPL-3.0-or-later
// The abdominal wall's musculo-aponeurotic layer (issue 8; geometry/materials.csv and
// shell_sections.csv `abdominal_wall`, geometry/calibration-notes-validation.md).
//
// The trunk-wall flesh is an isotropic viscoelastic solid that relaxes to a shear modulus of
// 1.5 kPa within a few ms (materials.csv flesh). The real wall holds, besides that tissue,
// sheets of muscle and aponeurosis (transversus abdominis, internal and external obliques,
// rectus abdominis in its sheath) that span from the lower ribs and the costal margin to the
// iliac crest and the pubis and carry membrane tension. The layer stands for them: shells on
// the faces of the abdominal organ block that face the trunk-wall flesh in front of the spine
// and on the flanks, a membrane of the wall's published tension-strain stiffness.
//  - Faces: boundary faces of the bricks of `abdominal_organs` and `abdominal_organs_pelvis`
//    (a face no other organ brick has) with at least two nodes in the flesh (parts of region
//    `flesh`), not lying on another part (no other part holds all four nodes: rib, costal
//    cartilage, pelvic cortex and joint shells, spine bricks), whose outward normal n (from
//    the brick's centroid) has n_x > -0.5 (not the back, where the column and the erector
//    spinae are) and n_z > -0.7 (not the block's floor: the pelvic floor is not this layer),
//    and whose centre lies above `z_pubis`, the pubic symphysis' height: the wall inserts on
//    the pubic crest and the inguinal ligament, not in front of the perineum below them.
//  - The tetra flesh rests on every other level of the block's surface: two chosen faces
//    that share an edge whose nodes the flesh does not hold become one quad, the flesh
//    cell's inner face (160 quads in the default model).
//  - The layer shares its nodes with the organ block, the flesh, the lower ribs and costal
//    cartilage at the top and the pelvic cortex at the bottom: no new node.
//  - A face warped by more than 15 degrees becomes two triangles along its shorter diagonal
//    (part `abdominal_wall_tria`), as the skin does.
//  - Mass: the layer's tissue is also in the flesh tetras that fill the wall; its own mass
//    (density x thickness x area, 0.07 kg) is counted twice and reported in the note.
#pragma once

#include "hbm/deckgen/fe_model.hpp"

#include <cstddef>

namespace hbm::deckgen {

struct AbdominalWallLayer {
  std::size_t quads = 0, trias = 0;
  double area_mm2 = 0, mass_kg = 0;
  std::size_t rib_nodes = 0, pelvis_nodes = 0;  // nodes shared with rib cage shells / pelvic shells
};

// Adds the parts `abdominal_wall` (quads) and `abdominal_wall_tria` with `material` (added
// to the model) and the shell thickness `thickness_mm`, on the faces above the height
// `z_pubis` (mm); returns what it made. Throws std::invalid_argument if the model has no
// part `abdominal_organs`, if the thickness is not positive, or if no face qualifies.
AbdominalWallLayer add_abdominal_wall(FeModel& m, FeMaterial material, double thickness_mm, double z_pubis);

}  // namespace hbm::deckgen
