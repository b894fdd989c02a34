// The orientation predicates against an independent exact evaluation (GMP rationals
// written here, not the library's), on inputs that fool a plain double evaluation.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "geometry/predicates.hpp"

using molsurf::Vec3;
using molsurf::geometry::orient2d;
using molsurf::geometry::orient3d;

namespace {

// det[b-a, c-a, d-a] by cofactor expansion of the 4x4 homogeneous determinant: a
// different formula from the library's, so a shared mistake is unlikely.
int reference_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 p[4] = {a, b, c, d};
  mpq_class m[4][4];
  for (int r = 0; r < 4; ++r) {
    m[r][0] = p[r].x;
    m[r][1] = p[r].y;
    m[r][2] = p[r].z;
    m[r][3] = 1;
  }
  // Gaussian elimination over the rationals.
  int sign = 1;
  for (int col = 0; col < 4; ++col) {
    int pivot = -1;
    for (int r = col; r < 4; ++r)
      if (sgn(m[r][col]) != 0) {
        pivot = r;
        break;
      }
    if (pivot < 0) return 0;
    if (pivot != col) {
      for (int k = 0; k < 4; ++k) std::swap(m[pivot][k], m[col][k]);
      sign = -sign;
    }
    for (int r = col + 1; r < 4; ++r) {
      const mpq_class factor = m[r][col] / m[col][col];
      for (int k = col; k < 4; ++k) m[r][k] -= factor * m[col][k];
    }
  }
  int det_sign = sign;
  for (int k = 0; k < 4; ++k) det_sign *= sgn(m[k][k]);
  // det[[a,1],[b,1],[c,1],[d,1]] = -det[b-a, c-a, d-a]
  return -det_sign;
}

int reference_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  // ax*by - ay*bx + bx*cy - by*cx + cx*ay - cy*ax: the expanded (shoelace) form.
  const mpq_class det = mpq_class(ax) * by - mpq_class(ay) * bx + mpq_class(bx) * cy - mpq_class(by) * cx +
                        mpq_class(cx) * ay - mpq_class(cy) * ax;
  return sgn(det);
}

int naive_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double det = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  return (det > 0) - (det < 0);
}

int naive_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double det = dot(d - a, cross(b - a, c - a));
  return (det > 0) - (det < 0);
}

}  // namespace

TEST(Predicates, KnownSigns) {
  const Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_EQ(orient3d(o, x, y, z), 1);  // z is on the side of (x-o)x(y-o) = +z
  EXPECT_EQ(orient3d(o, y, x, z), -1);
  EXPECT_EQ(orient3d(o, x, y, -1.0 * z), -1);
  EXPECT_EQ(orient3d(o, x, y, Vec3{0.3, 0.7, 0}), 0);
  EXPECT_EQ(orient2d(0, 0, 1, 0, 0, 1), 1);  // counter-clockwise
  EXPECT_EQ(orient2d(0, 0, 0, 1, 1, 0), -1);
  EXPECT_EQ(orient2d(0, 0, 1, 1, 3, 3), 0);
}

// Shewchuk's classic demonstration: points near the line through (12,12), (24,24),
// displaced by a few ulps around (0.5, 0.5). Rounding makes the naive sign wrong often.
TEST(Predicates, Orient2dNearlyCollinearUlpGrid) {
  int naive_wrong = 0;
  double px = 0.5;
  for (int i = 0; i < 256; ++i, px = std::nextafter(px, 1.0)) {
    double py = 0.5;
    for (int j = 0; j < 256; ++j, py = std::nextafter(py, 1.0)) {
      const int exact = reference_orient2d(px, py, 12, 12, 24, 24);
      ASSERT_EQ(orient2d(px, py, 12, 12, 24, 24), exact) << i << ' ' << j;
      naive_wrong += naive_orient2d(px, py, 12, 12, 24, 24) != exact;
    }
  }
  EXPECT_GT(naive_wrong, 0) << "the inputs should be hard enough to fool plain doubles";
}

TEST(Predicates, Orient3dNearlyCoplanarUlpGrid) {
  const Vec3 a{0.1, 0.2, 0.3}, b{12.7, 11.3, 9.1}, c{24.9, 23.1, 30.7};
  int naive_wrong = 0;
  const Vec3 base = a + 0.37 * (b - a) + 0.29 * (c - a);  // rounded: near the plane, off it by ulps
  double dz = base.z;
  for (int k = -64; k < 64; ++k) {
    dz = base.z;
    for (int s = 0; s < std::abs(k); ++s) dz = std::nextafter(dz, k < 0 ? -1e9 : 1e9);
    double dx = base.x;
    for (int i = 0; i < 16; ++i, dx = std::nextafter(dx, 1e9)) {
      const Vec3 d{dx, base.y, dz};
      const int exact = reference_orient3d(a, b, c, d);
      ASSERT_EQ(orient3d(a, b, c, d), exact) << k << ' ' << i;
      naive_wrong += naive_orient3d(a, b, c, d) != exact;
    }
  }
  EXPECT_GT(naive_wrong, 0);
}

// A small patch far from the origin (a surface's neighbouring faces): the differences of
// its points are doubles, which the exact path takes without the general expansion
// product; near the origin, with coordinates of both signs, they are not.
TEST(Predicates, Orient3dNearlyCoplanarCloseTogether) {
  for (const Vec3 origin : {Vec3{21.5, -33.25, 47.0}, Vec3{0.0, 0.0, 0.0}}) {
    const Vec3 a = origin + Vec3{0.1, 0.2, 0.3}, b = origin + Vec3{1.3, -0.7, 0.4},
               c = origin + Vec3{-0.6, 0.9, 1.1};
    int zeros = 0, positive = 0, negative = 0;
    for (int i = 0; i <= 40; ++i) {
      const double s = 0.025 * i, t = 1 - 0.02 * i;
      Vec3 d = a + s * (b - a) + t * (c - a);  // rounded: on the plane or ulps off it
      for (int k = -3; k <= 3; ++k) {
        Vec3 e = d;
        for (int step = 0; step < std::abs(k); ++step) e.z = std::nextafter(e.z, k < 0 ? -1e9 : 1e9);
        const int exact = reference_orient3d(a, b, c, e);
        ASSERT_EQ(orient3d(a, b, c, e), exact) << i << ' ' << k;
        (exact == 0 ? zeros : exact > 0 ? positive : negative)++;
      }
    }
    EXPECT_GT(positive, 0);
    EXPECT_GT(negative, 0);
  }
  // Exactly coplanar on a dyadic grid (every value representable), then an ulp off.
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> step(-64, 64);
  auto grid_point = [&] { return Vec3{20 + step(rng) / 64.0, 30 + step(rng) / 64.0, 40 + step(rng) / 64.0}; };
  int zeros = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 a = grid_point(), b = grid_point(), c = grid_point();
    const double s = step(rng) / 128.0, t = step(rng) / 128.0;
    Vec3 d = a + s * (b - a) + t * (c - a);
    if (trial % 2) d.y = std::nextafter(d.y, trial % 4 == 1 ? 1e9 : -1e9);
    const int exact = reference_orient3d(a, b, c, d);
    ASSERT_EQ(orient3d(a, b, c, d), exact) << trial;
    zeros += exact == 0;
  }
  EXPECT_GT(zeros, 500);
}

// Offsets of 1e-17 relative: below an ulp for some coordinates, representable for others.
TEST(Predicates, TinyRelativeOffsets) {
  const Vec3 a{1, 1, 1}, b{2, 3, 5}, c{-3, 4, 2};
  for (int k = -10; k <= 10; ++k) {
    const Vec3 d = a + 0.5 * (b - a) + 0.25 * (c - a) + Vec3{k * 1e-17, -k * 3e-17, k * 7e-17};
    EXPECT_EQ(orient3d(a, b, c, d), reference_orient3d(a, b, c, d)) << k;
    const double t = 1e-17 * k;
    EXPECT_EQ(orient2d(1, 1, 1 + t, 1 + 2 * t, 3, 5), reference_orient2d(1, 1, 1 + t, 1 + 2 * t, 3, 5)) << k;
  }
}

// Points a + i * step * (b - a) with step = 0.1: every product is rounded, so most are
// slightly off the line; the predicate must agree with the exact sign, zero included.
TEST(Predicates, NonRepresentableStepsAlongALine) {
  const double ax = 0.3, ay = 0.7, bx = 2.9, by = -1.3;
  int zeros = 0, nonzeros = 0;
  for (int i = 0; i <= 100; ++i) {
    const double t = 0.1 * i;
    const double px = ax + t * (bx - ax), py = ay + t * (by - ay);
    const int exact = reference_orient2d(ax, ay, bx, by, px, py);
    EXPECT_EQ(orient2d(ax, ay, bx, by, px, py), exact) << i;
    (exact == 0 ? zeros : nonzeros)++;
    const Vec3 a{ax, ay, 0.5}, b{bx, by, 1.5}, c{1.0, 1.0, 1.0}, p{px, py, 0.5 + t};
    EXPECT_EQ(orient3d(a, b, c, p), reference_orient3d(a, b, c, p)) << i;
  }
  EXPECT_GT(zeros, 0);
  EXPECT_GT(nonzeros, 0);
}

// Coordinates near 1e15 (ulp 0.125) with unit offsets: huge cancellation.
TEST(Predicates, LargeCoordinatesUnitOffsets) {
  const double big = 1e15;
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> offset(-4, 4);
  for (int trial = 0; trial < 2000; ++trial) {
    Vec3 p[4];
    for (auto& v : p) v = {big + offset(rng), big + offset(rng), big + offset(rng) * 0.125};
    EXPECT_EQ(orient3d(p[0], p[1], p[2], p[3]), reference_orient3d(p[0], p[1], p[2], p[3]));
    EXPECT_EQ(orient2d(p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y),
              reference_orient2d(p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y));
  }
  // Exactly on the plane x + y + z = 3e15 + 3.
  const Vec3 a{big, big + 1, big + 2}, b{big + 3, big, big}, c{big - 1, big + 4, big};
  const Vec3 d{big + 2, big + 2, big - 1};
  EXPECT_EQ(orient3d(a, b, c, d), 0);
  EXPECT_EQ(orient3d(a, b, c, d + Vec3{0, 0, 0.125}), reference_orient3d(a, b, c, d + Vec3{0, 0, 0.125}));
  EXPECT_NE(orient3d(a, b, c, d + Vec3{0, 0, 0.125}), 0);
}

TEST(Predicates, PermutationAntisymmetry) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coord(-10, 10);
  auto random_point = [&] { return Vec3{coord(rng), coord(rng), coord(rng)}; };
  for (int trial = 0; trial < 3000; ++trial) {
    const Vec3 a = random_point(), b = random_point(), c = random_point();
    // Half the time d is nearly coplanar, so the exact path is exercised too.
    const Vec3 d = trial % 2 ? random_point() : a + 0.3 * (b - a) + 0.6 * (c - a);
    const int s = orient3d(a, b, c, d);
    EXPECT_EQ(s, reference_orient3d(a, b, c, d));
    EXPECT_EQ(orient3d(b, a, c, d), -s);
    EXPECT_EQ(orient3d(a, c, b, d), -s);
    EXPECT_EQ(orient3d(b, c, a, d), s);
    EXPECT_EQ(orient3d(d, b, c, a), -s);
    EXPECT_EQ(orient3d(a, b, d, c), -s);
    const int t = orient2d(a.x, a.y, b.x, b.y, d.x, d.y);
    EXPECT_EQ(orient2d(b.x, b.y, a.x, a.y, d.x, d.y), -t);
    EXPECT_EQ(orient2d(b.x, b.y, d.x, d.y, a.x, a.y), t);
  }
}

// Grid-snapped coplanar points (exact dyadic coordinates, d an integer combination of
// a, b, c so exactly on their plane): the answer must be exactly 0, and one ulp off the
// grid it must be the exact nonzero sign.
TEST(Predicates, GridSnappedCoplanarIsExactlyZero) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<long> grid(-(1L << 20), 1L << 20);
  std::uniform_int_distribution<int> small(-5, 5);
  const double scale = 0x1p-30, origin = 1000.0;
  auto grid_point = [&] {
    return Vec3{origin + grid(rng) * scale, origin + grid(rng) * scale, origin + grid(rng) * scale};
  };
  int nonzero_checked = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Vec3 a = grid_point(), b = grid_point(), c = grid_point();
    const int i = small(rng), j = small(rng);
    const Vec3 d = a + double(i) * (b - a) + double(j) * (c - a);  // exact: few bits
    ASSERT_EQ(orient3d(a, b, c, d), 0) << trial;
    ASSERT_EQ(orient3d(d, a, b, c), 0) << trial;
    const Vec3 off{d.x, d.y, std::nextafter(d.z, 1e9)};
    const int exact = reference_orient3d(a, b, c, off);
    ASSERT_EQ(orient3d(a, b, c, off), exact) << trial;
    nonzero_checked += exact != 0;
    // 2D: d on the line ab.
    const double lx = a.x + i * (b.x - a.x), ly = a.y + i * (b.y - a.y);
    ASSERT_EQ(orient2d(a.x, a.y, b.x, b.y, lx, ly), 0) << trial;
  }
  EXPECT_GT(nonzero_checked, 3000);
}

TEST(Predicates, NonFiniteInputsDoNotCrash) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  for (const double bad : {nan, inf, -inf}) {
    const int s3 = orient3d(a, b, c, Vec3{bad, 0, 0});
    EXPECT_TRUE(s3 >= -1 && s3 <= 1);
    const int s2 = orient2d(0, 0, 1, 0, bad, 1);
    EXPECT_TRUE(s2 >= -1 && s2 <= 1);
  }
  // Finite but overflowing products take the exact path and stay correct.
  EXPECT_EQ(orient3d(Vec3{0, 0, 0}, Vec3{1e300, 0, 0}, Vec3{0, 1e300, 0}, Vec3{0, 0, 1e300}), 1);
  EXPECT_EQ(orient2d(0, 0, 1e300, 0, 0, 1e300), 1);
  // Subnormal coordinates: relative error bounds fail there, the guard sends them exact.
  const double tiny = 0x1p-1070;
  EXPECT_EQ(orient2d(0, 0, tiny, 0, 0, tiny), 1);
  EXPECT_EQ(orient3d(Vec3{0, 0, 0}, Vec3{1e-200, 0, 0}, Vec3{0, 1e-200, 0}, Vec3{0, 0, 1e-200}), 1);
}
