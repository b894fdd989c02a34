#include <gtest/gtest.h>

#include <random>

#include "geometry/implicit_point.hpp"
#include "geometry/predicates.hpp"

namespace molsurf::geometry {
namespace {

bool contains(const Interval& i, const mpq_class& v) { return mpq_class(i.lo) <= v && v <= mpq_class(i.hi); }

TEST(ImplicitPoint, ExplicitPointIsItself) {
  const auto p = ImplicitPoint::explicit_point({1.5, -2, 3});
  EXPECT_TRUE(p.is_explicit());
  EXPECT_EQ(p.rounded(), (Vec3{1.5, -2, 3}));
  EXPECT_EQ(p.exact().y, mpq_class(-2));
}

TEST(ImplicitPoint, LinePlaneCrossingIsExact) {
  // Line from (0,0,-1) to (1,2,2) meets z = 0 at t = 1/3: (1/3, 2/3, 0), not a double.
  const auto p = ImplicitPoint::line_plane({0, 0, -1}, {1, 2, 2}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_FALSE(p.is_explicit());
  const ExactPoint e = p.exact();
  EXPECT_EQ(e.x, mpq_class(1, 3));
  EXPECT_EQ(e.y, mpq_class(2, 3));
  EXPECT_EQ(e.z, mpq_class(0));
  EXPECT_NEAR(p.rounded().x, 1.0 / 3, 1e-16);
}

TEST(ImplicitPoint, IntervalsEncloseTheExactPoint) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-100, 100);
  auto random_point = [&] { return Vec3{coord(rng), coord(rng), coord(rng)}; };
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p = random_point(), q = random_point(), a = random_point(), b = random_point(), c = random_point();
    if (orient3d(a, b, c, p) == orient3d(a, b, c, q)) continue;  // the line must cross the plane
    const auto point = ImplicitPoint::line_plane(p, q, a, b, c);
    const ExactPoint e = point.exact();
    for (int axis = 0; axis < 3; ++axis) {
      ASSERT_TRUE(contains(point.coordinate(axis), e[axis]));
      EXPECT_LT(point.coordinate(axis).hi - point.coordinate(axis).lo, 1e-6);
    }
    EXPECT_EQ(orient3d(a, b, c, point), 0);  // it lies on the plane, exactly
    ++checked;
  }
  EXPECT_GT(checked, 500);
}

// rounded() is the exact coordinate truncated toward zero (mpq_get_d truncates), whichever
// path decides it: line-plane points by a double-double estimate when their differences
// are doubles (the nearby configurations below), the integer form otherwise and wherever
// the estimate lies too close to a double (the crossings that are doubles below).
void expect_truncated_exact(const ImplicitPoint& point) {
  const ExactPoint e = point.exact();
  const Vec3 truncated{mpq_get_d(e.x.get_mpq_t()), mpq_get_d(e.y.get_mpq_t()), mpq_get_d(e.z.get_mpq_t())};
  EXPECT_EQ(point.rounded(), truncated);
}

TEST(ImplicitPoint, RoundedIsTheExactValueTruncated) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> small(-64, 64);
  int checked = 0;
  for (const double scale : {0x1p-10, 1.0, 37.5, 1e4}) {
    auto random_point = [&] { return Vec3{unit(rng), unit(rng), unit(rng)} * scale; };
    // Dyadic offsets of a few bits: sums with them are exact, so the crossing is `m`
    // itself, a double (also exactly 1, 2^k and negative), and truncation must not move it.
    auto dyadic = [&] { return Vec3{small(rng) / 16.0, small(rng) / 16.0, small(rng) / 16.0} * scale; };
    for (int i = 0; i < 400; ++i) {
      const Vec3 p = random_point(), q = random_point(), a = random_point(), b = random_point(), c = random_point();
      if (orient3d(a, b, c, p) * orient3d(a, b, c, q) < 0) {
        expect_truncated_exact(ImplicitPoint::line_plane(p, q, a, b, c));
        ++checked;
      }
      std::array<Vec3, 9> planes;
      for (Vec3& v : planes) v = random_point();
      expect_truncated_exact(ImplicitPoint::three_planes(planes));

      const Vec3 m = i % 4 == 0 ? Vec3{1, -2, 0.5} * scale : Vec3{small(rng) / 8.0, small(rng) / 8.0, 1} * scale;
      const Vec3 u = dyadic(), v = dyadic(), d = dyadic();
      const Vec3 ea = m + u, eb = m + v, ec = m - u - v;
      if (orient3d(ea, eb, ec, m - d) * orient3d(ea, eb, ec, m + d * 3) < 0) {
        const auto point = ImplicitPoint::line_plane(m - d, m + d * 3, ea, eb, ec);
        expect_truncated_exact(point);
        EXPECT_EQ(point.rounded(), m);
        ++checked;
      }
      std::array<Vec3, 9> through_m;
      for (int k = 0; k < 3; ++k) {
        const Vec3 s = dyadic(), t = dyadic();
        through_m[3 * k] = m + s;
        through_m[3 * k + 1] = m + t;
        through_m[3 * k + 2] = m - s - t;
      }
      const Vec3 n0 = cross(through_m[1] - through_m[0], through_m[2] - through_m[0]);
      const Vec3 n1 = cross(through_m[4] - through_m[3], through_m[5] - through_m[3]);
      const Vec3 n2 = cross(through_m[7] - through_m[6], through_m[8] - through_m[6]);
      if (dot(n0, cross(n1, n2)) != 0) {  // exact here: a few bits per coordinate
        const auto point = ImplicitPoint::three_planes(through_m);
        expect_truncated_exact(point);
        EXPECT_EQ(point.rounded(), m);
      }
    }
  }
  // Molecular configurations: nearby points away from zero (their differences are doubles),
  // also with the crossing just off a double by a few units of 2^-60 of it.
  for (int i = 0; i < 4000; ++i) {
    const Vec3 centre{23.7, -31.2, 17.9};
    auto near = [&] { return centre + Vec3{unit(rng), unit(rng), unit(rng)} * 2.0; };
    const Vec3 p = near(), q = near(), a = near(), b = near(), c = near();
    if (orient3d(a, b, c, p) * orient3d(a, b, c, q) < 0) {
      expect_truncated_exact(ImplicitPoint::line_plane(p, q, a, b, c));
      ++checked;
    }
    // A plane tilted by k ulps of m.z, crossed by a vertical segment through m: the crossing
    // is m.z + k ulps / 4, a quarter, a half or a whole ulp off the double m.z.
    const Vec3 m = near();
    const double ulp = std::nextafter(m.z, 100.0) - m.z;
    const double k = small(rng) % 9;
    const Vec3 pa{m.x - 1, m.y - 1, m.z}, pb{m.x + 1, m.y - 1, m.z + k * ulp}, pc{m.x, m.y + 1, m.z};
    const Vec3 below{m.x, m.y, m.z - 0.5}, above{m.x, m.y, m.z + 0.75};
    if (orient3d(pa, pb, pc, below) * orient3d(pa, pb, pc, above) < 0)
      expect_truncated_exact(ImplicitPoint::line_plane(below, above, pa, pb, pc));
  }
  EXPECT_GT(checked, 2500);
}

TEST(ImplicitPoint, RoundedJustBelowADoubleIsTheDoubleBelow) {
  // A vertical line crosses a plane tilted by one ulp of z over a run of 2^80 of its side:
  // some 2^-130 of z off the double z, far beyond a double-double's precision. Truncated,
  // the crossing's z is the double next to z toward zero, or z itself, as the side says.
  for (const double z : {16.0, 17.0, -16.0, -17.0}) {
    const double ulp = std::nextafter(std::fabs(z), 100.0) - std::fabs(z);
    const double side = 0x1p18, run = 0x1p98;  // every difference below is a double
    const Vec3 a{0x1p46, -0x1p46, z}, m{a.x + side, a.y + side, z};
    const Vec3 b{a.x + run, a.y, z - ulp}, c{m.x, m.y + side, z};
    const auto point = ImplicitPoint::line_plane({m.x, m.y, z - 0.5}, {m.x, m.y, z + 0.75}, a, b, c);
    expect_truncated_exact(point);
    const double expected = z > 0 ? std::nextafter(z, 0.0) : z;  // -z - tiny truncates to -z
    EXPECT_EQ(point.rounded().z, expected);
  }
}

TEST(ImplicitPoint, CollinearCrossingsAreExactlyCollinear) {
  // Lines from the origin-ish point (0,0,-1) to (k, 2k, 2) meet z = 0 at (k/3, 2k/3, 0):
  // all on the line y = 2x, none representable as doubles.
  std::vector<ImplicitPoint> points;
  for (double k : {1.0, 5.0, 7.0})
    points.push_back(ImplicitPoint::line_plane({0, 0, -1}, {k, 2 * k, 2}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  EXPECT_EQ(orient2d(points[0], points[1], points[2], 0, 1), 0);
  // A point just off the line is decided, on the correct side.
  const auto off = ImplicitPoint::line_plane({0, 0, -1}, {1, 2.0000000001, 2}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_EQ(orient2d(points[0], points[2], off, 0, 1), 1);
  EXPECT_EQ(orient2d(points[0], off, points[2], 0, 1), -1);
}

TEST(ImplicitPoint, MixedExplicitAndImplicitOrientation) {
  const auto third = ImplicitPoint::line_plane({0, 0, -1}, {1, 2, 2}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const auto origin = ImplicitPoint::explicit_point({0, 0, 0});
  const auto on_line = ImplicitPoint::explicit_point({3, 6, 0});
  const auto left = ImplicitPoint::explicit_point({0, 1, 0});
  EXPECT_EQ(orient2d(origin, on_line, third, 0, 1), 0);
  EXPECT_EQ(orient2d(origin, third, left, 0, 1), 1);
  EXPECT_EQ(orient3d({0, 0, 1}, {1, 0, 1}, {0, 1, 1}, third), -1);  // below z = 1
}

}  // namespace
}  // namespace molsurf::geometry

namespace molsurf::geometry {
namespace {

// Signs and orders are certain only when the intervals exclude zero / each other; a
// touching bound or a NaN leaves them open.
TEST(Interval, CertainSignAndOrder) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(Interval(1, 2).certain_sign(), 1);
  EXPECT_EQ(Interval(-2, -1).certain_sign(), -1);
  EXPECT_EQ(Interval(0, 1).certain_sign(), 0);
  EXPECT_EQ(Interval(-1, 0).certain_sign(), 0);
  EXPECT_EQ(Interval(nan, nan).certain_sign(), 0);
  EXPECT_EQ(certain_order(Interval(1, 2), Interval(3, 4)), -1);
  EXPECT_EQ(certain_order(Interval(3, 4), Interval(1, 2)), 1);
  EXPECT_EQ(certain_order(Interval(1, 3), Interval(3, 4)), 0);  // touching
  EXPECT_EQ(certain_order(Interval(1, 5), Interval(2, 3)), 0);  // nested
  EXPECT_EQ(certain_order(Interval(nan, nan), Interval(1, 2)), 0);
}

TEST(Interval, OutwardRoundingMovesOneOrTwoSteps) {
  const double inf = std::numeric_limits<double>::infinity();
  const double max = std::numeric_limits<double>::max();
  for (double v : {0.0, -0.0, 1.0, -1.0, 1e-310, -1e-310, 3.5e300, -2.2e-16, 0.1, -0.1, 0x1p-1022, -0x1p-1022,
                   max, -max, 1.9999999999999998, -1.9999999999999998}) {
    const double up1 = std::nextafter(v, inf), down1 = std::nextafter(v, -inf);
    EXPECT_GE(interval_detail::up(v), up1) << v;
    EXPECT_LE(interval_detail::up(v), std::nextafter(up1, inf)) << v;
    EXPECT_LE(interval_detail::down(v), down1) << v;
    EXPECT_GE(interval_detail::down(v), std::nextafter(down1, -inf)) << v;
  }
  EXPECT_EQ(interval_detail::up(inf), inf);
  EXPECT_EQ(interval_detail::down(-inf), -inf);
  EXPECT_EQ(interval_detail::up(-inf), -max);
  EXPECT_EQ(interval_detail::down(inf), max);
  EXPECT_TRUE(std::isnan(interval_detail::up(std::nan(""))));
}

}  // namespace
}  // namespace molsurf::geometry
