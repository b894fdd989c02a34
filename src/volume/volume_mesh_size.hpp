#pragma once
// What a volume mesh will cost, known before gmsh starts: gmsh cannot be stopped once it
// meshes, and a tetrahedron size of 1e-3 A in a 50 A box asks for some 1e15 tetrahedra.
#include <cstdint>

#include "molsurf/mesh.hpp"

namespace molsurf::volume_detail {

// gmsh's peak memory per tetrahedron with the .msh text, measured on 7cth (4.25 M
// tetrahedra in 4.3 GB; 2hhb's 0.76 M in 1.08 GB includes the surface job), rounded down:
// the estimate below is a lower bound, so the refusal never turns away a mesh that fits.
inline constexpr std::uint64_t kBytesPerTetrahedron = 1000;

// At least this many tetrahedra fill `box` when none is longer than `size`: the box's
// volume over a regular tetrahedron's of edge `size` (size^3 / (6 sqrt 2), the largest
// volume such a tetrahedron can have up to a factor gmsh's shapes do not reach). Near the
// surface the tetrahedra follow its smaller triangles, so the true count is higher
// (1crn at the defaults: 3.6 times this).
double tetrahedra_lower_bound(const BoundingBox& box, double size);

// Throws molsurf::Error when the lower bound's memory is above `max_memory` bytes (0: the
// memory this process may use).
void check_volume_mesh_memory(const BoundingBox& box, double size, std::uint64_t max_memory);

}  // namespace molsurf::volume_detail
