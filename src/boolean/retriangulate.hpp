#pragma once
// Step 3, split (paper §2.3): a cut face is re-triangulated in its own plane by a local
// advancing front constrained to its intersection segments. The front starts as the
// face's boundary (split at the points on its edges) plus every constraint segment in
// both directions; each step removes one front edge by joining it to the point chosen by
// the Delaunay (Voronoi) criterion among the points that make a valid triangle.
//
// Validity is exact: a triangle is accepted only if, by exact orient2d on the implicit
// points, its apex lies strictly left of the edge, no point lies in the closed triangle
// and its new edges cross no front edge. The Delaunay choice only orders the candidates
// (floating point on the points' approximations), so it affects quality, never validity.
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "boolean/intersect.hpp"
#include "geometry/implicit_point.hpp"

namespace molsurf::boolean_engine {

struct FaceToSplit {
  // Boundary points counter-clockwise in the projection: corner 0, the points inside edge
  // 0 in order, corner 1, ... (point ids).
  std::vector<std::uint32_t> boundary;
  std::vector<std::uint32_t> interior;  // points strictly inside the face
  // Constraint segments not on the boundary, with no point strictly inside any of them.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> constraints;
  // Sets of points collinear by construction (the points on one edge of the face, the
  // points on one intersection segment): any three of a set have orient2d = 0, known
  // without arithmetic (their exact evaluation is the expensive case of the filter).
  std::vector<std::vector<std::uint32_t>> collinear_sets;
  Projection projection;
};

// Triangles (point ids) counter-clockwise in the projection, i.e. oriented as the face.
// Throws std::logic_error if the front cannot advance (a broken precondition).
std::vector<std::array<std::uint32_t, 3>> retriangulate_face(const FaceToSplit& face,
                                                             std::span<const geometry::ImplicitPoint> points);

// Sorts `ids` (points strictly inside the segment from -> to) along it, exactly.
void sort_along_segment(std::vector<std::uint32_t>& ids, const Vec3& from, const Vec3& to,
                        std::span<const geometry::ImplicitPoint> points);

// Splits each segment at the points of `candidates` lying strictly inside it (exact
// collinearity in `projection` and betweenness), returning the pieces; each segment's
// points (ends included) are appended to `collinear_sets`.
std::vector<std::pair<std::uint32_t, std::uint32_t>> split_segments_at_points(
    std::span<const std::pair<std::uint32_t, std::uint32_t>> segments, std::span<const std::uint32_t> candidates,
    const Projection& projection, std::span<const geometry::ImplicitPoint> points,
    std::vector<std::vector<std::uint32_t>>& collinear_sets);

}  // namespace molsurf::boolean_engine
