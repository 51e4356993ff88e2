// SPDX-License-Identifier: GPL-3.0-or-later
// The thoracic organ block's parts and its anatomical variants (issue 8;
// geometry/calibration-notes-validation.md). The block shares every node with the rib cage,
// the spine and the thoracic flesh, as in the seed.
//  - Mediastinum: the column between the two pleural sacs (heart, great vessels, blood,
//    oesophagus) is water-like, not air-filled: the organ bricks whose centroid lies within a
//    half width of the mid-plane (y = 0), and below a height, become a part `mediastinum` with
//    the abdominal organ set (1060 kg/m^3, the liver's bulk modulus). The default model
//    (MesherOptions::lungs) cuts the column of thoracic_organs.csv (Gleeson 2001's mean
//    mediastinal width, below the T4 upper endplate) and gives the rest the lungs' set
//    (materials.csv lungs: their air alone, inflated lung's density); hbm-deckgen
//    --mediastinum W re-cuts it. With --undifferentiated-organs (the seed's block, one
//    air-filled set) --mediastinum W cuts a band over the block's whole height.
//  - Pleura (variant): the lungs slide on the chest wall. The block's nodes (with the
//    mediastinum where the model has one) that it shares only with the wall (ribs, costal
//    cartilage, sternum, thoracic flesh) are duplicated, the block takes the copies, and a
//    frictionless /INTER/TYPE7 holds the wall nodes on the block's surface (the pleural
//    cavity holds a few ml of lubricating fluid). Nodes the block shares with anything else
//    (spine, discs, abdominal organs, inlet fascia, springs, rigid bodies) stay shared: the
//    lungs hang from the hilum and the mediastinum. Contact interfaces on wall nodes stay
//    with the wall.
#pragma once

#include "hbm/deckgen/fe_model.hpp"

#include <limits>

namespace hbm::deckgen {

// Detaches the thoracic organ block from the chest wall; returns the number of nodes
// detached (the wall keeps the originals, the block gets new ones at the same places).
// Throws std::invalid_argument if the model has no part `thoracic_organs`.
std::size_t add_pleura(FeModel& m);

// Puts the thoracic organ elements whose centroid has |y| < half_width and z < z_top (mm) in
// the part `mediastinum` (made with the material `abdominal_organs` if the model has none;
// an existing one is re-cut: its elements outside go back to thoracic_organs); returns how
// many are in it. Throws std::invalid_argument for a half width <= 0, an empty column or a
// model without those part and material.
std::size_t add_mediastinum(FeModel& m, double half_width, double z_top = std::numeric_limits<double>::infinity());

}  // namespace hbm::deckgen
