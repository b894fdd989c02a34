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
#include <optional>
#include <unordered_map>
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

// The points of one face with exact predicates in its projection: the interval filter
// first, then integer homogeneous coordinates at one exponent for the whole face (inline
// fixed-size integers, GMP's mpz when those overflow), each built once (points are shared
// by several predicates, and their exact form is costly).
class FacePoints {
 public:
  FacePoints(std::vector<std::uint32_t> ids, std::span<const geometry::ImplicitPoint> all, Projection projection);
  const std::vector<std::uint32_t>& ids() const { return ids_; }
  int local(std::uint32_t id) const;
  const geometry::ImplicitPoint& point(int i) const { return all_[ids_[i]]; }
  const Projection& projection() const { return projection_; }
  int orient(int a, int b, int c) const;       // local indices
  int compare(int a, int b, int axis) const;   // exact order of one coordinate

 private:
  int exponent() const;
  const geometry::SmallHomogeneousPoint& small(int i) const;  // may have overflowed
  const geometry::HomogeneousPoint& exact(int i) const;

  std::vector<std::uint32_t> ids_;
  std::span<const geometry::ImplicitPoint> all_;
  Projection projection_;
  std::vector<std::pair<std::uint32_t, int>> local_;  // (id, local index), sorted
  mutable std::vector<std::optional<geometry::SmallHomogeneousPoint>> small_;
  mutable std::vector<std::optional<geometry::HomogeneousPoint>> exact_;
  mutable int exponent_;
};

// Triangles (point ids) counter-clockwise in the projection, i.e. oriented as the face.
// `points` holds the face's boundary and interior points. Throws std::logic_error if the
// front cannot advance (a broken precondition).
std::vector<std::array<std::uint32_t, 3>> retriangulate_face(const FaceToSplit& face, const FacePoints& points);

// Sorts `ids` (points strictly inside the segment from -> to) along it, exactly.
void sort_along_segment(std::vector<std::uint32_t>& ids, const Vec3& from, const Vec3& to,
                        std::span<const geometry::ImplicitPoint> points);

// Splits each segment at the face's points lying strictly inside it (exact
// collinearity in `projection` and betweenness), returning the pieces; each segment's
// points (ends included) are appended to `collinear_sets`. `known_inside` (empty, or one
// list per segment) names points the caller built strictly inside a segment (where two
// traces cross): they are taken without a test, whose exact zero is the filter's costly case.
std::vector<std::pair<std::uint32_t, std::uint32_t>> split_segments_at_points(
    std::span<const std::pair<std::uint32_t, std::uint32_t>> segments, const FacePoints& points,
    std::vector<std::vector<std::uint32_t>>& collinear_sets,
    std::span<const std::vector<std::uint32_t>> known_inside = {});

}  // namespace molsurf::boolean_engine

namespace molsurf::boolean_engine {

// The common case, without a single predicate: a face with no point in its interior. Its
// constraints are then chords between boundary points that do not cross (a crossing would
// be an interior point), so they cut the face into convex pieces, and three boundary
// points are collinear exactly when one edge of the face holds all three. Each piece is
// ear-clipped, collinearity decided from `edge_runs` (each edge's points, corners
// included), the ear with the largest smallest angle first (approximate: quality only).
// Counter-clockwise in the projection like the face; nullopt if a piece cannot be
// clipped (the caller then uses the advancing front).
std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulate_chords(
    std::span<const std::uint32_t> boundary, std::span<const std::vector<std::uint32_t>> edge_runs,
    std::span<const std::pair<std::uint32_t, std::uint32_t>> chords, std::span<const geometry::ImplicitPoint> points,
    Projection projection);

}  // namespace molsurf::boolean_engine

namespace molsurf::boolean_engine {

// The next most common case: the constraints and the face's boundary form one connected
// planar graph (disjoint polylines from boundary to boundary, or traces that cross at
// interior points). Its pieces are found by walking the graph with each piece on the left,
// the edges around every point of degree three or more in exact angular order; each piece
// must be a simple polygon. Each is ear-clipped with exact orientations (an ear: a
// strictly convex corner whose closed triangle holds no other corner of the polygon), the
// ear with the largest smallest angle first (approximate: quality only).
// nullopt when the constraints have another shape (a loose end, a loop apart from the
// rest, a piece that meets a point twice), or no ear is found, or the best ear has an
// angle under 0.1 degree (the caller then uses the advancing front, whose Delaunay choice
// handles nearly collinear points better).
std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulate_polylines(const FaceToSplit& face,
                                                                                const FacePoints& points);

// Its buffers, kept by a caller that splits many faces: no allocation in the steady state
// (allocation was a tenth of the one-pass trim's cost of this step).
struct PolylineWork {
  std::vector<int> local_boundary, boundary_position;
  std::vector<std::uint64_t> lines;
  std::vector<std::int8_t> memo;
  std::vector<std::vector<int>> around, pieces;
  std::vector<std::vector<std::uint8_t>> walked;
  std::vector<std::uint8_t> in_piece, state;
  std::vector<std::array<double, 2>> at;
  std::vector<std::array<double, 4>> box;
  std::vector<int> prev, next;
  std::vector<double> score;
};
std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulate_polylines(const FaceToSplit& face,
                                                                                const FacePoints& points,
                                                                                PolylineWork& work);

}  // namespace molsurf::boolean_engine
