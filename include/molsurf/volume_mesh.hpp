#pragma once
// The volume mesh around the molecule (the paper's §3.4): tetrahedra between the surface and
// an outer box, conforming to the surface's triangles, with tagged regions and boundaries,
// for finite-element solvers (FEniCS/dolfinx, FETk). Built with gmsh's library when molsurf
// was built with it (MOLSURF_GMSH; GPL: see LICENSE); otherwise the call throws.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf {

struct VolumeMeshOptions {
  double box_margin = 10;    // angstrom between the surface's bounding box and the outer box
  bool fill_inside = false;  // also the solute region inside the outer surface, each cavity its own region
  double box_size = 0;       // tetrahedron size at the box, angstrom; 0: box_margin / 3 (at least 1)
  // Refuse, before gmsh starts, a mesh whose tetrahedra (at least the box's volume over a
  // regular tetrahedron's of edge box_size) need more memory than this many bytes; 0: the
  // memory this process may use.
  std::uint64_t max_memory = 0;
};

struct VolumeRegion {
  std::string name;            // "solvent", "solute", "cavity-K"
  int physical = 0;            // its physical tag in the file
  std::size_t tetrahedra = 0;
  double volume = 0;           // the sum of its tetrahedra's volumes, angstrom^3
};

struct VolumeMeshReport {
  std::size_t nodes = 0, tetrahedra = 0;
  std::vector<VolumeRegion> regions;
  double min_dihedral_deg = 0;     // smallest dihedral angle of any tetrahedron
  double min_radius_ratio = 0;     // 3 x inradius / circumradius: 1 for the regular tetrahedron
  double median_radius_ratio = 0;
  double box_volume = 0;
  double seconds = 0;
};

// Whether this build can make volume meshes (gmsh's library was found and linked).
bool volume_mesh_available();

struct VolumeMesh {
  VolumeMeshReport report;
  std::string msh;  // the file: gmsh MSH 2.2 ASCII
};

// Meshes the region between a closed, outward surface (as compute_surface gives it: the
// outer surface and its cavities) and an axis-aligned box `box_margin` beyond its bounding
// box: tetrahedra (physical volumes "solvent" = 1, then with fill_inside "solute" = 2 and
// "cavity-K" = 2 + K) and the boundary triangles (physical surfaces "outer" = 1,
// "cavity-K" = 1 + K in the report's order, "box" = C + 1 for C components), as gmsh MSH
// 2.2 ASCII text. The surface's triangles are the boundary as they are: nothing on it is
// remeshed. Throws molsurf::Error when this build has no volume mesher or the mesher
// fails. Not reentrant: gmsh keeps one model per process.
VolumeMesh mesh_volume(const Mesh& surface, const VolumeMeshOptions& options = {});

}  // namespace molsurf
