#pragma once
// A computed surface written to a file, the same from every front end (the command line,
// Python's Surface.write): the MSMS header names the surface and its source, the atoms go
// into the cell data, and a lossy format is checked as it will hold the surface.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/written_check.hpp"

namespace molsurf {

// How the file is written (the command's --ascii and --no-header).
struct SurfaceFileOptions {
  bool ascii = false;  // .ply and .stl as text
  // MSMS .vert/.face: the header lines and the atom-name column; without them every row is
  // numbers only, as numpy.loadtxt readers (PyGBe) need.
  bool msms_header = true;
  int msms_decimals = 3;  // kMsmsExact: every coordinate exact
  int threads = 0;        // for the check and the writing; 0: OpenMP's default
};

// What the file records of the surface of `kind` made from `atoms` (read from `source`) with
// `spheres`: e.g. "solvent accessible surface for 1crn.pdb" in the MSMS headers, the probe
// and density there, each face's atom in the cell data.
MeshWriteOptions surface_write_options(SurfaceKind kind, const SphereOptions& spheres, std::span<const Atom> atoms,
                                       const std::filesystem::path& source, const SurfaceFileOptions& file = {});

// The check a surface's file gets: the self-intersection test as the surface had it.
MeshCheckOptions surface_check_options(const ComputedSurface& surface, int threads);

// `surface` checked as `path` will hold it (check_as_written): for .vert the decimals raised
// where 3 would break it (with a note), for .stl an Error if float32 would.
WrittenCheck check_surface_as_written(const std::filesystem::path& path, const ComputedSurface& surface,
                                      const MeshWriteOptions& options);

struct WrittenSurface {
  std::vector<std::filesystem::path> files;  // the .vert/.face pair for MSMS
  std::string note;                          // check_as_written's, empty when there is none
};

// The whole write of one surface file: the path checked (check_output_paths), the surface
// checked as the file will hold it, written to a temporary and put in place.
WrittenSurface write_surface(const std::filesystem::path& path, const ComputedSurface& surface,
                             const MeshWriteOptions& options);

}  // namespace molsurf
