#pragma once
// What the trim of one atom hands to the join: its kept pieces, on points named by their
// definitions (merged within the atom by exact value), and the counts of where its faces went.
#include <cstddef>
#include <vector>

#include "molsurf/mesh.hpp"
#include "surface/one_pass/point_definition.hpp"

namespace molsurf::surface_detail::one_pass {

struct AtomPieces {
  std::vector<PointDefinition> points;
  std::vector<Vec3> coordinates;  // of points, as written; NaN x: not yet known (left to the join)
  std::size_t implicit_points = 0;
  std::vector<Triangle> triangles;
  std::size_t faces_inside = 0, faces_whole = 0, faces_cut = 0, crossings = 0;
};

}  // namespace molsurf::surface_detail::one_pass
