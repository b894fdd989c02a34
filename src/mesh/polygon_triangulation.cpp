#include "mesh/polygon_triangulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>

#include "boolean/ear_clipping.hpp"
#include "boolean/face_points.hpp"
#include "geometry/implicit_point.hpp"
#include "geometry/predicates.hpp"

namespace molsurf {

namespace {

std::vector<Triangle> fan(std::span<const Index> corners) {
  std::vector<Triangle> triangles;
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) triangles.push_back({corners[0], corners[i], corners[i + 1]});
  return triangles;
}

// The plane to project on: the two axes other than the one the polygon's normal (Newell's,
// approximate: any axis that shows the polygon without folding it will do) is closest to,
// in the cyclic order that keeps the polygon's turning; `flipped` when seen from behind.
struct Plane {
  boolean_engine::Projection projection;
  bool flipped = false;
};

Plane projection_plane(std::span<const Vec3> vertices, std::span<const Index> corners) {
  Vec3 normal{0, 0, 0};
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3& p = vertices[corners[i]];
    const Vec3& q = vertices[corners[(i + 1) % corners.size()]];
    normal.x += (p.y - q.y) * (p.z + q.z);
    normal.y += (p.z - q.z) * (p.x + q.x);
    normal.z += (p.x - q.x) * (p.y + q.y);
  }
  const double n[3] = {normal.x, normal.y, normal.z};
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(n[k]) > std::fabs(n[axis])) axis = k;
  return {{(axis + 1) % 3, (axis + 2) % 3}, n[axis] < 0};
}

// The fan from corner 0 is an embedding when, in the projection, every fan triangle turns
// the same way (strictly) and every corner lies strictly on that side of corner 0 -> 1:
// the corners then advance around corner 0 within less than half a turn.
bool fan_embeds(std::span<const Vec3> vertices, std::span<const Index> corners, boolean_engine::Projection p) {
  auto orient = [&](Index a, Index b, Index c) {
    const Vec3 &x = vertices[a], &y = vertices[b], &z = vertices[c];
    return geometry::orient2d(x[p.u], x[p.v], y[p.u], y[p.v], z[p.u], z[p.v]);
  };
  const int side = orient(corners[0], corners[1], corners[2]);
  if (side == 0) return false;
  for (std::size_t i = 2; i + 1 < corners.size(); ++i)
    if (orient(corners[0], corners[i], corners[i + 1]) != side || orient(corners[0], corners[1], corners[i + 1]) != side)
      return false;
  return true;
}

// Whether every corner turns strictly the same way as the fan does (`fan_embeds` holds
// already): the polygon is then convex, and any of its diagonals cut it.
bool strictly_convex(std::span<const Vec3> vertices, std::span<const Index> corners, boolean_engine::Projection p) {
  const std::size_t n = corners.size();
  auto orient = [&](Index a, Index b, Index c) {
    const Vec3 &x = vertices[a], &y = vertices[b], &z = vertices[c];
    return geometry::orient2d(x[p.u], x[p.v], y[p.u], y[p.v], z[p.u], z[p.v]);
  };
  const int side = orient(corners[n - 1], corners[0], corners[1]);
  for (std::size_t i = 1; i < n; ++i)
    if (orient(corners[i - 1], corners[i], corners[(i + 1) % n]) != side) return false;
  return side != 0;
}

// A convex polygon cut by halving: the triangle (first, middle, last) of a chain, then each
// half. Its triangles shrink towards the boundary, so a boundary edge's box meets O(log n)
// of them; a fan's n long slivers would each reach across the polygon, and the faces
// along the rim (a prism's sides) would meet the boxes of half of them.
void halve(std::span<const Index> corners, std::size_t first, std::size_t last, std::vector<Triangle>& out) {
  if (last - first < 2) return;
  const std::size_t middle = first + (last - first) / 2;
  out.push_back({corners[first], corners[middle], corners[last]});
  halve(corners, first, middle, out);
  halve(corners, middle, last, out);
}

std::vector<Triangle> balanced(std::span<const Index> corners) {
  const std::size_t n = corners.size(), a = n / 3, b = 2 * n / 3;
  std::vector<Triangle> triangles{{corners[0], corners[a], corners[b]}};
  halve(corners, 0, a, triangles);
  halve(corners, a, b, triangles);
  std::vector<Index> closing(corners.begin() + static_cast<std::ptrdiff_t>(b), corners.end());
  closing.push_back(corners[0]);
  halve(closing, 0, closing.size() - 1, triangles);
  return triangles;
}

}  // namespace

std::vector<Triangle> triangulate_polygon(std::span<const Vec3> vertices, std::span<const Index> corners) {
  if (corners.size() <= 3) return fan(corners);
  const Plane plane = projection_plane(vertices, corners);
  if (fan_embeds(vertices, corners, plane.projection))
    return corners.size() > 4 && strictly_convex(vertices, corners, plane.projection) ? balanced(corners)
                                                                                      : fan(corners);
  // Ear clipping takes the boundary counter-clockwise in the projection.
  const std::size_t n = corners.size();
  std::vector<geometry::ImplicitPoint> points;
  points.reserve(n);
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  if (plane.flipped) std::reverse(order.begin(), order.end());
  for (const std::uint32_t k : order) points.push_back(geometry::ImplicitPoint::explicit_point(vertices[corners[k]]));
  boolean_engine::FaceToSplit face;
  face.boundary.resize(n);
  std::iota(face.boundary.begin(), face.boundary.end(), 0u);
  face.projection = plane.projection;
  const boolean_engine::FacePoints face_points(face.boundary, points, plane.projection);
  const auto clipped = boolean_engine::triangulate_polylines(face, face_points);
  if (!clipped || clipped->size() != n - 2) return fan(corners);
  std::vector<Triangle> triangles;
  triangles.reserve(n - 2);
  for (const auto& t : *clipped) {
    Triangle triangle{corners[order[t[0]]], corners[order[t[1]]], corners[order[t[2]]]};
    if (plane.flipped) std::swap(triangle[1], triangle[2]);
    triangles.push_back(triangle);
  }
  return triangles;
}

}  // namespace molsurf
