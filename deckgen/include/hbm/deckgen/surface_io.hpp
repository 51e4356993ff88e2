// SPDX-License-Identifier: GPL-3.0-or-later
// Surface files through assimp (STL, OBJ, PLY): export of the generated outer surface for
// viewing, import of a reference envelope surface (file and face in every error), and the
// CGAL checks of the torso's closed boundary surface.
#pragma once

#include "hbm/deckgen/fe_model.hpp"
#include "hbm/deckgen/surface_tools.hpp"

#include <filesystem>
#include <iosfwd>

namespace hbm::deckgen {

// Skin shells and rigid-body envelopes of the model as one triangle surface.
TriSurface outer_surface(const FeModel& m);
void export_outer_surface(const FeModel& m, const std::filesystem::path& file);
// Reads a triangle surface; throws SourceError (file, face index) on unreadable files,
// non-finite coordinates or degenerate faces.
TriSurface import_surface(const std::filesystem::path& file);
void write_surface(const TriSurface& s, const std::filesystem::path& file);

// Torso boundary (from the hexahedra): closed, free of self-intersections, enclosed volume
// equal to the sum of the hexahedra volumes (0.1 %). Prints and returns the verdict.
bool print_surface_check(std::ostream& os, const FeModel& m);
// Prints the volume and extents of the reference surface beside those of the model.
void compare_with_envelope(std::ostream& os, const FeModel& m, const std::filesystem::path& file);

}  // namespace hbm::deckgen
