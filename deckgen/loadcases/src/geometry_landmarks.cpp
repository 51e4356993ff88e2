// SPDX-License-Identifier: GPL-3.0-or-later
// Landmark look-up in the geometry CSV tables (see geometry_landmarks.hpp).
#include "hbm/deckgen/loadcases/geometry_landmarks.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace hbm::deckgen::loadcases {

namespace {

struct CsvRow {
  int line = 0;
  std::vector<std::string> cells;
};

struct CsvTable {
  std::string file;
  std::vector<std::string> header;
  std::vector<CsvRow> rows;

  int column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    throw std::runtime_error(file + ": no column '" + name + "' in the header");
  }
  double number(const CsvRow& r, const std::string& name) const {
    const auto c = static_cast<std::size_t>(column(name));
    if (c >= r.cells.size())
      throw std::runtime_error(file + ":" + std::to_string(r.line) + ": field " + name + ": missing");
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(r.cells[c], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != r.cells[c].size() || !std::isfinite(v))
      throw std::runtime_error(file + ":" + std::to_string(r.line) + ": field " + name + " = '" + r.cells[c] +
                               "': not a finite number");
    return v;
  }
};

CsvTable read_csv(const std::filesystem::path& p) {
  std::ifstream in(p);
  if (!in) throw std::runtime_error(p.string() + ": cannot open");
  CsvTable t;
  t.file = p.string();
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    if (t.header.empty())
      t.header = cells;
    else
      t.rows.push_back({n, cells});
  }
  if (t.header.empty()) throw std::runtime_error(t.file + ": no header line");
  return t;
}

}  // namespace

Eigen::Vector3d vertebra_centre(const std::filesystem::path& geometry_dir, const std::string& level) {
  const CsvTable t = read_csv(geometry_dir / "spine_landmarks.csv");
  const int c = t.column("level");
  for (const CsvRow& r : t.rows)
    if (static_cast<std::size_t>(c) < r.cells.size() && r.cells[static_cast<std::size_t>(c)] == level)
      return {0.5 * (t.number(r, "upper_x_mm") + t.number(r, "lower_x_mm")), 0.0,
              0.5 * (t.number(r, "upper_z_mm") + t.number(r, "lower_z_mm"))};
  throw std::runtime_error(t.file + ": no vertebra '" + level + "'");
}

Eigen::Vector3d pelvis_landmark(const std::filesystem::path& geometry_dir, const std::string& name) {
  const CsvTable t = read_csv(geometry_dir / "pelvis_landmarks.csv");
  const int c = t.column("name");
  auto find = [&](const std::string& n, Eigen::Vector3d& out) {
    for (const CsvRow& r : t.rows)
      if (static_cast<std::size_t>(c) < r.cells.size() && r.cells[static_cast<std::size_t>(c)] == n) {
        out = {t.number(r, "x_mm"), t.number(r, "y_mm"), t.number(r, "z_mm")};
        return true;
      }
    return false;
  };
  Eigen::Vector3d p;
  if (find(name, p)) return p;
  if (name.size() > 2 && name.substr(name.size() - 2) == "_l" && find(name.substr(0, name.size() - 2) + "_r", p))
    return {p.x(), -p.y(), p.z()};
  throw std::runtime_error(t.file + ": no landmark '" + name + "'");
}

}  // namespace hbm::deckgen::loadcases
