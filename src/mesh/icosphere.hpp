#pragma once
// Geodesic spheres from the icosahedron (class I subdivision at frequency n):
// 20 n^2 faces, 30 n^2 edges, 10 n^2 + 2 shared vertices, closed and outward by construction.
#include <cstdint>

#include "molsurf/mesh.hpp"

namespace molsurf {

struct IcosphereOptions {
  int frequency = 1;
  // Scale the circumradius so that the polyhedron's area equals the sphere's (4 pi r^2)
  // instead of inscribing it (vertices just inside the sphere: icosphere_scale).
  bool area_corrected = false;
  std::int32_t tag = kNoTag;  // given to every face
};

Mesh make_icosphere(const Vec3& centre, double radius, const IcosphereOptions& options);

// The icosphere on the unit sphere at the origin (corners of length 1 within a few ulps),
// which make_icosphere scales.
Mesh make_unit_icosphere(int frequency);

// The factor that maps the unit icosphere (area `unit_area`) onto a sphere: area-corrected,
// or inscribed. An inscribed polyhedron's vertices lie strictly inside the sphere, rounding
// included (radius less 2^-30 of itself and 2^-48 of the centre's largest coordinate, far
// more than the unit vertices' few ulps and the rounding of centre + u * scale): so the
// polyhedra of two exactly tangent spheres never touch, as the open balls they stand for do
// not. Tangent spheres are separate shells, as in the sphere arrangement.
double icosphere_scale(const Vec3& centre, double radius, double unit_area, bool area_corrected);

// The frequency whose vertex count (10 n^2 + 2) is closest to `density` vertices per
// square angstrom of the sphere's area (MSMS's convention); at least 1.
int frequency_for_density(double radius, double density);

}  // namespace molsurf
