#pragma once
// Random doubles with full 53-bit mantissas over a chosen range of exponents and both
// signs: inputs whose exact sums and products need many bits (exact-arithmetic tests).
#include <cmath>
#include <random>

namespace molsurf::test {

inline double random_double(std::mt19937_64& rng, int min_exponent, int max_exponent) {
  std::uniform_real_distribution<double> mantissa(0.5, 1.0);
  std::uniform_int_distribution<int> exponent(min_exponent, max_exponent);
  std::bernoulli_distribution negative(0.5);
  const double v = std::ldexp(mantissa(rng), exponent(rng));
  return negative(rng) ? -v : v;
}

}  // namespace molsurf::test
