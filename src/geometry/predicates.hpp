#pragma once
// Exact orientation predicates on input doubles: the foundation of every combinatorial
// decision in molsurf (mesh checking now, the mesh-Boolean engine later).
//
// Each predicate first evaluates its determinant in double precision and compares it
// with a static forward error bound on that evaluation (Shewchuk's "A" bounds, scaled
// by the permanent: the same expression with every term replaced by its magnitude).
// If the double result is farther from zero than the bound, its sign is the exact sign.
// Otherwise the determinant is evaluated exactly, out of line (the hot path stays a dozen
// flops and a branch): in double expansions when no part can underflow or overflow
// (expansion.hpp), else in GMP integers (every finite double is an integer times a power
// of two).
//
// Conventions (note: orient3d is the NEGATION of Shewchuk's orient3d):
//   orient3d(a, b, c, d) = sign det[b-a, c-a, d-a] = sign dot(d-a, (b-a)x(c-a)).
//     +1 when d lies on the side of plane abc that the normal (b-a)x(c-a) points to,
//     i.e. "above" a triangle abc that is counter-clockwise seen from d. For a mesh
//     face abc (counter-clockwise from outside) +1 means d is outside the face's plane.
//   orient2d(a, b, c) = sign of (b-a)x(c-a): +1 when a, b, c turn counter-clockwise
//     (c left of the directed line a->b), -1 clockwise, 0 collinear.
//
// Inputs must be finite. Non-finite inputs do not crash: they return 0 when the filter
// cannot decide (the answer is then meaningless, but defined).
//
// The filter bounds assume every product is rounded (no fused multiply-add), which is
// what GCC does in ISO C++ mode (-std=c++20 implies -ffp-contract=off); a fused
// operation only makes the evaluation more accurate, so the bound stays valid anyway.
// Gradual underflow breaks the relative error model, so a tiny absolute term is added
// to each bound: inputs so small that it matters simply take the exact path.
#include <cmath>

#include "molsurf/vec3.hpp"

namespace molsurf::geometry {

namespace predicates_detail {

inline constexpr double kEpsilon = 0x1p-53;  // half an ulp of 1: the unit roundoff
inline constexpr double kOrient2dBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
inline constexpr double kOrient3dBound = (7.0 + 56.0 * kEpsilon) * kEpsilon;
// Covers the absolute errors of products that fall into the subnormal range (each at
// most 2^-1075, amplified by at most one later multiplication by an input difference).
inline constexpr double kUnderflowGuard = 0x1p-1000;

int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy);
int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace predicates_detail

inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  using namespace predicates_detail;
  const double detleft = (bx - ax) * (cy - ay);
  const double detright = (by - ay) * (cx - ax);
  const double det = detleft - detright;
  const double bound = kOrient2dBound * (std::fabs(detleft) + std::fabs(detright)) + kUnderflowGuard;
  // One branch, taken almost always (the filter rarely fails); the sign itself without one
  // (it is unpredictable). A NaN fails the test and goes to the exact path, as before.
  if (std::fabs(det) > bound) return (det > 0) - (det < 0);
  return orient2d_exact(ax, ay, bx, by, cx, cy);
}

inline int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  using namespace predicates_detail;
  // Shewchuk's layout (differences to d), whose error analysis the bound comes from;
  // det[a-d, b-d, c-d] = -det[b-a, c-a, d-a], hence the negated result below.
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double adz = a.z - d.z, bdz = b.z - d.z, cdz = c.z - d.z;

  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;

  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double abs_adz = std::fabs(adz), abs_bdz = std::fabs(bdz), abs_cdz = std::fabs(cdz);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * abs_adz +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * abs_bdz +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * abs_cdz;
  const double bound = kOrient3dBound * permanent +
                       kUnderflowGuard * (1.0 + abs_adz + abs_bdz + abs_cdz);
  if (std::fabs(det) > bound) return (det < 0) - (det > 0);  // as orient2d's
  // Four points on one axis-aligned plane (a polygon cap of a mesh file, a box's side):
  // a column of the determinant is exactly zero (a difference of doubles is 0 only when
  // they are equal), so the sign is 0 without the exact arithmetic the filter sends it to.
  if ((adz == 0 && bdz == 0 && cdz == 0) || (adx == 0 && bdx == 0 && cdx == 0) || (ady == 0 && bdy == 0 && cdy == 0))
    return 0;
  return orient3d_exact(a, b, c, d);
}

// Sign of the z component of the normal (b-a)x(c-a) of a 3D triangle, and of the x and
// y components: orient2d of the projections onto the (x,y), (y,z) and (z,x) planes.
inline int normal_sign_z(const Vec3& a, const Vec3& b, const Vec3& c) {
  return orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}
inline int normal_sign_x(const Vec3& a, const Vec3& b, const Vec3& c) {
  return orient2d(a.y, a.z, b.y, b.z, c.y, c.z);
}
inline int normal_sign_y(const Vec3& a, const Vec3& b, const Vec3& c) {
  return orient2d(a.z, a.x, b.z, b.x, c.z, c.x);
}

// Exactly collinear (or coincident) points: all three projected orientations vanish.
inline bool collinear3d(const Vec3& a, const Vec3& b, const Vec3& c) {
  return normal_sign_z(a, b, c) == 0 && normal_sign_x(a, b, c) == 0 && normal_sign_y(a, b, c) == 0;
}

}  // namespace molsurf::geometry
