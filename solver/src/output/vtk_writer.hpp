// SPDX-License-Identifier: GPL-3.0-or-later
// Animation output: one XML VTK unstructured grid (.vtu, raw binary appended data,
// UInt64 headers) per frame and a .pvd collection listing the frames with their times.
// Cells as themselves (hexahedron, wedge, tetra, quad, triangle, line). Point data:
// displacement, velocity, added mass; cell data: part id, element id, von Mises,
// plastic strain, eroded flag. Every file is written to "<name>.tmp" and renamed.
#pragma once

#include "hbm/solver/model.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace hbm::solver {

class VtkWriter {
 public:
  VtkWriter(std::filesystem::path dir, std::string run_name);
  // Write frame at `time` with velocities `vel` (3 arrays, at t^n). Returns false and
  // sets `error` on I/O failure.
  bool write_frame(const Model& m, double time, const Vec3Soa& vel, std::string& error);
  std::size_t n_frames() const { return frames_.size(); }
  std::filesystem::path pvd_path() const;

 private:
  std::filesystem::path dir_;
  std::string name_;
  std::vector<std::pair<double, std::string>> frames_;
};

// Write `text` to `path` through a temporary file renamed on success.
bool write_file_atomically(const std::filesystem::path& path, const std::string& text, std::string& error);

}  // namespace hbm::solver
