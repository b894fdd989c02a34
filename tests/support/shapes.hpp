#pragma once
// Closed, outward test solids beyond spheres: the engineering shapes of the paper's
// Table I (slabs, capped cylinders, a channel) and rigid transforms to place them.
#include "molsurf/mesh.hpp"

namespace molsurf {

// Box [lo, hi] whose faces are regular grids: nx x ny x nz cells along x, y, z
// (each cell two triangles); vertices shared along the box's edges.
Mesh make_box(const Vec3& lo, const Vec3& hi, int nx = 1, int ny = 1, int nz = 1);

// Latitude-longitude sphere: `slices` around the polar axis (z), `stacks` bands from pole
// to pole; 2 * slices * (stacks - 1) faces (triangle fans at the poles).
Mesh make_uv_sphere(const Vec3& centre, double radius, int slices, int stacks);

// Cylinder of `radius` from `base` along `axis` (any length > 0, the cylinder's length is
// `length`), `segments` around, `rings` bands along the axis, closed by fan caps:
// 2 * segments * (rings + 1) faces.
Mesh make_capped_cylinder(const Vec3& base, const Vec3& axis, double radius, double length, int segments,
                          int rings);

// A square channel: the box [-outer/2, outer/2]^2 x [0, length] with a square duct of side
// `inner` bored along z (a genus-1 solid). `rings` bands along z, `divisions` cells per
// side of each wall.
Mesh make_channel(double outer, double inner, double length, int rings, int divisions);

// Rotation by `angle` radians about `axis` (through the origin), then translation.
struct RigidTransform {
  Vec3 axis{0, 0, 1};
  double angle = 0;
  Vec3 translation{};
  Vec3 apply(const Vec3& p) const;
};
Mesh transformed(const Mesh& mesh, const RigidTransform& transform);

}  // namespace molsurf
