#pragma once
// A polygon face of a mesh file (OFF, OBJ, PLY, VTK, MSMS) as triangles: n - 2 of them,
// covering the polygon as drawn, for concave polygons too. Fanning every polygon from its
// first corner, as readers commonly do, makes an L-shaped face fold over itself, and the
// exact check then calls a valid prism invalid.
#include <span>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf {

// The triangles of the polygon `corners` (indices into `vertices`, in the file's order),
// each with the polygon's orientation. Seen along the axis its normal is closest to, with
// exact orientations: a strictly convex polygon is cut by halving (triangles that shrink
// towards the rim, so that the faces along it meet few of their boxes); one that is not
// convex but star-shaped around its first corner (the fan from it is exactly an
// embedding) is fanned; any other is ear-clipped (boolean_engine::triangulate_polylines). A polygon that is not simple in that projection (it crosses
// itself) gets the fan: its triangles are then whatever the file drew, and the check says so.
std::vector<Triangle> triangulate_polygon(std::span<const Vec3> vertices, std::span<const Index> corners);

}  // namespace molsurf
