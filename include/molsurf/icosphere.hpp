#pragma once
// Geodesic spheres from the icosahedron (class I subdivision at frequency n):
// 20 n^2 faces, 30 n^2 edges, 10 n^2 + 2 shared vertices, closed and outward by construction.
#include <cstdint>

#include "molsurf/mesh.hpp"

namespace molsurf {

struct IcosphereOptions {
  int frequency = 1;
  // Scale the circumradius so that the polyhedron's area equals the sphere's (4 pi r^2)
  // instead of inscribing it (vertices on the sphere).
  bool area_corrected = false;
  std::int32_t tag = kNoTag;  // given to every face
};

Mesh make_icosphere(const Vec3& centre, double radius, const IcosphereOptions& options);

// The frequency whose vertex count (10 n^2 + 2) is closest to `density` vertices per
// square angstrom of the sphere's area (MSMS's convention); at least 1.
int frequency_for_density(double radius, double density);

}  // namespace molsurf
