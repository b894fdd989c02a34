#pragma once
// The exact arrangement of any spheres (the types, the tie rules and what they mean:
// include/molsurf/sphere_arrangement.hpp), computed sphere by sphere in parallel
// (sphere_arranger.hpp) and joined into shells (sphere_arrangement.cpp). compute_areas runs
// it on the atoms' spheres; the SES reads its vertices and arcs.
#include <cstdint>
#include <span>
#include <vector>

#include "arrangement/sphere_arranger.hpp"
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

namespace arrangement {

// Steps 1 to 4 (sphere_arranger.hpp) on every sphere `arrange` marks, in parallel; the others'
// results are left empty. `held` marks the spheres inside another's closed ball, or later
// copies (`copy`), which are buried without a look: decided beforehand, on the whole
// structure (sphere_containers), since a holder may lie outside the spheres given here.
// The neighbours are the power diagram's of the spheres given that are neither held nor of
// radius 0: a sphere's exposed part is exact when every ball that overlaps it is given.
std::vector<SphereResult> arrange_each_sphere(std::span<const Vec3> centres, std::span<const double> radii,
                                              std::span<const char> held, std::span<const char> copy,
                                              std::span<const char> arrange);

}  // namespace arrangement

}  // namespace molsurf
