#pragma once
// Double-double numbers: an unevaluated sum hi + lo with |lo| <= ulp(hi) / 2, about 106
// significant bits (Dekker 1971). The filter of the exact rounding of implicit points: an
// estimate this close to the exact value, with a bound on its error, decides the rounded
// double except where the value lies within the bound of a double. Each operation below
// errs by at most a few units of 2^-104 of the magnitudes it combines.
#include "geometry/expansion.hpp"

namespace molsurf::geometry {

struct DoubleDouble {
  double hi = 0, lo = 0;
};

inline DoubleDouble normalized(double hi, double lo) {
  DoubleDouble r;
  expansion_detail::two_sum(hi, lo, r.hi, r.lo);
  return r;
}

// a b - c d: the two exact products' difference, rounded once.
inline DoubleDouble product_difference_dd(double a, double b, double c, double d) {
  double p = 0, pe = 0, q = 0, qe = 0, s = 0, se = 0;
  expansion_detail::two_product(a, b, p, pe);
  expansion_detail::two_product(c, d, q, qe);
  expansion_detail::two_sum(p, -q, s, se);
  return normalized(s, se + (pe - qe));
}

inline DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b) {
  double s = 0, e = 0;
  expansion_detail::two_sum(a.hi, b.hi, s, e);
  return normalized(s, e + (a.lo + b.lo));
}

inline DoubleDouble operator-(const DoubleDouble& a) { return {-a.hi, -a.lo}; }
inline DoubleDouble operator-(const DoubleDouble& a, const DoubleDouble& b) { return a + (-b); }

inline DoubleDouble operator*(const DoubleDouble& a, double b) {
  double p = 0, e = 0;
  expansion_detail::two_product(a.hi, b, p, e);
  return normalized(p, e + a.lo * b);
}

inline DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b) {
  double p = 0, e = 0;
  expansion_detail::two_product(a.hi, b.hi, p, e);
  return normalized(p, e + (a.hi * b.lo + a.lo * b.hi));
}

inline DoubleDouble operator/(const DoubleDouble& a, const DoubleDouble& b) {
  const double q1 = a.hi / b.hi;
  double p = 0, e = 0;
  expansion_detail::two_product(q1, b.hi, p, e);
  const double remainder = (((a.hi - p) - e) + a.lo) - q1 * b.lo;
  return normalized(q1, remainder / b.hi);
}

}  // namespace molsurf::geometry
