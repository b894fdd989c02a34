#pragma once
// Areas and volumes of the true spheres' union, with no mesh: the atoms' spheres
// (r_vdW + probe) -> their exact arrangement (sphere_arrangement.hpp) -> per atom, per
// shell (the outer surface and each cavity) and in total, exact to rounding. The whole of
// `molsurf --areas-only`; compute_surface runs it too, so that the mesh's report carries
// the exact numbers beside the facets' own.
#include <span>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/sphere_arrangement.hpp"
#include "molsurf/surface.hpp"

namespace molsurf {

struct ComputedAreas {
  SphereArrangement arrangement;  // sphere i is atom i
  double seconds = 0;             // wall time of the arrangement
};

// Throws molsurf::Error for a coordinate that is not finite, a radius that is negative or
// not finite, or such a probe (what the structure readers refuse).
void check_spheres(std::span<const Atom> atoms, const SphereOptions& spheres);

// Only spheres.probe is read of the sphere options. threads: 0 keeps OpenMP's default.
// Refuses what check_spheres refuses.
ComputedAreas compute_areas(std::span<const Atom> atoms, const SphereOptions& spheres, int threads = 0);

// Each atom's exact area: all of it, or (outer_only) only what lies on the outer shells.
std::vector<double> exact_atom_area(const SphereArrangement& arrangement, bool outer_only = false);

}  // namespace molsurf
