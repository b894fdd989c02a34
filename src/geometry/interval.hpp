#pragma once
// Closed intervals of doubles with outward rounding: the floating-point filter for
// predicates on constructed (implicit) points. Every operation rounds to nearest and then
// widens each bound by one ulp, so the exact real result always lies inside; a sign is
// certain when the interval excludes zero.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>

namespace molsurf::geometry {

struct Interval {
  double lo = 0, hi = 0;

  constexpr Interval() = default;
  constexpr explicit Interval(double v) : lo(v), hi(v) {}
  constexpr Interval(double l, double h) : lo(l), hi(h) {}

  // +1 / -1 when every value in the interval has that sign; 0 when the sign is uncertain
  // (the interval contains zero, or a bound is NaN).
  int certain_sign() const { return (lo > 0) - (hi < 0); }  // no branch: signs are unpredictable
  double mid() const { return 0.5 * (lo + hi); }
};

namespace interval_detail {
// A double at least one and at most two steps above v (what std::nextafter(v, +inf) does,
// with at most one step more, and without branches on the hot path of the filter). Rounding
// to nearest moved the exact result by at most half a step, |v| 2^-53; adding |v| 2^-52
// moves past it. denorm_min covers results that underflowed to or below subnormals.
inline double up(double v) {
  const double w = v + (std::fabs(v) * 0x1p-52 + std::numeric_limits<double>::denorm_min());
  if (w == w) return w;
  return v < 0 ? std::numeric_limits<double>::lowest() : v;  // -inf + inf; NaN stays NaN
}
inline double down(double v) { return -up(-v); }
}  // namespace interval_detail

// -1 / +1 when every value of a lies below / above every value of b; 0 when they overlap
// (or a bound is NaN). Without a branch on the order, which is unpredictable.
inline int certain_order(const Interval& a, const Interval& b) { return (b.hi < a.lo) - (a.hi < b.lo); }

inline Interval operator+(const Interval& a, const Interval& b) {
  return {interval_detail::down(a.lo + b.lo), interval_detail::up(a.hi + b.hi)};
}
inline Interval operator-(const Interval& a, const Interval& b) {
  return {interval_detail::down(a.lo - b.hi), interval_detail::up(a.hi - b.lo)};
}
inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }
inline Interval operator*(const Interval& a, const Interval& b) {
  const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
  return {interval_detail::down(std::min({p1, p2, p3, p4})), interval_detail::up(std::max({p1, p2, p3, p4}))};
}
// Division by an interval that contains zero gives the whole line (the filter then fails).
inline Interval operator/(const Interval& a, const Interval& b) {
  if (b.lo <= 0 && b.hi >= 0) {
    const double inf = std::numeric_limits<double>::infinity();
    return {-inf, inf};
  }
  const double q1 = a.lo / b.lo, q2 = a.lo / b.hi, q3 = a.hi / b.lo, q4 = a.hi / b.hi;
  return {interval_detail::down(std::min({q1, q2, q3, q4})), interval_detail::up(std::max({q1, q2, q3, q4}))};
}

}  // namespace molsurf::geometry
