#pragma once
// Areas and volumes of the true spheres' union, with no mesh: the atoms' spheres
// (r_vdW + probe) -> their exact arrangement (sphere_arrangement.hpp) -> per atom, per
// shell (the outer surface and each cavity) and in total, exact to rounding. The whole of
// `molsurf --areas-only`; compute_surface runs it too, so that the mesh's report carries
// the exact numbers beside the facets' own.
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/sphere_arrangement.hpp"
#include "molsurf/surface.hpp"

namespace molsurf {

struct ComputedAreas {
  SphereArrangement arrangement;  // sphere i is atom i
  double seconds = 0;             // wall time of the arrangement
};

// Throws molsurf::Error for a coordinate that is not finite or a radius that is negative or
// not finite (what the structure readers refuse), ParameterError for a probe out of
// kProbeParameter's range (parameters.hpp).
void check_spheres(std::span<const Atom> atoms, const SphereOptions& spheres);

// Only spheres.probe is read of the sphere options. threads: 0 keeps OpenMP's default.
// Refuses what check_spheres refuses, and threads out of kThreadsParameter's range.
ComputedAreas compute_areas(std::span<const Atom> atoms, const SphereOptions& spheres, int threads = 0);

// Each atom's exact area: all of it, or (outer_only) only what lies on the outer shells.
std::vector<double> exact_atom_area(const SphereArrangement& arrangement, bool outer_only = false);

}  // namespace molsurf

namespace molsurf {

// One frame's numbers: what --areas-only and areas() give for one structure.
struct FrameAreas {
  double area = 0, volume = 0;  // of the cavities too unless outer_only
  std::size_t cavities = 0;
  std::vector<double> atom_area;
  double seconds = 0;  // of the arrangement
};

// Many frames of one job: the models of a file, the frames of a trajectory. Small frames run
// in parallel, one thread each; large ones one after another on all threads. The numbers do
// not depend on `threads` either way. atoms_of(f, atoms) fills frame f's atoms; it is called
// on the thread that computes the frame, once for frame 0 first. A frame's refusal is thrown
// as molsurf::Error prefixed with frame_name(f) (default: "frame F"), the lowest failing
// frame's whatever the thread count.
std::vector<FrameAreas> compute_frame_areas(std::size_t frames,
                                            const std::function<void(std::size_t, std::vector<Atom>&)>& atoms_of,
                                            const SphereOptions& spheres, bool outer_only, int threads = 0,
                                            const std::function<std::string(std::size_t)>& frame_name = {});

}  // namespace molsurf
