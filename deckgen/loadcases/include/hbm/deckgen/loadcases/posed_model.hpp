// SPDX-License-Identifier: GPL-3.0-or-later
// A posed variant of the body model: the same deck written by hbm-deckgen with some rigid
// limbs rotated about their joints (--joint NAME=ANGLE), used by a load case whose test
// posture differs from the model's seated driver posture (the oblique thorax cases raise the
// left arm out of the impactor's path). The variant is a committed file generated from the
// same sources as the base model; check_posed_model guards against a stale variant: same
// parts, same node ids, and every node of every part other than the posed limbs at the same
// place (1e-6 mm) as in the base model. Nodes of no part (rigid-body main nodes) are not
// compared; the posed parts should include the joint spring parts that move with the limb.
#pragma once

#include "hbm/deckgen/loadcases/model_view.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace hbm::deckgen::loadcases {

// Where a load case's posed model lies: relative paths are taken from the folder that holds
// the base model's folder (decks/ for decks/hbm50/hbm50.inc).
std::filesystem::path posed_model_path(const std::filesystem::path& base_model, const std::string& posed_model);

// Throws std::runtime_error naming both files, the first differing part or node, and the
// command that regenerates the variant (regenerate_command).
void check_posed_model(const ModelView& base, const ModelView& posed, const std::vector<std::string>& posed_part_prefixes,
                       const std::string& regenerate_command);

}  // namespace hbm::deckgen::loadcases
