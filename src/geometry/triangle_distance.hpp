#pragma once
// The distance from a point to a triangle (its closest point on the closed triangle), in
// floating point. For filters that decide which faces to keep in view, never for a
// combinatorial decision about the surface: a caller adds a margin far above the rounding
// (a few units in the last place of the coordinates) and keeps a face when in doubt.
#include "molsurf/vec3.hpp"

namespace molsurf::geometry {

// The point of triangle (a, b, c) closest to p; a degenerate triangle is treated as the
// segment or point it is.
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace molsurf::geometry
