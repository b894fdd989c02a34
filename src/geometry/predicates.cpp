// The exact fallback of the orientation predicates: reached only when the floating-point
// filter in predicates.hpp cannot certify the sign (near-degenerate or exactly degenerate
// inputs). First in double expansions, when the range guard allows; otherwise every finite
// double is an integer times a power of two, so scaled to one common exponent the
// determinant is evaluated exactly in GMP integers.
#include "geometry/predicates.hpp"

#include <gmpxx.h>

#include "geometry/exact_integers.hpp"
#include "geometry/expansion.hpp"

#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>

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

namespace {

using expansion_detail::fast_two_sum;
using expansion_detail::two_product;
using expansion_detail::two_sum;

// Expansions in fixed arrays: parts nonoverlapping, increasing in magnitude, no zeros.
template <std::size_t N>
struct Parts {
  std::array<double, N> v;
  int n = 0;
  void push(double x) {
    if (x != 0) v[n++] = x;
  }
};

// a b - c d exactly: at most four parts.
Parts<4> product_difference(double a, double b, double c, double d) {
  double p = 0, pe = 0, q = 0, qe = 0;
  two_product(a, b, p, pe);
  two_product(-c, d, q, qe);
  // Grow-expansion of (pe, p) by qe, then by q (Shewchuk's Two_Two_Sum).
  double s0 = 0, e0 = 0, s1 = 0, e1 = 0, s2 = 0, e2 = 0, s3 = 0, e3 = 0;
  two_sum(pe, qe, s0, e0);    // e0 smallest
  two_sum(p, s0, s1, e1);
  two_sum(e1, q, s2, e2);
  two_sum(s1, s2, s3, e3);
  Parts<4> out;
  out.push(e0);
  out.push(e2);
  out.push(e3);
  out.push(s3);
  return out;
}

// e * b exactly (Scale-Expansion with zero elimination).
template <std::size_t N>
Parts<2 * N> scale_parts(const Parts<N>& e, double b) {
  Parts<2 * N> h;
  if (e.n == 0 || b == 0) return h;
  double q = 0, err = 0;
  two_product(e.v[0], b, q, err);
  h.push(err);
  for (int i = 1; i < e.n; ++i) {
    double high = 0, low = 0, sum = 0;
    two_product(e.v[i], b, high, low);
    two_sum(q, low, sum, err);
    h.push(err);
    fast_two_sum(high, sum, q, err);
    h.push(err);
  }
  h.push(q);
  return h;
}

// e + f exactly (Fast-Expansion-Sum with zero elimination, Shewchuk's merge then sweep).
template <std::size_t N, std::size_t M>
Parts<N + M> sum_parts(const Parts<N>& e, const Parts<M>& f) {
  std::array<double, N + M> merged;
  int m = 0, i = 0, j = 0;
  while (i < e.n && j < f.n) merged[m++] = std::fabs(f.v[j]) > std::fabs(e.v[i]) ? e.v[i++] : f.v[j++];
  while (i < e.n) merged[m++] = e.v[i++];
  while (j < f.n) merged[m++] = f.v[j++];
  Parts<N + M> h;
  if (m == 0) return h;
  double q = merged[0];
  for (int k = 1; k < m; ++k) {
    double s = 0, err = 0;
    two_sum(q, merged[k], s, err);
    h.push(err);
    q = s;
  }
  h.push(q);
  return h;
}

// The common near-degenerate case: points close together, whose nine differences are
// doubles (no rounding: Sterbenz). The determinant w . (u x v) is then three cross terms,
// each a difference of two exact products (four parts), scaled by a double and summed: at
// most 24 parts in fixed arrays. Nothing when a difference is not a double.
std::optional<int> orient3d_of_exact_differences(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  std::array<double, 9> diff;
  const std::array<double, 9> hi{b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  const std::array<double, 3> lo{a.x, a.y, a.z};
  for (int k = 0; k < 9; ++k) {
    double s = 0, err = 0;
    two_sum(hi[k], -lo[k % 3], s, err);
    if (err != 0) return std::nullopt;
    diff[k] = s;
  }
  const double ux = diff[0], uy = diff[1], uz = diff[2], vx = diff[3], vy = diff[4], vz = diff[5];
  const Parts<24> det = sum_parts(sum_parts(scale_parts(product_difference(uy, vz, uz, vy), diff[6]),
                                            scale_parts(product_difference(uz, vx, ux, vz), diff[7])),
                                  scale_parts(product_difference(ux, vy, uy, vx), diff[8]));
  if (det.n == 0) return 0;
  return det.v[det.n - 1] > 0 ? 1 : -1;
}

}  // namespace

int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (!all_finite({a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z})) return 0;
  const double values[] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  if (fits_expansion_range(values, 3)) {
    if (const auto sign = orient3d_of_exact_differences(a, b, c, d)) return *sign;
    const Expansion det = det3(difference(b, a), difference(c, a), difference(d, a));
    if (det.valid()) return det.sign();
  }
  const int e = common_exponent(values);
  if (e == INT_MAX) return 0;
  const IntVec ia = scaled(a, e);
  return sgn(det3(scaled(b, e) - ia, scaled(c, e) - ia, scaled(d, e) - ia));
}

}  // namespace molsurf::geometry::predicates_detail
