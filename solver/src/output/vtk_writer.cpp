// SPDX-License-Identifier: GPL-3.0-or-later
// VTK XML writer (format: "VTK File Formats", Kitware, XML UnstructuredGrid with
// appended raw data; each block is a UInt64 byte count followed by the values).
#include "output/vtk_writer.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace hbm::solver {

bool write_file_atomically(const std::filesystem::path& path, const std::string& text, std::string& error) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) {
      error = "cannot write " + tmp.string();
      return false;
    }
    f.write(text.data(), static_cast<std::streamsize>(text.size()));
    f.flush();
    if (!f) {
      error = "write failed: " + tmp.string();
      return false;
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    error = "cannot rename " + tmp.string() + ": " + ec.message();
    return false;
  }
  return true;
}

VtkWriter::VtkWriter(std::filesystem::path dir, std::string run_name)
    : dir_(std::move(dir)), name_(std::move(run_name)) {}

std::filesystem::path VtkWriter::pvd_path() const { return dir_ / (name_ + ".pvd"); }

namespace {

// Appended data blocks and the XML that references them.
class Appended {
 public:
  template <class T>
  std::string array(const char* type, const char* name, int components, const std::vector<T>& v) {
    std::ostringstream x;
    x << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\"" << components
      << "\" format=\"appended\" offset=\"" << data_.size() << "\"/>\n";
    const std::uint64_t bytes = v.size() * sizeof(T);
    append(&bytes, sizeof bytes);
    append(v.data(), bytes);
    return x.str();
  }
  const std::string& data() const { return data_; }

 private:
  void append(const void* p, std::size_t n) { data_.append(static_cast<const char*>(p), n); }
  std::string data_;
};

}  // namespace

bool VtkWriter::write_frame(const Model& m, double time, const Vec3Soa& vel, std::string& error) {
  const NodalState& n = m.nodes;
  const std::size_t nn = n.n_nodes;
  std::vector<double> pts(3 * nn), disp(3 * nn), v(3 * nn), fcont(3 * nn), dmas(nn);
  for (std::size_t i = 0; i < nn; ++i) {
    pts[3 * i] = n.x.x[i];
    pts[3 * i + 1] = n.x.y[i];
    pts[3 * i + 2] = n.x.z[i];
    disp[3 * i] = n.x.x[i] - n.x0.x[i];
    disp[3 * i + 1] = n.x.y[i] - n.x0.y[i];
    disp[3 * i + 2] = n.x.z[i] - n.x0.z[i];
    v[3 * i] = vel.x[i];
    v[3 * i + 1] = vel.y[i];
    v[3 * i + 2] = vel.z[i];
    fcont[3 * i] = n.contact_force.x[i];
    fcont[3 * i + 1] = n.contact_force.y[i];
    fcont[3 * i + 2] = n.contact_force.z[i];
    dmas[i] = n.added_mass[i];
  }
  std::vector<std::int64_t> conn, offsets, part, elem;
  std::vector<std::uint8_t> types;
  std::vector<double> vm, epsp, eroded, ener, hourg, buf;
  for (const auto& g : m.groups) {
    const std::int64_t pid = m.parts[static_cast<std::size_t>(g->part)].id;
    Index nodes[8];
    for (std::size_t e = 0; e < g->n_elements; ++e) {
      int k = 0;
      const VtkCellType t = g->vtk_cell(e, nodes, k);
      for (int j = 0; j < k; ++j) conn.push_back(nodes[j]);
      offsets.push_back(static_cast<std::int64_t>(conn.size()));
      types.push_back(static_cast<std::uint8_t>(t));
      part.push_back(pid);
      elem.push_back(g->element_id[e]);
    }
    for (auto [field, out] : {std::pair{CellField::VonMises, &vm}, std::pair{CellField::PlasticStrain, &epsp},
                              std::pair{CellField::Eroded, &eroded}, std::pair{CellField::SpecificEnergy, &ener},
                              std::pair{CellField::HourglassEnergy, &hourg}}) {
      buf.assign(g->n_elements, 0.0);
      g->cell_field(field, buf);
      out->insert(out->end(), buf.begin(), buf.end());
    }
  }
  Appended a;
  std::ostringstream x;
  x << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
    << "<UnstructuredGrid>\n<FieldData>\n";
  const std::vector<double> tv{time};
  x << a.array("Float64", "TimeValue", 1, tv);
  x << "</FieldData>\n<Piece NumberOfPoints=\"" << nn << "\" NumberOfCells=\"" << types.size() << "\">\n";
  x << "<PointData Vectors=\"displacement\">\n"
    << a.array("Float64", "displacement", 3, disp) << a.array("Float64", "velocity", 3, v)
    << a.array("Float64", "contact_force", 3, fcont)
    << a.array("Float64", "added_mass", 1, dmas) << "</PointData>\n";
  x << "<CellData Scalars=\"part\">\n"
    << a.array("Int64", "part", 1, part) << a.array("Int64", "element_id", 1, elem)
    << a.array("Float64", "von_mises", 1, vm) << a.array("Float64", "plastic_strain", 1, epsp)
    << a.array("Float64", "eroded", 1, eroded) << a.array("Float64", "specific_energy", 1, ener)
    << a.array("Float64", "hourglass_energy", 1, hourg) << "</CellData>\n";
  x << "<Points>\n" << a.array("Float64", "Points", 3, pts) << "</Points>\n";
  x << "<Cells>\n"
    << a.array("Int64", "connectivity", 1, conn) << a.array("Int64", "offsets", 1, offsets)
    << a.array("UInt8", "types", 1, types) << "</Cells>\n";
  x << "</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
  std::string text = x.str();
  text += a.data();
  text += "\n</AppendedData>\n</VTKFile>\n";
  char fname[64];
  std::snprintf(fname, sizeof fname, "_%04zu.vtu", frames_.size());
  const std::string file = name_ + fname;
  if (!write_file_atomically(dir_ / file, text, error)) return false;
  frames_.emplace_back(time, file);
  std::ostringstream p;
  p.precision(17);
  p << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
    << "<Collection>\n";
  for (const auto& [t, f] : frames_) p << "<DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << f << "\"/>\n";
  p << "</Collection>\n</VTKFile>\n";
  return write_file_atomically(pvd_path(), p.str(), error);
}

}  // namespace hbm::solver
