#pragma once
// Doubles to floats rounded outward, for boxes kept in single precision that only reject
// (the face tree's, the cleanup's face index's): every double box lies inside its float box.
#include <cmath>
#include <limits>

namespace molsurf::geometry {

// The largest float not above x (outside float's range: the largest float or minus
// infinity, so a huge box still covers everything it must).
inline float float_below(double x) {
  if (!(x <= std::numeric_limits<float>::max())) return x > 0 ? std::numeric_limits<float>::max() : static_cast<float>(x);
  if (x < -static_cast<double>(std::numeric_limits<float>::max())) return -std::numeric_limits<float>::infinity();
  const auto f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

// The smallest float not below x.
inline float float_above(double x) { return -float_below(-x); }

}  // namespace molsurf::geometry
