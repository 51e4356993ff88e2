// SPDX-License-Identifier: GPL-3.0-or-later
// assimp surface import/export and the torso surface check (see surface_io.hpp).
#include "hbm/deckgen/surface_io.hpp"

#include "hbm/deckgen/model_checks.hpp"
#include "hbm/deckgen/table.hpp"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cmath>
#include <iomanip>
#include <ostream>
#include <type_traits>
#include <utility>

namespace hbm::deckgen {

TriSurface outer_surface(const FeModel& m) {
  std::vector<std::array<int, 4>> quads;
  for (std::size_t e = 0; e < m.shells.size(); ++e) {
    const FePart& p = m.parts[static_cast<std::size_t>(m.shell_part[e])];
    if (p.region == "skin" || p.region == "head" || p.region == "limbs") quads.push_back(m.shells[e]);
  }
  for (std::size_t e = 0; e < m.trias.size(); ++e) {
    const FePart& p = m.parts[static_cast<std::size_t>(m.tria_part[e])];
    if (p.region == "skin") quads.push_back({m.trias[e][0], m.trias[e][1], m.trias[e][2], m.trias[e][2]});
  }
  return triangulate(m.nodes, quads);
}

void write_surface(const TriSurface& s, const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::string format = ext == ".stl" ? "stl" : ext == ".obj" ? "obj" : ext == ".ply" ? "ply" : "";
  if (format.empty()) throw std::invalid_argument(file.string() + ": surface export supports .stl, .obj and .ply");
  aiScene scene;
  scene.mRootNode = new aiNode();
  scene.mMaterials = new aiMaterial*[1]{new aiMaterial()};
  scene.mNumMaterials = 1;
  auto* mesh = new aiMesh();
  mesh->mMaterialIndex = 0;
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mNumVertices = static_cast<unsigned>(s.points.size());
  mesh->mVertices = new aiVector3D[s.points.size()];
  for (std::size_t i = 0; i < s.points.size(); ++i)
    mesh->mVertices[i] = aiVector3D(static_cast<float>(s.points[i].x()), static_cast<float>(s.points[i].y()), static_cast<float>(s.points[i].z()));
  mesh->mNumFaces = static_cast<unsigned>(s.triangles.size());
  mesh->mFaces = new aiFace[s.triangles.size()];
  for (std::size_t f = 0; f < s.triangles.size(); ++f) {
    mesh->mFaces[f].mNumIndices = 3;
    mesh->mFaces[f].mIndices = new unsigned[3];
    for (int k = 0; k < 3; ++k) mesh->mFaces[f].mIndices[k] = static_cast<unsigned>(s.triangles[f][static_cast<std::size_t>(k)]);
  }
  scene.mMeshes = new aiMesh*[1]{mesh};
  scene.mNumMeshes = 1;
  scene.mRootNode->mMeshes = new unsigned[1]{0};
  scene.mRootNode->mNumMeshes = 1;
  std::filesystem::path tmp = file;
  tmp.replace_extension(".tmp" + ext);
  Assimp::Exporter ex;
  if (ex.Export(&scene, format, tmp.string()) != AI_SUCCESS) {
    std::filesystem::remove(tmp);
    throw std::runtime_error(file.string() + ": assimp export failed: " + ex.GetErrorString());
  }
  std::filesystem::rename(tmp, file);
}

void export_outer_surface(const FeModel& m, const std::filesystem::path& file) { write_surface(outer_surface(m), file); }

TriSurface import_surface(const std::filesystem::path& file) {
  Assimp::Importer im;
  const aiScene* sc = im.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (!sc || !sc->mRootNode || sc->mNumMeshes == 0)
    throw SourceError(file, 0, "", std::string("cannot read surface: ") + (im.GetErrorString()[0] ? im.GetErrorString() : "no mesh"));
  TriSurface s;
  int face_no = 0;
  for (unsigned mi = 0; mi < sc->mNumMeshes; ++mi) {
    const aiMesh* mesh = sc->mMeshes[mi];
    int base = static_cast<int>(s.points.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw SourceError(file, 0, "vertex " + std::to_string(v + 1), "non-finite coordinate");
      s.points.push_back({p.x, p.y, p.z});
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f, ++face_no) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines are not part of a surface
      std::array<int, 3> t{base + static_cast<int>(face.mIndices[0]), base + static_cast<int>(face.mIndices[1]),
                           base + static_cast<int>(face.mIndices[2])};
      const auto &a = s.points[static_cast<std::size_t>(t[0])], &b = s.points[static_cast<std::size_t>(t[1])],
                 &c = s.points[static_cast<std::size_t>(t[2])];
      if ((b - a).cross(c - a).norm() <= 1e-12)
        throw SourceError(file, 0, "face " + std::to_string(face_no + 1), "degenerate triangle (zero area)");
      s.triangles.push_back(t);
    }
  }
  if (s.triangles.empty()) throw SourceError(file, 0, "", "no triangle faces");
  return s;
}

bool print_surface_check(std::ostream& os, const FeModel& m) {
  auto torso_part = [&](int part) {
    const FePart& p = m.parts[static_cast<std::size_t>(part)];
    return p.segment == "thorax" || p.segment == "abdomen" || p.segment == "pelvis";
  };
  // The torso's elements of one kind and their volume.
  auto torso_elements = [&](ElementKind kind, const auto& elements, const std::vector<int>& part_of) {
    std::vector<typename std::decay_t<decltype(elements)>::value_type> out;
    double volume = 0;
    for (std::size_t e = 0; e < elements.size(); ++e)
      if (torso_part(part_of[e])) {
        out.push_back(elements[e]);
        volume += element_mass(m, kind, e) / m.materials[static_cast<std::size_t>(m.parts[static_cast<std::size_t>(part_of[e])].material)].rho;
      }
    return std::pair(out, volume);
  };
  const auto [torso, hex_volume] = torso_elements(ElementKind::Brick, m.bricks, m.brick_part);
  // The torso's tetras (flesh cut into tetras over a coarser grid than the bricks under it,
  // whose faces they do not share) bound a closed surface of their own, checked apart.
  const auto [tets, tet_volume] = torso_elements(ElementKind::Tetra, m.tetras, m.tetra_part);
  auto report = [&os](const char* what, const TriSurface& s, double element_volume) {
    SurfaceReport r = check_surface(s);
    bool vol_ok = r.closed && std::abs(r.volume - element_volume) <= 1e-3 * element_volume;
    bool ok = r.closed && !r.self_intersecting && vol_ok;
    os << what << " (CGAL): " << r.triangles << " triangles, " << (r.closed ? "closed" : "OPEN") << ", "
       << (r.self_intersecting ? "SELF-INTERSECTING" : "no self-intersection") << ", enclosed volume " << std::fixed << std::setprecision(2)
       << r.volume * 1e-6 << " l vs elements " << element_volume * 1e-6 << " l: " << (ok ? "OK" : "FAIL") << "\n";
    os.unsetf(std::ios::floatfield);
    return ok;
  };
  bool ok = report(tets.empty() ? "Torso boundary surface" : "Torso hexahedra boundary surface",
                   triangulate(m.nodes, hex_boundary_faces(torso)), hex_volume);
  if (!tets.empty()) ok = report("Torso tetra boundary surface", triangulate(m.nodes, tet_boundary_faces(tets)), tet_volume) && ok;
  return ok;
}

void compare_with_envelope(std::ostream& os, const FeModel& m, const std::filesystem::path& file) {
  TriSurface ref = import_surface(file);
  TriSurface gen = outer_surface(m);
  auto box = [](const TriSurface& s) {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (const auto& p : s.points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    return std::pair(lo, hi);
  };
  auto [rl, rh] = box(ref);
  auto [gl, gh] = box(gen);
  SurfaceReport rr = check_surface(ref);
  os << "Reference envelope " << file.string() << ": " << ref.triangles.size() << " triangles, " << (rr.closed ? "closed" : "open");
  if (rr.closed) os << ", volume " << rr.volume * 1e-6 << " l";
  os << "\n  extents reference [" << rl.transpose() << "] - [" << rh.transpose() << "], model [" << gl.transpose() << "] - ["
     << gh.transpose() << "]\n";
}

}  // namespace hbm::deckgen
