#pragma once
// Mesh files: the format follows the extension. Every write is atomic: the data goes
// to a temporary file beside the target, which is renamed over it only when complete.
#include <filesystem>
#include <span>
#include <string>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf {

enum class MeshFormat { vtp, vtk, ply, off, stl, obj, msms, msh };

// .vtp .vtk .ply .off .stl .obj .vert/.face (MSMS pair) .msh; throws on anything else.
MeshFormat mesh_format_from_path(const std::filesystem::path& path);
const char* mesh_format_name(MeshFormat format);

struct MeshWriteOptions {
  // When given, face tags index these atoms: cell data gets serial, residue and chain,
  // and MSMS .vert gets each vertex's closest atom.
  std::span<const Atom> atoms;
  bool ascii = false;          // .ply (binary little-endian by default), .stl
  bool msms_header = true;     // MSMS .vert/.face 3-line headers
  double probe_radius = 1.4;   // recorded in MSMS headers
  double density = 2.0;        // recorded in MSMS headers
};

// For MSMS the path may name either file of the pair (or end in .vert); both are written.
void write_mesh(const std::filesystem::path& path, const Mesh& mesh, const MeshWriteOptions& options = {});

// Reads .stl (ASCII/binary) .off .ply (ASCII/binary) .obj .vtk .vtp (and MSMS .vert/.face).
// Coincident vertices are not merged except for STL, which has no shared vertices
// (exactly equal coordinates are merged there). Face tags are read back when present.
Mesh read_mesh(const std::filesystem::path& path);

}  // namespace molsurf
