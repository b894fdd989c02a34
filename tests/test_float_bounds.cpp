// Doubles rounded outward to floats (geometry/float_bounds.hpp): the largest float not
// above, the smallest not below, at every magnitude and at the edges of float's range.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "geometry/float_bounds.hpp"

namespace molsurf::geometry {
namespace {

// The reference: the nearest float, stepped down by nextafterf when it lies above x.
float below_by_nextafter(double x) {
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

TEST(FloatBounds, AgreeWithNextafterAtEveryMagnitude) {
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> mantissa(0.5, 1);
  std::uniform_int_distribution<int> exponent(-160, 130);
  std::vector<double> values{0.0, -0.0, 1.0, -1.0, 0.1, -0.1, 1e-45, -1e-45, 1e-46, -1e-46, 3e-39, -3e-39,
                             static_cast<double>(std::numeric_limits<float>::max()),
                             -static_cast<double>(std::numeric_limits<float>::max()),
                             static_cast<double>(std::numeric_limits<float>::denorm_min())};
  for (int k = 0; k < 200000; ++k) {
    const double x = std::ldexp(mantissa(random), exponent(random));
    values.push_back(k % 2 ? x : -x);
  }
  for (const double x : values) {
    const float below = float_below(x), above = float_above(x);
    ASSERT_EQ(below, below_by_nextafter(x)) << x;
    ASSERT_EQ(above, -below_by_nextafter(-x)) << x;
    ASSERT_LE(static_cast<double>(below), x) << x;
    ASSERT_GE(static_cast<double>(above), x) << x;
    // Adjacent floats, or x itself a float.
    if (below != above) ASSERT_EQ(std::nextafter(below, std::numeric_limits<float>::infinity()), above) << x;
    else ASSERT_EQ(static_cast<double>(below), x) << x;
  }
}

TEST(FloatBounds, OutsideFloatsRangeABoxStillCoversItsPoints) {
  constexpr float kMax = std::numeric_limits<float>::max();
  constexpr float kInf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(float_below(1e300), kMax);
  EXPECT_EQ(float_above(1e300), kInf);
  EXPECT_EQ(float_below(-1e300), -kInf);
  EXPECT_EQ(float_above(-1e300), -kMax);
  EXPECT_EQ(float_below(std::numeric_limits<double>::infinity()), kMax);
  EXPECT_EQ(float_above(-std::numeric_limits<double>::infinity()), -kMax);
  EXPECT_TRUE(std::isnan(float_below(std::nan(""))));
  EXPECT_EQ(float_below(-1e-300), -std::numeric_limits<float>::denorm_min());
  EXPECT_EQ(float_above(1e-300), std::numeric_limits<float>::denorm_min());
}

}  // namespace
}  // namespace molsurf::geometry
