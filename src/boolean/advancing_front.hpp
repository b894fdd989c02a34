#pragma once
// Step 3, split (paper §2.3), the general case: a cut face is re-triangulated in its own
// plane by a local advancing front constrained to its intersection segments. The front
// starts as the face's boundary (split at the points on its edges) plus every constraint
// segment in both directions; each step removes one front edge by joining it to the point
// chosen by the Delaunay (Voronoi) criterion among the points that make a valid triangle.
//
// Validity is exact: a triangle is accepted only if, by exact orient2d on the implicit
// points, its apex lies strictly left of the edge, no point lies in the closed triangle
// and its new edges cross no front edge. The Delaunay choice only orders the candidates
// (floating point on the points' approximations), so it affects quality, never validity.
#include <array>
#include <cstdint>
#include <vector>

#include "boolean/face_points.hpp"

namespace molsurf::boolean_engine {

// Triangles (point ids) counter-clockwise in the projection, i.e. oriented as the face.
// `points` holds the face's boundary and interior points. Throws std::logic_error if the
// front cannot advance (a broken precondition).
std::vector<std::array<std::uint32_t, 3>> retriangulate_face(const FaceToSplit& face, const FacePoints& points);

}  // namespace molsurf::boolean_engine
