#pragma once
// Step 2, intersect (paper §2.2.2): what two faces (one of each operand) have in common,
// decided with exact signed volumes (orient3d) on the input doubles and, for points in a
// face's plane, exact orient2d in a coordinate projection. Degenerate contacts (a vertex
// on a face, an edge through an edge, coplanar overlaps, coincident vertices) are found
// as what they are and keyed by the elements they lie on.
#include <array>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "boolean/operands.hpp"
#include "boolean/point_key.hpp"
#include "geometry/predicates.hpp"

namespace molsurf::boolean_engine {

// Where a point lies on one face: at corner `index`, inside edge `index` (from corner
// index to index + 1), or in the interior.
enum class Where : std::uint8_t { corner, edge, interior };
struct Location {
  Where where = Where::interior;
  std::uint8_t index = 0;
};

struct PairPoint {
  PointKey key;
  Location on_a, on_b;
};

struct PairIntersection {
  std::uint32_t face_a = 0, face_b = 0;  // combined indices
  bool coplanar = false;
  bool same_orientation = false;  // coplanar only: the faces' normals agree
  // Not coplanar, and the segment runs through the interiors of both faces (not along an
  // edge of either): the surfaces cross there, so the pieces of either face on the two
  // sides of it lie on opposite sides of the other solid.
  bool transversal = false;
  std::vector<PairPoint> points;  // distinct keys
  // Constraint segments in each face (keys of their end points); they may lie on the
  // face's own boundary. For a non-coplanar pair both lists hold the one segment.
  std::vector<std::pair<PointKey, PointKey>> segments_a, segments_b;
  // Vertex pairs (a's, b's) found at the same position.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> coincident_vertices;

  bool empty() const { return points.empty(); }
};

// Projection of a face onto the coordinate plane (u, v) that drops an axis along which
// its normal is exactly nonzero, oriented so the face is counter-clockwise there.
struct Projection {
  int u = 0, v = 1;
};
Projection face_projection(const Vec3& a, const Vec3& b, const Vec3& c);

// Where a point lies in the closed triangle, from its signs against the triangle's edges
// (s[k] against edge k, from corner k to k + 1): false when one is negative; zeros on edges
// k - 1 and k put it at corner k.
inline bool locate_from_signs(const std::array<int, 3>& s, Location& where) {
  if (s[0] < 0 || s[1] < 0 || s[2] < 0) return false;
  const int zeros = (s[0] == 0) + (s[1] == 0) + (s[2] == 0);
  if (zeros == 0) {
    where = {Where::interior, 0};
  } else if (zeros == 1) {
    where = {Where::edge, static_cast<std::uint8_t>(s[0] == 0 ? 0 : (s[1] == 0 ? 1 : 2))};
  } else if (zeros == 2) {
    // Edges i and i+1 meet at corner i+1.
    const int nonzero = s[0] != 0 ? 0 : (s[1] != 0 ? 1 : 2);
    where = {Where::corner, static_cast<std::uint8_t>((nonzero + 2) % 3)};
  } else {
    throw std::logic_error("boolean: point on all three edges of a face");
  }
  return true;
}

// The crossing of the line through p and q, which lie strictly on opposite sides of the
// plane of triangle t, located in the closed triangle (false: it misses t). Exact, before
// any point is constructed: the line passes each edge on the side orient3d(p, q, edge)
// gives, and meets t iff no two edges see it on opposite sides.
inline bool locate_crossing(const Vec3& p, const Vec3& q, const std::array<Vec3, 3>& t, Location& where) {
  std::array<int, 3> s;
  for (int i = 0; i < 3; ++i) s[i] = geometry::orient3d(p, q, t[i], t[(i + 1) % 3]);
  // Inside iff the three signs agree (or vanish); normalise to "all >= 0".
  if (s[0] < 0 || s[1] < 0 || s[2] < 0)
    for (int& v : s) v = -v;
  return locate_from_signs(s, where);
}

PairIntersection intersect_faces(const Operands& operands, std::uint32_t face_a, std::uint32_t face_b);

}  // namespace molsurf::boolean_engine
