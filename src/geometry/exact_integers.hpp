#pragma once
// Exact evaluation without fractions. Every finite double is m * 2^e with an integer m;
// scaled by one common power of two, all the doubles of a predicate become integers, and
// signs of polynomials in them are evaluated in GMP integers (no gcd, unlike rationals).
// Uniform positive scaling does not change the sign of any homogeneous predicate.
#include <gmpxx.h>

#include <climits>
#include <cmath>
#include <span>

#include "molsurf/vec3.hpp"

namespace molsurf::geometry {

// The exponent e such that every value in `values` is an integer multiple of 2^e
// (INT_MAX when all are zero).
inline int common_exponent(std::span<const double> values) {
  int lowest = INT_MAX;
  for (double v : values) {
    if (v == 0 || !std::isfinite(v)) continue;
    int e = 0;
    std::frexp(v, &e);  // v = f * 2^e, 0.5 <= |f| < 1: the mantissa's last bit is 2^(e - 53)
    lowest = std::min(lowest, e - 53);
  }
  return lowest;
}

// v / 2^exponent, exactly (v must be a multiple of 2^exponent).
inline mpz_class scaled_integer(double v, int exponent) {
  if (v == 0) return 0;
  int e = 0;
  const double f = std::frexp(v, &e);
  mpz_class m(std::ldexp(f, 53));  // exact: 53 significant bits
  const int shift = e - 53 - exponent;
  mpz_mul_2exp(m.get_mpz_t(), m.get_mpz_t(), static_cast<mp_bitcnt_t>(shift));
  return m;
}

struct IntVec {
  mpz_class x, y, z;
  const mpz_class& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

inline IntVec scaled(const Vec3& v, int exponent) {
  return {scaled_integer(v.x, exponent), scaled_integer(v.y, exponent), scaled_integer(v.z, exponent)};
}
inline IntVec operator-(const IntVec& a, const IntVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
// det[u, v, w] = w . (u x v)
inline mpz_class det3(const IntVec& u, const IntVec& v, const IntVec& w) {
  return w.x * (u.y * v.z - u.z * v.y) + w.y * (u.z * v.x - u.x * v.z) + w.z * (u.x * v.y - u.y * v.x);
}

}  // namespace molsurf::geometry
