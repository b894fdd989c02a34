// The exact fallback of the orientation predicates: reached only when the floating-point
// filter in predicates.hpp cannot certify the sign (near-degenerate or exactly degenerate
// inputs). Every finite double is a dyadic rational, so GMP rationals evaluate the
// determinant with no rounding at all.
#include "geometry/predicates.hpp"

#include <gmpxx.h>

#include <cmath>
#include <initializer_list>

namespace molsurf::geometry::predicates_detail {

namespace {

bool all_finite(std::initializer_list<double> values) {
  for (const double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy) {
  // GMP raises SIGFPE when converting an infinity or NaN: refuse them here.
  if (!all_finite({ax, ay, bx, by, cx, cy})) return 0;
  const mpq_class qax(ax), qay(ay);
  const mpq_class ubx = mpq_class(bx) - qax, uby = mpq_class(by) - qay;
  const mpq_class ucx = mpq_class(cx) - qax, ucy = mpq_class(cy) - qay;
  const mpq_class det = ubx * ucy - uby * ucx;
  return sgn(det);
}

int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (!all_finite({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z})) return 0;
  const mpq_class ax(a.x), ay(a.y), az(a.z);
  const mpq_class ux = mpq_class(b.x) - ax, uy = mpq_class(b.y) - ay, uz = mpq_class(b.z) - az;
  const mpq_class vx = mpq_class(c.x) - ax, vy = mpq_class(c.y) - ay, vz = mpq_class(c.z) - az;
  const mpq_class wx = mpq_class(d.x) - ax, wy = mpq_class(d.y) - ay, wz = mpq_class(d.z) - az;
  // det[u, v, w] = w . (u x v)
  const mpq_class det = wx * (uy * vz - uz * vy) + wy * (uz * vx - ux * vz) + wz * (ux * vy - uy * vx);
  return sgn(det);
}

}  // namespace molsurf::geometry::predicates_detail
