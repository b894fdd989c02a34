#pragma once
// Mesh files: the format follows the extension. Every write is atomic: the data goes
// to a temporary file beside the target, which is renamed over it only when complete.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/sphere_arrangement.hpp"

namespace molsurf {

enum class MeshFormat { vtp, vtk, ply, off, stl, obj, msms, msh };

inline constexpr int kMsmsExact = -1;  // MeshWriteOptions::msms_decimals: round-trip exact

// .vtp .vtk .ply .off .stl .obj .vert/.face (MSMS pair) .msh; throws on anything else.
MeshFormat mesh_format_from_path(const std::filesystem::path& path);
const char* mesh_format_name(MeshFormat format);

struct MeshWriteOptions {
  // When given, face tags index these atoms: cell data gets serial, residue and chain,
  // and MSMS .vert gets each vertex's closest atom.
  std::span<const Atom> atoms;
  // With `atoms`: the face tag each of them stands for, increasing (a process's share of a
  // structure cut into blocks, its atoms tagged by their index in the whole structure);
  // empty: tag k is atoms[k]. Read by the .vtp and .vtk writers; the other formats refuse it.
  std::span<const std::uint32_t> atom_tags;
  bool ascii = false;          // .ply (binary little-endian by default), .stl
  bool msms_header = true;     // MSMS .vert/.face 3-line headers
  // MSMS .vert: the closest atom's name as a 10th column, as MSMS writes when its input
  // names the atoms (MaSIF reads it); only when `atoms` are given and named. Readers that load the
  // rows as a numeric table (PyGBe's numpy.loadtxt) need it off.
  bool msms_atom_names = true;
  // What the surface is, for the first line of the MSMS headers ("# MSMS-format vertices
  // of the DESCRIPTION"), e.g. "solvent accessible surface for 1crn.pdb"; "surface" when empty.
  std::string surface_description;
  // Decimals of MSMS .vert coordinates: 3 is MSMS's own "%9.3f"; kMsmsExact writes each
  // coordinate in the shortest fixed-point text that reads back as the same double.
  // Readers of .vert (MSMS tools, PyGBe, TABI-PB, MaSIF) split on whitespace, so wider
  // columns are read correctly (docs/formats.md).
  int msms_decimals = 3;
  // Every face lies on its atom's sphere (the SAS and vdW surfaces): MSMS normals are then
  // the spheres' own inside a patch. False for the SES, whose toroidal and reentrant faces
  // lie on no atom's sphere: normals are the faces' area-weighted means there too.
  bool faces_on_atom_spheres = true;
  // The solvent-excluded surface's: the arrangement of `atoms`' r + probe_radius spheres
  // (ComputedSurface::ses_arrangement). With it (and `atoms`), MSMS rows carry each vertex's
  // patch type (contact, toroidal, reentrant), closest atom and analytic normal, and each
  // face's type (patch_types.hpp).
  std::shared_ptr<const SphereArrangement> ses_arrangement;
  double probe_radius = 1.4;   // recorded in MSMS headers
  double density = 2.0;        // recorded in MSMS headers
  int threads = 0;             // for the parallel parts (.vtp's compression); 0: OpenMP's default
};

// For MSMS the path may name either file of the pair (or end in .vert); both are written,
// and replace the old pair only when both are complete.
void write_mesh(const std::filesystem::path& path, const Mesh& mesh, const MeshWriteOptions& options = {});

// The files write_mesh() writes for `path`: the .vert/.face pair for MSMS, else `path`.
std::vector<std::filesystem::path> mesh_output_files(const std::filesystem::path& path);

// Whether `format` keeps every coordinate exactly (binary doubles or shortest round-trip
// text): all but STL (float32 by definition) and MSMS at a fixed number of decimals.
bool mesh_format_is_exact(MeshFormat format, const MeshWriteOptions& options = {});

// The mesh that read_mesh() gives back for the file write_mesh() writes: coordinates
// rounded as the format stores them, and for STL, whose facets share no vertices,
// corners with equal float32 coordinates merged into one vertex, in the reader's order.
// Face tags are kept (for reports) even where the format drops them. For an exact
// format this is `mesh` itself. Check this mesh, not `mesh`, before writing a lossy
// format: rounding can make faces degenerate or cross.
Mesh mesh_as_written(const Mesh& mesh, MeshFormat format, const MeshWriteOptions& options = {});

// Reads .stl (ASCII/binary) .off .ply (ASCII/binary) .obj .vtk .vtp (and MSMS .vert/.face),
// and a .pvtp index as the one surface its .vtp pieces make, glued where their open edges'
// vertices are equal doubles (the seams of molsurf --blocks).
// Coincident vertices are not merged except for STL, which has no shared vertices
// (exactly equal coordinates are merged there). Face tags are read back when present.
Mesh read_mesh(const std::filesystem::path& path);

}  // namespace molsurf
