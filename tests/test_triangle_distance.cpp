// The distance from a point to a triangle (src/geometry/triangle_distance.hpp): against a
// dense sampling of the triangle, for points in every Voronoi region of its corners, edges
// and face, and for triangles degenerate to a segment or a point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/triangle_distance.hpp"

namespace molsurf::geometry {
namespace {

// The least distance from p to points of the triangle on a barycentric grid of `n` steps,
// and the grid's spacing bound (every point of the triangle lies within it of a grid point).
double sampled_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int n) {
  double best = HUGE_VAL;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
      best = std::min(best, norm(a + u * (b - a) + v * (c - a) - p));
    }
  return best;
}

double longest_edge(const Vec3& a, const Vec3& b, const Vec3& c) {
  return std::max({norm(b - a), norm(c - b), norm(a - c)});
}

void expect_like_sampling(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int n = 300;
  const double exact = distance_to_triangle(p, a, b, c);
  const double sampled = sampled_distance(p, a, b, c, n);
  const double spacing = longest_edge(a, b, c) / n;
  EXPECT_LE(exact, sampled + 1e-12) << "a sampled point is nearer than the closest point";
  EXPECT_GE(exact, sampled - spacing - 1e-12) << "closer than any point of the triangle";
  // The closest point lies on the triangle: its distance to the triangle is nothing.
  const Vec3 q = closest_point_on_triangle(p, a, b, c);
  EXPECT_NEAR(norm(q - p), exact, 1e-12);
  EXPECT_LE(sampled_distance(q, a, b, c, n), spacing);
}

TEST(TriangleDistance, EveryRegionOfARightTriangle) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  // Beyond each corner, beyond each edge, above the face, and on the triangle itself.
  const Vec3 points[] = {{-1, -1, 0.5}, {2, -0.5, 0}, {-0.3, 2, -1}, {0.5, -1, 0.2}, {1, 1, 0.3},
                         {-1, 0.5, 0},  {0.2, 0.2, 2}, {0.2, 0.2, -3}, {0.25, 0.25, 0}, {0.5, 0, 0}};
  for (const Vec3& p : points) {
    SCOPED_TRACE(testing::Message() << "p = " << p.x << ", " << p.y << ", " << p.z);
    expect_like_sampling(p, a, b, c);
  }
  EXPECT_DOUBLE_EQ(distance_to_triangle({0.2, 0.2, 2}, a, b, c), 2);
  EXPECT_DOUBLE_EQ(distance_to_triangle({2, 0, 0}, a, b, c), 1);
  EXPECT_DOUBLE_EQ(distance_to_triangle({0.25, 0.25, 0}, a, b, c), 0);
}

TEST(TriangleDistance, RandomTrianglesAndPoints) {
  std::mt19937_64 rng(20261128);
  std::uniform_real_distribution<double> coordinate(-3, 3);
  auto point = [&] { return Vec3{coordinate(rng), coordinate(rng), coordinate(rng)}; };
  for (int k = 0; k < 200; ++k) {
    const Vec3 a = point(), b = point(), c = point(), p = point();
    SCOPED_TRACE(k);
    expect_like_sampling(p, a, b, c);
  }
}

// A needle, a segment with a repeated corner, three collinear corners and a point: no
// division by a vanishing area, and the distance of the segment or point they are.
TEST(TriangleDistance, DegenerateTriangles) {
  const Vec3 a{0, 0, 0}, b{2, 0, 0};
  const Vec3 points[] = {{1, 1, 0}, {-1, 0, 0}, {3, 0.5, 0.5}, {0.5, 0, 0}};
  for (const Vec3& p : points) {
    SCOPED_TRACE(testing::Message() << "p = " << p.x << ", " << p.y << ", " << p.z);
    expect_like_sampling(p, a, b, {1, 1e-9, 0});
    expect_like_sampling(p, a, b, b);
    expect_like_sampling(p, a, b, {1, 0, 0});
    expect_like_sampling(p, b, a, {4, 0, 0});
    EXPECT_DOUBLE_EQ(distance_to_triangle(p, a, a, a), norm(p - a));
    const double segment = distance_to_triangle(p, a, b, b);
    EXPECT_TRUE(std::isfinite(segment));
    EXPECT_DOUBLE_EQ(distance_to_triangle(p, a, b, {1, 0, 0}), segment);
  }
  EXPECT_DOUBLE_EQ(distance_to_triangle({1, 1, 0}, a, b, b), 1);
  EXPECT_DOUBLE_EQ(distance_to_triangle({-1, 0, 0}, a, b, {1, 0, 0}), 1);
}

}  // namespace
}  // namespace molsurf::geometry
