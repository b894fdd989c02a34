// Floating-point expansions against GMP rationals: values are exact, parts stay
// nonoverlapping (so the sign is the largest part's), the range guard refuses what could
// underflow or overflow, and the predicates built on them agree with GMP at and beyond
// the edges of that range.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include "random_doubles.hpp"

#include <cmath>
#include <random>
#include <vector>

#include "geometry/expansion.hpp"
#include "geometry/predicates.hpp"

using molsurf::Vec3;
using molsurf::geometry::Expansion;
using molsurf::geometry::fits_expansion_range;

namespace {

using molsurf::test::random_double;

mpq_class value_of(const Expansion& e) {
  mpq_class sum = 0;
  for (double part : e.parts()) sum += mpq_class(part);
  return sum;
}

// Nonoverlapping, increasing magnitude, no zeros: the lowest set bit of each part lies
// above the highest bit of the one before.
bool well_formed(const Expansion& e) {
  const auto parts = e.parts();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (parts[i] == 0) return false;
    if (i == 0) continue;
    int exponent_below = 0;
    std::frexp(parts[i - 1], &exponent_below);  // |below| < 2^exponent_below
    // The lowest set bit of parts[i]: its value modulo 2^exponent_below must be zero.
    const double scaled = std::ldexp(parts[i], -exponent_below);
    if (scaled != std::trunc(scaled)) return false;
  }
  return true;
}


int reference_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  auto q = [](const Vec3& v) { return std::array<mpq_class, 3>{v.x, v.y, v.z}; };
  const auto qa = q(a), qb = q(b), qc = q(c), qd = q(d);
  mpq_class u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) {
    u[i] = qb[i] - qa[i];
    v[i] = qc[i] - qa[i];
    w[i] = qd[i] - qa[i];
  }
  const mpq_class det = w[0] * (u[1] * v[2] - u[2] * v[1]) + w[1] * (u[2] * v[0] - u[0] * v[2]) +
                        w[2] * (u[0] * v[1] - u[1] * v[0]);
  return sgn(det);
}

}  // namespace

TEST(Expansion, SumsDifferencesAndProductsAreExact) {
  std::mt19937_64 rng(17);
  for (int trial = 0; trial < 2000; ++trial) {
    const double a = random_double(rng, -60, 60), b = random_double(rng, -60, 60);
    const double c = random_double(rng, -60, 60), d = random_double(rng, -60, 60);
    const Expansion ab = Expansion::difference_of(a, b), cd = Expansion::product_of(c, d);
    EXPECT_EQ(value_of(ab), mpq_class(a) - mpq_class(b));
    EXPECT_EQ(value_of(cd), mpq_class(c) * mpq_class(d));
    const Expansion sum = ab + cd, product = ab * cd, scaled = ab.scaled(c);
    ASSERT_TRUE(sum.valid() && product.valid() && scaled.valid());
    EXPECT_EQ(value_of(sum), value_of(ab) + value_of(cd));
    EXPECT_EQ(value_of(product), value_of(ab) * value_of(cd));
    EXPECT_EQ(value_of(scaled), value_of(ab) * mpq_class(c));
    EXPECT_TRUE(well_formed(sum) && well_formed(product) && well_formed(scaled));
    EXPECT_EQ(product.sign(), sgn(value_of(product)));
  }
}

TEST(Expansion, CancellationToZeroAndToTinyRemainders) {
  const double a = 0.1, b = 0x1p-70;
  const Expansion x = Expansion::difference_of(a, b);  // not representable in one double
  EXPECT_EQ(x.size(), 2);
  EXPECT_EQ((x - x).sign(), 0);
  EXPECT_EQ((x - x).size(), 0);
  // (a - b)^2 - a^2 + 2ab = b^2: everything cancels but a part 2^-140.
  const Expansion rest = x * x - Expansion::product_of(a, a) + Expansion::product_of(2 * a, b);
  EXPECT_EQ(value_of(rest), mpq_class(b) * mpq_class(b));
  EXPECT_EQ(rest.sign(), 1);
}

TEST(Expansion, CompressKeepsTheValue) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 500; ++trial) {
    Expansion e;
    for (int k = 0; k < 6; ++k)
      e = e + Expansion::product_of(random_double(rng, -40, 40), random_double(rng, -40, 40));
    const mpq_class before = value_of(e);
    e.compress();
    EXPECT_EQ(value_of(e), before);
    EXPECT_TRUE(well_formed(e));
    EXPECT_EQ(e.sign(), sgn(before));
  }
}

TEST(Expansion, OutgrowingTheCapacityIsReportedNotWrong) {
  // Parts 2^(60k) apart cannot merge: more of them than the capacity.
  Expansion e;
  for (int k = 0; k <= Expansion::kCapacity; ++k) e = e + Expansion(std::ldexp(1.0, 60 * k - 900));
  EXPECT_FALSE(e.valid());
  EXPECT_FALSE((e * Expansion(3.0)).valid());
}

TEST(Expansion, RangeGuard) {
  EXPECT_TRUE(fits_expansion_range(std::vector<double>{1.0, -250.5, 1e-9, 0.0}, 3));
  EXPECT_FALSE(fits_expansion_range(std::vector<double>{1.0, 1e-200}, 3));   // parts could underflow
  EXPECT_FALSE(fits_expansion_range(std::vector<double>{1.0, 1e200}, 3));    // could overflow
  EXPECT_FALSE(fits_expansion_range(std::vector<double>{1.0, NAN}, 3));
  EXPECT_FALSE(fits_expansion_range(std::vector<double>{1.0, INFINITY}, 3));
  // The allowed window narrows with the degree.
  EXPECT_TRUE(fits_expansion_range(std::vector<double>{1e-30}, 3));
  EXPECT_FALSE(fits_expansion_range(std::vector<double>{1e-30}, 11));
}

// Nearly coplanar quadruples at scales inside and outside the expansions' range: the
// predicate must agree with GMP either way (outside, it falls back to GMP).
TEST(Expansion, Orient3dAgreesWithGmpAcrossScales) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (const double scale : {1e-300, 1e-120, 1e-30, 1.0, 1e30, 1e120, 1e290}) {
    int zeros = 0;
    for (int trial = 0; trial < 300; ++trial) {
      const Vec3 a{unit(rng) * scale, unit(rng) * scale, unit(rng) * scale};
      const Vec3 b{unit(rng) * scale, unit(rng) * scale, unit(rng) * scale};
      const Vec3 c{unit(rng) * scale, unit(rng) * scale, unit(rng) * scale};
      // d on the line through a and b (nearly or exactly coplanar with a, b, c).
      const double t = std::ldexp(std::floor(unit(rng) * 64), -5);
      const Vec3 d{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
      const int expected = reference_orient3d(a, b, c, d);
      zeros += expected == 0;
      ASSERT_EQ(molsurf::geometry::orient3d(a, b, c, d), expected) << "scale " << scale << " trial " << trial;
      ASSERT_EQ(molsurf::geometry::predicates_detail::orient3d_exact(a, b, c, d), expected);
    }
    EXPECT_GT(zeros, 0) << "no exactly coplanar case at scale " << scale;
  }
}
