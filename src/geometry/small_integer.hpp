#pragma once
// Signed integers of at most kLimbs 64-bit limbs, kept inline (no allocation), with
// schoolbook arithmetic on 128-bit products. The exact path of the implicit-point
// predicates works on integers of a few hundred bits; mpz_class pays a call, a size check
// and often an allocation per operation, which made that path several times slower than
// its arithmetic. GMP's mpz stays the fallback beyond kLimbs, and reads these values
// through view() without a copy.
//
// An operation whose result would not fit sets `overflow` (sticky through later
// operations); the caller then falls back to mpz_class. The value is sign-magnitude:
// `size` limbs of magnitude, negative size for negative values (as in mpz).
#include <gmp.h>

#include <array>
#include <cstdint>
#include <optional>

namespace molsurf::geometry {

class SmallInteger {
 public:
  static constexpr int kLimbs = 20;  // 1280 bits: degree-11 predicates on 60-bit inputs

  SmallInteger() = default;
  // v / 2^exponent (v must be a multiple of 2^exponent).
  static SmallInteger scaled(double v, int exponent);

  int sign() const { return size_ > 0 ? 1 : (size_ < 0 ? -1 : 0); }
  bool overflow() const { return overflow_; }
  // Read-only mpz view of the value (valid while this object lives, no copy).
  mpz_srcptr view(mpz_t storage) const;

  friend SmallInteger operator+(const SmallInteger& a, const SmallInteger& b) { return add(a, b, false); }
  friend SmallInteger operator-(const SmallInteger& a, const SmallInteger& b) { return add(a, b, true); }
  friend SmallInteger operator*(const SmallInteger& a, const SmallInteger& b);
  SmallInteger operator-() const {
    SmallInteger r = *this;
    r.size_ = -size_;
    return r;
  }
  friend int compare(const SmallInteger& a, const SmallInteger& b) { return (a - b).sign(); }
  // (x / w) * 2^exponent, truncated toward zero to a double (w > 0): the quotient to 64
  // bits by one long division, then its leading 53 bits (as mpz_tdiv_q and mpz_get_d
  // would give). Empty when an operand has overflowed or w is not positive.
  friend std::optional<double> truncated_quotient(const SmallInteger& x, const SmallInteger& w, int exponent);

  SmallInteger(const SmallInteger& other) : size_(other.size_), overflow_(other.overflow_) {
    copy_limbs(other);
  }
  SmallInteger& operator=(const SmallInteger& other) {
    size_ = other.size_;
    overflow_ = other.overflow_;
    copy_limbs(other);
    return *this;
  }

 private:
  static SmallInteger add(const SmallInteger& a, const SmallInteger& b, bool subtract);
  static SmallInteger overflowed() {
    SmallInteger r;
    r.overflow_ = true;
    return r;
  }
  int length() const { return size_ < 0 ? -size_ : size_; }
  void copy_limbs(const SmallInteger& other) {
    for (int i = 0, n = other.length(); i < n; ++i) limbs_[i] = other.limbs_[i];
  }

  std::array<mp_limb_t, kLimbs> limbs_;  // only the first |size_| are set
  int size_ = 0;
  bool overflow_ = false;
};

}  // namespace molsurf::geometry
