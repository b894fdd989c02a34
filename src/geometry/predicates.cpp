// The exact fallback of the orientation predicates: reached only when the floating-point
// filter in predicates.hpp cannot certify the sign (near-degenerate or exactly degenerate
// inputs). First in double expansions, when the range guard allows; otherwise every finite
// double is an integer times a power of two, so scaled to one common exponent the
// determinant is evaluated exactly in GMP integers.
#include "geometry/predicates.hpp"

#include <gmpxx.h>

#include "geometry/exact_integers.hpp"
#include "geometry/expansion.hpp"

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
  // GMP cannot convert an infinity or NaN: refuse them here.
  if (!all_finite({ax, ay, bx, by, cx, cy})) return 0;
  const double values[] = {ax, ay, bx, by, cx, cy};
  if (fits_expansion_range(values, 2)) {
    const Expansion left = Expansion::difference_of(bx, ax) * Expansion::difference_of(cy, ay);
    const Expansion right = Expansion::difference_of(by, ay) * Expansion::difference_of(cx, ax);
    const Expansion det = left - right;
    if (det.valid()) return det.sign();
  }
  const int e = common_exponent(values);
  if (e == INT_MAX) return 0;
  const mpz_class iax = scaled_integer(ax, e), iay = scaled_integer(ay, e);
  const mpz_class det = (scaled_integer(bx, e) - iax) * (scaled_integer(cy, e) - iay) -
                        (scaled_integer(by, e) - iay) * (scaled_integer(cx, e) - iax);
  return sgn(det);
}

int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (!all_finite({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z})) return 0;
  const double values[] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  if (fits_expansion_range(values, 3)) {
    const Expansion det = det3(difference(b, a), difference(c, a), difference(d, a));
    if (det.valid()) return det.sign();
  }
  const int e = common_exponent(values);
  if (e == INT_MAX) return 0;
  const IntVec ia = scaled(a, e);
  return sgn(det3(scaled(b, e) - ia, scaled(c, e) - ia, scaled(d, e) - ia));
}

}  // namespace molsurf::geometry::predicates_detail
