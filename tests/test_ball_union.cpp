#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/ball_union.hpp"

namespace molsurf {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(BallUnion, OneSphere) {
  const std::vector<Vec3> c{{1, -2, 3}};
  const std::vector<double> r{1.7};
  const BallUnionMeasure m = measure_ball_union(c, r, 200);
  EXPECT_NEAR(m.area, 4 * kPi * 1.7 * 1.7, 1e-9);
  EXPECT_NEAR(m.volume, 4.0 / 3 * kPi * std::pow(1.7, 3), 1e-3);  // midpoint rule in z
  const BallUnionMeasure fine = measure_ball_union(c, r, 4000);
  EXPECT_NEAR(fine.volume, 4.0 / 3 * kPi * std::pow(1.7, 3), 1e-6);
}

TEST(BallUnion, TwoOverlappingSpheresMatchTheLensFormula) {
  // Off-axis placement so the slicing direction is not special.
  const double r1 = 1.5, r2 = 1.2, d = 2.0;
  const Vec3 axis = normalized(Vec3{0.3, -0.5, 0.8});
  const std::vector<Vec3> c{{0.1, 0.2, 0.3}, Vec3{0.1, 0.2, 0.3} + axis * d};
  const std::vector<double> r{r1, r2};
  // Caps cut off each sphere: heights from the radical plane.
  const double x = (d * d + r1 * r1 - r2 * r2) / (2 * d);  // distance from c1 to the plane
  const double h1 = r1 - x, h2 = r2 - (d - x);
  const double area = 4 * kPi * (r1 * r1 + r2 * r2) - 2 * kPi * (r1 * h1 + r2 * h2);
  auto cap = [](double rr, double h) { return kPi * h * h * (3 * rr - h) / 3; };
  const double volume = 4.0 / 3 * kPi * (std::pow(r1, 3) + std::pow(r2, 3)) - cap(r1, h1) - cap(r2, h2);
  const BallUnionMeasure m = measure_ball_union(c, r, 4000);
  EXPECT_NEAR(m.area, area, 1e-5 * area);
  EXPECT_NEAR(m.volume, volume, 2e-5 * volume);
  // The midpoint rule in z converges (about as 1/slices at the kinks).
  const BallUnionMeasure coarse = measure_ball_union(c, r, 500), fine = measure_ball_union(c, r, 32000);
  EXPECT_LT(std::abs(fine.volume - volume), std::abs(coarse.volume - volume) / 10);
  EXPECT_NEAR(m.area_per_ball[0], 4 * kPi * r1 * r1 - 2 * kPi * r1 * h1, 1e-5 * area);
}

TEST(BallUnion, NestedAndDuplicateBalls) {
  const std::vector<Vec3> c{{0, 0, 0}, {0.2, 0, 0}, {0, 0, 0}};
  const std::vector<double> r{2.0, 0.5, 2.0};
  const BallUnionMeasure m = measure_ball_union(c, r, 2000);
  EXPECT_NEAR(m.area, 4 * kPi * 4, 1e-6);
  EXPECT_EQ(m.area_per_ball[1], 0);
  EXPECT_EQ(m.area_per_ball[2], 0);  // the duplicate counts once
  EXPECT_NEAR(m.volume, 4.0 / 3 * kPi * 8, 1e-4);
}

TEST(BallUnion, CavityWallsCount) {
  // Six balls around the origin leave a small cavity there; its wall is part of the area
  // and its volume is not part of the union's.
  std::vector<Vec3> c;
  for (double s : {-1.0, 1.0}) {
    c.push_back({s * 1.9, 0, 0});
    c.push_back({0, s * 1.9, 0});
    c.push_back({0, 0, s * 1.9});
  }
  const std::vector<double> r(6, 1.5);
  const BallUnionMeasure coarse = measure_ball_union(c, r, 1000);
  const BallUnionMeasure fine = measure_ball_union(c, r, 4000);
  EXPECT_NEAR(coarse.area, fine.area, 1e-4 * fine.area);  // converged
  EXPECT_NEAR(coarse.volume, fine.volume, 1e-4 * fine.volume);
  EXPECT_LT(fine.volume, 6 * 4.0 / 3 * kPi * std::pow(1.5, 3));
}

}  // namespace
}  // namespace molsurf
