// Inline fixed-size integers against GMP's mpz: exact sums, differences and products of
// scaled doubles of every sign and size, overflow reported instead of wrong values, and
// the implicit-point predicates built on them agreeing with their mpz versions.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include "random_doubles.hpp"

#include <cmath>
#include <random>

#include "geometry/exact_integers.hpp"
#include "geometry/implicit_point.hpp"
#include "geometry/predicates.hpp"
#include "geometry/small_integer.hpp"

namespace molsurf::geometry {
namespace {

using molsurf::test::random_double;

mpz_class value_of(const SmallInteger& v) {
  mpz_t storage;
  return mpz_class(v.view(storage));
}


TEST(SmallInteger, ScaledDoublesMatchMpz) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 2000; ++trial) {
    const double v = random_double(rng, -40, 40);
    const int exponent = -100 + static_cast<int>(trial % 7);  // below every ulp in range
    EXPECT_EQ(value_of(SmallInteger::scaled(v, exponent)), scaled_integer(v, exponent));
  }
  EXPECT_EQ(value_of(SmallInteger::scaled(1.0, 0)), 1);
  EXPECT_EQ(value_of(SmallInteger::scaled(-6.0, 1)), -3);
  EXPECT_EQ(SmallInteger::scaled(0.0, 0).sign(), 0);
  EXPECT_TRUE(SmallInteger::scaled(1.5, 0).overflow());  // not a multiple of 2^0
  EXPECT_TRUE(SmallInteger::scaled(1e300, -400).overflow());  // 1397 bits
  EXPECT_TRUE(SmallInteger::scaled(INFINITY, 0).overflow());
}

TEST(SmallInteger, ArithmeticMatchesMpz) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 3000; ++trial) {
    const int exponent = -120;
    const SmallInteger a = SmallInteger::scaled(random_double(rng, -60, 60), exponent);
    const SmallInteger b = SmallInteger::scaled(random_double(rng, -60, 60), exponent);
    const SmallInteger c = SmallInteger::scaled(random_double(rng, -60, 60), exponent);
    const mpz_class ma = value_of(a), mb = value_of(b), mc = value_of(c);
    EXPECT_EQ(value_of(a + b), ma + mb);
    EXPECT_EQ(value_of(a - b), ma - mb);
    EXPECT_EQ(value_of(a - a), 0);
    EXPECT_EQ((a - a).sign(), 0);
    EXPECT_EQ(value_of(-a), -ma);
    const SmallInteger expression = a * b * c - c * (a + b) * b + a;
    ASSERT_FALSE(expression.overflow());
    EXPECT_EQ(value_of(expression), ma * mb * mc - mc * (ma + mb) * mb + ma);
    EXPECT_EQ(expression.sign(), sgn(ma * mb * mc - mc * (ma + mb) * mb + ma));
    EXPECT_EQ(compare(a, b), cmp(ma, mb) > 0 ? 1 : (cmp(ma, mb) < 0 ? -1 : 0));
  }
}

TEST(SmallInteger, CarriesAcrossEveryLimb) {
  // (2^640 - 1) + 1 = 2^640: the carry runs through ten limbs.
  SmallInteger x = SmallInteger::scaled(1.0, 0);
  const SmallInteger two_to_64 = SmallInteger::scaled(std::ldexp(1.0, 64), 0);
  SmallInteger power = x;
  for (int i = 0; i < 10; ++i) power = power * two_to_64;
  const SmallInteger all_ones = power - x;
  EXPECT_EQ(value_of(all_ones + x), value_of(power));
  EXPECT_EQ(value_of(all_ones), (mpz_class(1) << 640) - 1);
}

TEST(SmallInteger, OverflowIsReportedAndSticky) {
  const SmallInteger big = SmallInteger::scaled(std::ldexp(1.0, 1000), 0);  // 16 limbs
  ASSERT_FALSE(big.overflow());
  const SmallInteger product = big * big;  // 32 limbs: more than kLimbs
  EXPECT_TRUE(product.overflow());
  EXPECT_TRUE((product + big).overflow());
  EXPECT_TRUE((big - product).overflow());
}

// The implicit-point predicates: small and mpz forms agree on nearly degenerate triples.
TEST(SmallInteger, ImplicitPointPredicatesAgreeWithMpz) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> coord(-50, 50);
  auto random_point = [&] { return Vec3{coord(rng), coord(rng), coord(rng)}; };
  int compared = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // Three crossings of one plane by lines through a common point: collinear or nearly.
    const Vec3 a = random_point(), b = random_point(), c = random_point();
    const Vec3 apex = random_point(), d1 = random_point(), d2 = random_point();
    const Vec3 far1{apex.x + 2 * (d1.x - apex.x), apex.y + 2 * (d1.y - apex.y), apex.z + 2 * (d1.z - apex.z)};
    const ImplicitPoint p1 = ImplicitPoint::line_plane(apex, d1, a, b, c);
    const ImplicitPoint p2 = ImplicitPoint::line_plane(apex, far1, a, b, c);
    const ImplicitPoint p3 = ImplicitPoint::line_plane(apex, d2, a, b, c);
    if (p1.coordinate(0).hi - p1.coordinate(0).lo > 1e6 || p2.coordinate(0).hi - p2.coordinate(0).lo > 1e6) continue;
    const int e = common_exponent_of({&p1, &p2, &p3});
    const auto s1 = p1.small_homogeneous(e), s2 = p2.small_homogeneous(e), s3 = p3.small_homogeneous(e);
    ASSERT_FALSE(s1.overflow() || s2.overflow() || s3.overflow());
    const auto m1 = p1.homogeneous(e), m2 = p2.homogeneous(e), m3 = p3.homogeneous(e);
    EXPECT_EQ(value_of(s1.x), m1.x);
    EXPECT_EQ(value_of(s2.w), m2.w);
    for (int u = 0; u < 3; ++u)
      for (int v = 0; v < 3; ++v) {
        if (u == v) continue;
        const int small_sign = orient2d_homogeneous(s1, s2, s3, u, v);
        EXPECT_EQ(small_sign, orient2d_homogeneous(m1, m2, m3, u, v));
        EXPECT_EQ(compare_homogeneous(s1, s3, u), compare_homogeneous(m1, m3, u));
        ++compared;
      }
  }
  EXPECT_GT(compared, 1000);
}

// rounded() now divides in SmallInteger: each coordinate must be the exact value
// truncated toward zero to a double (no larger in magnitude, and the next double away
// from zero already too large), at scales from 1e-6 to 1e6.
TEST(SmallInteger, RoundedCoordinatesAreTruncations) {
  std::mt19937_64 rng(41);
  int checked = 0;
  for (const double scale : {1e-6, 1e-2, 1.0, 37.0, 1e6}) {
    std::uniform_real_distribution<double> coord(-scale, scale);
    auto random_point = [&] { return Vec3{coord(rng), coord(rng), coord(rng)}; };
    for (int trial = 0; trial < 300; ++trial) {
      const Vec3 p = random_point(), q = random_point(), a = random_point(), b = random_point(), c = random_point();
      const int sp = orient3d(a, b, c, p), sq = orient3d(a, b, c, q);
      if (sp == 0 || sq == 0 || sp == sq) continue;
      const ImplicitPoint point = ImplicitPoint::line_plane(p, q, a, b, c);
      const Vec3 r = point.rounded();
      const ExactPoint e = point.exact();
      for (int axis = 0; axis < 3; ++axis) {
        const mpq_class exact = e[axis], value(r[axis]);
        ASSERT_LE(abs(value), abs(exact)) << "axis " << axis;
        if (sgn(value) != 0) ASSERT_EQ(sgn(value), sgn(exact));
        const double away = std::nextafter(std::fabs(r[axis]), INFINITY);
        ASSERT_GT(mpq_class(away), abs(exact)) << "axis " << axis;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 500);
}

}  // namespace
}  // namespace molsurf::geometry
