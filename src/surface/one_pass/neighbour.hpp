#pragma once
// A neighbour's polyhedron as the atom being trimmed sees it, and the exact tests the trim
// asks of it: does a face's box reach it, does a line cross one of its faces, is a point
// inside it. The polyhedra are convex and star-shaped from their centres, which is what
// makes each test local.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/implicit_point.hpp"
#include "geometry/predicates.hpp"
#include "molsurf/mesh.hpp"
#include "surface/atom_polyhedra.hpp"

namespace molsurf::surface_detail::one_pass {

inline BoundingBox box_of(const Vec3& a, const Vec3& b, const Vec3& c) {
  BoundingBox box;
  box.extend(a);
  box.extend(b);
  box.extend(c);
  return box;
}

// A neighbour's polyhedron as the trimmed atom sees it: its faces that can reach the
// trimmed atom's boundary (the lens), with their boxes. Vertices are computed when needed,
// by the same expression as everywhere (the same doubles).
struct Neighbour {
  std::uint32_t atom = 0;
  Vec3 centre;
  double scale = 0, inradius = 0, circumradius = 0;
  const PolyhedronTemplate* shape = nullptr;
  std::vector<std::uint32_t> lens;
  std::vector<BoundingBox> lens_boxes;
  // The lens grouped by block of the icosahedron: where each group ends in `lens`, and the
  // box of the group's faces, so a face is tested against the few groups it can reach.
  std::vector<std::uint32_t> group_end;
  std::vector<BoundingBox> group_box;
  bool lens_found = false;  // found on first use: most neighbours only bury faces whole
  BoundingBox box;

  Vec3 vertex(Index v) const { return centre + shape->unit.vertices[v] * scale; }
  std::array<Vec3, 3> face(std::uint32_t g) const {
    const Triangle& t = shape->unit.faces[g];
    return {vertex(t[0]), vertex(t[1]), vertex(t[2])};
  }
};

// The closed box meets the closed ball: a face that misses a neighbour's circumscribed
// ball is outside its polyhedron. The radius is widened far beyond the rounding of the
// distance (relative to the coordinates' size).
inline bool box_meets_ball(const BoundingBox& b, const Vec3& c, double r) {
  double d2 = 0;
  for (int axis = 0; axis < 3; ++axis) {
    // The distance beyond the box on this axis (0 inside it, and for a NaN), without branches.
    const double x = c[axis], e = std::max(0.0, std::max(b.min[axis] - x, x - b.max[axis]));
    d2 += e * e;
  }
  const double reach = r + 1e-9 * (r + std::max({std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)}));
  return d2 <= reach * reach;
}

// x in the closed cone from the centre o over the triangle (a, b, c), counter-clockwise
// seen from outside: o lies strictly inside, so for x in the triangle's plane this is x
// in the closed triangle.
template <class Point>
bool in_cone(const Vec3& o, const std::array<Vec3, 3>& t, const Point& x) {
  for (int k = 0; k < 3; ++k)
    if (geometry::orient3d(o, t[k], t[(k + 1) % 3], x) < 0) return false;
  return true;
}

// Exact: x in the closed polyhedron. The polyhedron is convex and star-shaped from its
// centre, so x is inside iff it is behind the face that the ray from the centre through
// x meets.
bool inside_closed(const geometry::ImplicitPoint& x, const Neighbour& n);

}  // namespace molsurf::surface_detail::one_pass
