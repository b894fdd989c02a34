#pragma once
// Exact arithmetic on floating-point expansions (Priest 1991; Shewchuk 1997): a value is
// an unevaluated sum of doubles that do not overlap, in increasing magnitude, so the sign
// of the sum is the sign of its largest part. Sums and products are exact as long as no
// product underflows or overflows, which `fits_expansion_range` guarantees beforehand.
//
// Why not only GMP: the exact path of our predicates runs on nearly degenerate inputs,
// and those are common by construction (a flat surface rotated by a rounded angle, points
// along a cut that is straight up to rounding). GMP pays an allocation and a call per
// operation; an expansion of a few doubles on the stack costs tens of flops. GMP stays
// the fallback for inputs outside the range and for expansions that outgrow their
// capacity (then `valid()` is false).
//
// Requires round-to-nearest-even (IEEE default; x86-64 SSE2).
#include <array>
#include <cmath>
#include <span>

#include "molsurf/vec3.hpp"

namespace molsurf::geometry {

// Error-free transformations (Dekker; Shewchuk 1997), the steps every expansion operation
// is made of.
namespace expansion_detail {

// s + err == a + b exactly, s = fl(a + b).
inline void two_sum(double a, double b, double& s, double& err) {
  s = a + b;
  const double b_virtual = s - a;
  const double a_virtual = s - b_virtual;
  err = (a - a_virtual) + (b - b_virtual);
}

// The same when |a| >= |b| (or a == 0).
inline void fast_two_sum(double a, double b, double& s, double& err) {
  s = a + b;
  err = b - (s - a);
}

// hi + lo == a, each with at most 26 significant bits (Veltkamp).
inline void split(double a, double& hi, double& lo) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// p + err == a * b exactly (no underflow or overflow), p = fl(a * b). Dekker's product
// rather than std::fma: without -mfma that is a library call per product.
inline void two_product(double a, double b, double& p, double& err) {
  p = a * b;
  double a_hi = 0, a_lo = 0, b_hi = 0, b_lo = 0;
  split(a, a_hi, a_lo);
  split(b, b_hi, b_lo);
  const double err1 = p - a_hi * b_hi;
  const double err2 = err1 - a_lo * b_hi;
  const double err3 = err2 - a_hi * b_lo;
  err = a_lo * b_lo - err3;
}

}  // namespace expansion_detail

class Expansion {
 public:
  static constexpr int kCapacity = 32;

  Expansion() = default;
  explicit Expansion(double v) {
    if (v != 0) parts_[size_++] = v;
  }
  // Copies only the parts in use (most expansions have a handful of the 32).
  Expansion(const Expansion& other) : size_(other.size_), valid_(other.valid_) {
    for (int i = 0; i < size_; ++i) parts_[i] = other.parts_[i];
  }
  Expansion& operator=(const Expansion& other) {
    size_ = other.size_;
    valid_ = other.valid_;
    for (int i = 0; i < size_; ++i) parts_[i] = other.parts_[i];
    return *this;
  }
  static Expansion difference_of(double a, double b);  // a - b, exactly
  static Expansion product_of(double a, double b);     // a * b, exactly

  int sign() const { return size_ == 0 ? 0 : (parts_[size_ - 1] > 0 ? 1 : -1); }
  // False when a result outgrew the capacity: the value is then meaningless.
  bool valid() const { return valid_; }
  int size() const { return size_; }
  std::span<const double> parts() const { return {parts_.data(), static_cast<std::size_t>(size_)}; }

  Expansion operator-() const;
  Expansion scaled(double b) const;  // this * b
  // Fewer, non-adjacent parts for the same value (keeps products small).
  void compress();

  friend Expansion operator+(const Expansion& e, const Expansion& f);
  friend Expansion operator-(const Expansion& e, const Expansion& f) { return e + (-f); }
  friend Expansion operator*(const Expansion& e, const Expansion& f);

 private:
  void push(double v) {
    if (size_ == kCapacity)
      valid_ = false;
    else
      parts_[size_++] = v;
  }

  std::array<double, kCapacity> parts_;  // only the first size_ are set
  int size_ = 0;
  bool valid_ = true;
};

struct ExpansionVec {
  Expansion x, y, z;
  const Expansion& operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
};

ExpansionVec difference(const Vec3& a, const Vec3& b);  // a - b, exactly
// det[u, v, w] = w . (u x v)
Expansion det3(const ExpansionVec& u, const ExpansionVec& v, const ExpansionVec& w);

// True when every product of up to `degree` of these values (and of values made from
// them by sums and differences) is exact in double expansions: no part can underflow
// below the smallest subnormal step or overflow. Non-finite values do not fit.
bool fits_expansion_range(std::span<const double> values, int degree);

}  // namespace molsurf::geometry
