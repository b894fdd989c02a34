#pragma once
// Step 3, split (paper §2.3), the common cases: a cut face is cut along its constraints
// into simple polygons, and each is ear-clipped. When a face has another shape, the
// caller falls back to the advancing front (advancing_front.hpp).
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "boolean/face_points.hpp"

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
  std::vector<std::uint32_t> piece_ids;
};
// Asked of each piece before it is clipped, with the point ids of its corners in order:
// false leaves the piece out of the result untriangulated (the one-pass union drops the
// pieces that lie inside a neighbour). Empty: every piece is wanted. Whether the pieces
// make a whole triangulation is checked on all of them either way.
using PieceWanted = std::function<bool(std::span<const std::uint32_t> corner_ids)>;
std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulate_polylines(const FaceToSplit& face,
                                                                                const FacePoints& points,
                                                                                PolylineWork& work,
                                                                                const PieceWanted& wanted = {});

}  // namespace molsurf::boolean_engine
