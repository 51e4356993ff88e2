// SPDX-License-Identifier: GPL-3.0-or-later
// Anatomical landmarks the load cases aim at, read from the geometry sources the model was
// generated from (geometry/spine_landmarks.csv, geometry/pelvis_landmarks.csv): vertebral
// body centres (mean of the upper and lower endplate centres, mid-sagittal) and named
// pelvis points. Malformed tables give file:line errors.
#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <string>

namespace hbm::deckgen::loadcases {

// Centre of a vertebral body (e.g. "T8"): midpoint of its endplate centres, y = 0 (mm).
Eigen::Vector3d vertebra_centre(const std::filesystem::path& geometry_dir, const std::string& level);
// Named pelvis landmark (e.g. "greater_trochanter_l"). A missing "_l" landmark is taken as
// the mirror image (y -> -y) of its "_r" counterpart (the model is symmetric).
Eigen::Vector3d pelvis_landmark(const std::filesystem::path& geometry_dir, const std::string& name);

}  // namespace hbm::deckgen::loadcases
