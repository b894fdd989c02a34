#pragma once
// The exact arrangement of any spheres (the types, the tie rules and what they mean:
// include/molsurf/sphere_arrangement.hpp), computed sphere by sphere in parallel
// (sphere_arranger.hpp) and joined into shells (sphere_arrangement.cpp). compute_areas runs
// it on the atoms' spheres; the SES reads its vertices and arcs.
#include <span>

#include "molsurf/sphere_arrangement.hpp"
#include "molsurf/vec3.hpp"

namespace molsurf {

struct ArrangementOptions {
  int threads = 0;  // 0: OpenMP's default
};

// Throws std::invalid_argument when the spans differ in length or a radius or coordinate is
// not finite or a radius is negative. Spheres of radius 0 are buried.
SphereArrangement arrange_spheres(std::span<const Vec3> centres, std::span<const double> radii,
                                  const ArrangementOptions& options = {});

}  // namespace molsurf
