#include "mesh/embedded_stars.hpp"

#include <algorithm>
#include <cmath>

#include "common/parallel_exceptions.hpp"
#include "common/parallel_threshold.hpp"
#include "geometry/predicates.hpp"

namespace molsurf {

namespace {

// The axis a star is seen along: the one its summed face normal is most along. Any axis
// is sound (the test is exact); a poor one only leaves the star unproved.
int viewing_axis(const Mesh& mesh, std::span<const std::uint32_t> faces) {
  Vec3 sum;
  for (const std::uint32_t f : faces) {
    const Triangle& t = mesh.faces[f];
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    sum += cross(b - a, c - a);
  }
  const double x = std::fabs(sum.x), y = std::fabs(sum.y), z = std::fabs(sum.z);
  return z >= x && z >= y ? 2 : (x >= y ? 0 : 1);
}

// Along `axis`, the orientation of the projected triangle (geometry::normal_sign_*), and
// a point's second projected coordinate in the same frame: x -> (y, z), y -> (z, x),
// z -> (x, y).
int seen_orientation(const Vec3& a, const Vec3& b, const Vec3& c, int axis) {
  return axis == 0 ? geometry::normal_sign_x(a, b, c)
                   : (axis == 1 ? geometry::normal_sign_y(a, b, c) : geometry::normal_sign_z(a, b, c));
}
double seen_second(const Vec3& p, int axis) { return axis == 0 ? p.z : (axis == 1 ? p.x : p.y); }

bool star_embedded(const Mesh& mesh, Index v, std::span<const std::uint32_t> faces) {
  if (faces.size() < 3) return false;
  const int axis = viewing_axis(mesh, faces);
  const Vec3& centre = mesh.vertices[v];
  const double centre_second = seen_second(centre, axis);
  int turn = 0;
  std::size_t around = 0;
  for (const std::uint32_t f : faces) {
    const Triangle& t = mesh.faces[f];
    const int corner = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
    const Vec3 &from = mesh.vertices[t[(corner + 1) % 3]], &to = mesh.vertices[t[(corner + 2) % 3]];
    // Each face turns the same way around the vertex, by less than half a turn.
    const int sign = seen_orientation(centre, from, to, axis);
    if (sign == 0 || (turn != 0 && sign != turn)) return false;
    turn = sign;
    // The face's wedge, counter-clockwise from a to b, half open [a, b): it holds the
    // direction of the first projected axis iff a lies on or below the vertex's line and
    // b strictly above it (exact comparisons). Consecutive wedges share their boundary
    // rays, so every direction lies in as many wedges as the star winds around.
    const Vec3 &a = turn > 0 ? from : to, &b = turn > 0 ? to : from;
    around += (seen_second(a, axis) <= centre_second) && (seen_second(b, axis) > centre_second);
  }
  return around == 1;
}

}  // namespace

std::vector<std::uint8_t> embedded_stars(const Mesh& mesh, const VertexFaces& around) {
  const auto nv = static_cast<std::int64_t>(around.start.size()) - 1;
  std::vector<std::uint8_t> embedded(static_cast<std::size_t>(std::max<std::int64_t>(nv, 0)), 0);
  ParallelExceptions errors;
#pragma omp parallel for schedule(static) if (nv >= kParallelMinItems)
  for (std::int64_t v = 0; v < nv; ++v)
    errors.run(v, [&] { embedded[v] = star_embedded(mesh, static_cast<Index>(v), around.of(static_cast<Index>(v))); });
  errors.rethrow();
  return embedded;
}

}  // namespace molsurf
