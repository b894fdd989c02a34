#pragma once
// Exact point-in-solid by ray parity. The ray leaves the point along +x, perturbed
// symbolically to (1, e, e^2) with e infinitely small (Simulation of Simplicity), so it
// never meets an edge or a vertex: faces sharing an edge decide the tie the same way and
// the crossing count is exact. The point must not lie on the solid's surface.
#include <cstddef>
#include <cstdint>

#include "geometry/face_bvh.hpp"
#include "geometry/implicit_point.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf::geometry {

// The perturbed ray from x along +x and the triangle abc: it misses the face, crosses it, or
// x lies on the face (then the ray's crossing means nothing).
enum class RayMeets : std::uint8_t { misses, crosses, origin_on_face };
RayMeets ray_meets(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x);

class RayParity {
 public:
  explicit RayParity(const Mesh& solid);
  // Odd number of crossings: inside. Throws std::logic_error if the point is on a face.
  bool inside(const Vec3& point) const;
  bool inside(const ExactPoint& point) const;  // exact rational point (slow path)

 private:
  const Mesh& solid_;
  BoxBvh tree_;
  double max_x_ = 0;
};

}  // namespace molsurf::geometry
