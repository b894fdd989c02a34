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
