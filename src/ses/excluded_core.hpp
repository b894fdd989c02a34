#pragma once
// The solvent-accessible solid with every atom's exposed shell taken away: what is left of
// the SAS solid once the probe has been swept over the inside of each exposed face (the
// third family of the probe's sweep; the other two, around arcs and at vertices, are
// probe_sweep.hpp). Each atom's exposed faces, scaled about the atom's centre by
// r_vdW / (r_vdW + probe), become its contact patch on the van der Waals sphere; along every
// seam between two atoms' faces, each side gets a wall in the plane through its atom's
// centre, from the scaled edge up to the seam. The walls of the two atoms meet at the seam:
// a ridge whose part within a probe radius of the seam the probe sweep removes, leaving the
// reentrant fill. Built face by face from the SAS mesh, no Boolean: closed and 2-manifold by
// construction (a vertex where one atom's faces meet only at a point gets one copy per fan).
#include <cstddef>
#include <span>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf::ses_detail {

struct ExcludedCore {
  Mesh mesh;                  // face tags: atom index
  std::size_t wall_faces = 0;
  std::size_t pinched_vertices = 0;  // SAS vertices where one atom's faces form several fans
};

// `sas`: the solvent-accessible surface at probe radius `probe`, its face tags atom indices.
ExcludedCore excluded_core(const Mesh& sas, std::span<const Atom> atoms, double probe);

}  // namespace molsurf::ses_detail
