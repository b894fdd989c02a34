#pragma once
// Exact predicates on spheres for the arrangement: each is a polynomial in the input
// doubles (centres, radii), written once as a template and evaluated first in floating
// point with a bound on its rounding error (Approx: the value and its permanent, the same
// polynomial over absolute values; fewer than 100 operations each, so the error is below
// 100 u times the permanent and 1e-11 of it is a bound with a margin of a hundred), then,
// when that bound cannot settle the sign, in rational arithmetic (GMP), which is exact.
//
// On sphere i a neighbour j cuts the cap {y : 2 D_j . y > e_j} (y relative to c_i,
// D_j = c_j - c_i, e_j = |D_j|^2 + r_i^2 - r_j^2): the points of sphere i inside open ball j.
#include <cmath>
#include <cstddef>
#include <gmpxx.h>

#include "molsurf/vec3.hpp"

namespace molsurf::arrangement {

struct Approx {
  double v = 0, m = 0;  // value and permanent
  Approx() = default;
  explicit Approx(double x) : v(x), m(std::fabs(x)) {}
  Approx(double value, double permanent) : v(value), m(permanent) {}
};
inline Approx operator+(const Approx& a, const Approx& b) { return {a.v + b.v, a.m + b.m}; }
inline Approx operator-(const Approx& a, const Approx& b) { return {a.v - b.v, a.m + b.m}; }
inline Approx operator*(const Approx& a, const Approx& b) { return {a.v * b.v, a.m * b.m}; }

template <class T>
struct V3 {
  T x, y, z;
};

// a - b for input doubles: exact in rationals; in floating point one rounding, relative.
template <class T>
V3<T> difference(const Vec3& a, const Vec3& b) {
  if constexpr (std::is_same_v<T, Approx>) {
    return {Approx(a.x - b.x), Approx(a.y - b.y), Approx(a.z - b.z)};
  } else {
    return {T(a.x) - T(b.x), T(a.y) - T(b.y), T(a.z) - T(b.z)};
  }
}
template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
V3<T> combination(const T& a, const V3<T>& u, const T& b, const V3<T>& v) {
  return {a * u.x + b * v.x, a * u.y + b * v.y, a * u.z + b * v.z};
}

// Counts the decisions that needed rational arithmetic (for the statistics).
struct DecisionCounter {
  std::size_t exact = 0;
};

inline int sign_of(const mpq_class& q) { return sgn(q); }

// The sign of the polynomial `f` evaluates (a generic lambda taking the number type as its
// template argument): certain in floating point, else exact.
template <class F>
int exact_sign(F&& f, DecisionCounter& counter) {
  const Approx a = f.template operator()<Approx>();
  if (std::isfinite(a.m) && std::fabs(a.v) > 1e-11 * a.m) return a.v > 0 ? 1 : -1;
  if (std::isfinite(a.m) && a.m == 0) return 0;
  ++counter.exact;
  return sign_of(f.template operator()<mpq_class>());
}

// Whether the closed ball of radius `small` about `a` lies in the closed ball of radius
// `big` about `b`: big >= small and |b - a|^2 <= (big - small)^2, decided exactly on the
// input doubles (floating point settles it when the distance is clearly apart from the
// bound, whose rounding is some 1e-16 of it).
inline bool ball_in_ball(const Vec3& a, double small, const Vec3& b, double big, DecisionCounter& counter) {
  if (big < small) return false;
  const Vec3 gap = b - a;
  if (molsurf::dot(gap, gap) > (big - small) * (big - small) * (1 + 1e-12)) return false;
  return exact_sign([&]<class T>() -> T {
           const auto d = difference<T>(b, a);
           return (T(big) - T(small)) * (T(big) - T(small)) - dot(d, d);
         }, counter) >= 0;
}

// sign(x + y sqrt(z)), z >= 0, exactly.
int sign_plus_root(const mpq_class& x, const mpq_class& y, const mpq_class& z);

// The terms of sphere i's circles j and k (neighbours' caps), from the input doubles.
template <class T>
struct CirclePair {
  V3<T> dj, dk;   // D_j, D_k
  T ej, ek;       // e_j, e_k
  T g;            // |D_j x D_k|^2 = |D_j|^2 |D_k|^2 - (D_j . D_k)^2
  V3<T> y0;       // 2 g times the point of the two planes nearest c_i (in their span)
  T q;            // 4 r_i^2 g^2 - |y0|^2: > 0 when the circles cross at two points
  V3<T> w;        // D_j x D_k
};

template <class T>
T sphere_term(const V3<T>& d, double ri, double rj) {  // e = |D|^2 + r_i^2 - r_j^2
  return dot(d, d) + T(ri) * T(ri) - T(rj) * T(rj);
}

template <class T>
CirclePair<T> circle_pair(const Vec3& ci, double ri, const Vec3& cj, double rj, const Vec3& ck, double rk) {
  CirclePair<T> p;
  p.dj = difference<T>(cj, ci);
  p.dk = difference<T>(ck, ci);
  p.ej = sphere_term(p.dj, ri, rj);
  p.ek = sphere_term(p.dk, ri, rk);
  const T jj = dot(p.dj, p.dj), kk = dot(p.dk, p.dk), jk = dot(p.dj, p.dk);
  p.g = jj * kk - jk * jk;
  const T a = p.ej * kk - p.ek * jk, b = p.ek * jj - p.ej * jk;
  p.y0 = combination(a, p.dj, b, p.dk);
  p.q = T(4) * T(ri) * T(ri) * p.g * p.g - dot(p.y0, p.y0);
  p.w = cross(p.dj, p.dk);
  return p;
}

}  // namespace molsurf::arrangement
