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
