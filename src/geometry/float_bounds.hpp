#pragma once
// Doubles to floats rounded outward, for boxes kept in single precision that only reject
// (the face tree's, the cleanup's face index's): every double box lies inside its float box.
#include <bit>
#include <cstdint>
#include <limits>

namespace molsurf::geometry {

// The largest float not above x (outside float's range: the largest float or minus
// infinity, so a huge box still covers everything it must). The step down is taken on the
// float's bits: libm's nextafterf, a call, cost a fifth of building the face index.
inline float float_below(double x) {
  constexpr float kMax = std::numeric_limits<float>::max();
  if (!(x <= kMax)) return x > 0 ? kMax : static_cast<float>(x);  // above the range, or NaN
  if (x < -static_cast<double>(kMax)) return -std::numeric_limits<float>::infinity();
  const auto f = static_cast<float>(x);
  if (static_cast<double>(f) <= x) return f;
  // f > x: the float next to f toward minus infinity.
  if (f > 0) return std::bit_cast<float>(std::bit_cast<std::uint32_t>(f) - 1);
  if (f < 0) return std::bit_cast<float>(std::bit_cast<std::uint32_t>(f) + 1);
  return -std::numeric_limits<float>::denorm_min();
}

// The smallest float not below x.
inline float float_above(double x) { return -float_below(-x); }

}  // namespace molsurf::geometry
