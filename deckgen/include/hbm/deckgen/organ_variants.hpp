// SPDX-License-Identifier: GPL-3.0-or-later
// Anatomical variants of the thoracic organ block, for calibration studies (issue 8;
// geometry/calibration-notes-validation.md, "Tissue viscosity, a pleura and the presternal
// tissue against the two frontal speeds"). The default model follows the seed: one
// undifferentiated, air-filled organ block sharing every node with the rib cage and the
// thoracic flesh. Neither variant is the default; each is a post-pass on the built model.
//  - Pleura: the lungs slide on the chest wall. The organ block's nodes that it shares
//    only with the wall (ribs, costal cartilage, sternum, thoracic flesh) are duplicated,
//    the block takes the copies, and a frictionless /INTER/TYPE7 holds the wall nodes on the
//    block's surface (the pleural cavity holds a few ml of lubricating fluid). Nodes the block
//    shares with anything else (spine, discs, abdominal organs, inlet fascia, springs, rigid
//    bodies) stay shared: the lungs hang from the hilum and the mediastinum. Contact
//    interfaces on wall nodes stay with the wall.
//  - Mediastinum: the block between the lungs (heart, great vessels, blood, oesophagus) is
//    water-like, not air-filled: the organ bricks whose centroid lies within a half width of
//    the mid-plane (y = 0) become a part `mediastinum` with the abdominal organ set
//    (1060 kg/m^3, the liver's bulk modulus). Applied after the pleura, the band slides on
//    the wall with the rest of the block (it joins the pleura's main surface).
#pragma once

#include "hbm/deckgen/fe_model.hpp"

namespace hbm::deckgen {

// Detaches the thoracic organ block from the chest wall; returns the number of nodes
// detached (the wall keeps the originals, the block gets new ones at the same places).
// Throws std::invalid_argument if the model has no part `thoracic_organs`.
std::size_t add_pleura(FeModel& m);

// Moves the thoracic organ elements whose centroid has |y| < half_width (mm) to a new part
// `mediastinum` with the material `abdominal_organs`; returns how many moved. Throws
// std::invalid_argument for a half width <= 0 or a model without those part and material.
std::size_t add_mediastinum(FeModel& m, double half_width);

}  // namespace hbm::deckgen
