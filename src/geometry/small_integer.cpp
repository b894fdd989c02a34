#include "geometry/small_integer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace molsurf::geometry {

static_assert(GMP_NUMB_BITS == 64, "SmallInteger assumes 64-bit limbs without nails");

namespace {
__extension__ using Wide = unsigned __int128;  // GCC and Clang on 64-bit targets
}  // namespace

SmallInteger SmallInteger::scaled(double v, int exponent) {
  SmallInteger r;
  if (v == 0) return r;
  // The double's own fields: no library calls (frexp and ldexp were most of the cost).
  const auto bits = std::bit_cast<std::uint64_t>(v);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  if (biased == 0x7ff) return overflowed();  // infinity or NaN
  std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
  int e = 0;  // v = mantissa * 2^e
  if (biased == 0) {
    e = -1074;  // subnormal
  } else {
    mantissa |= std::uint64_t{1} << 52;
    e = biased - 1075;
  }
  int shift = e - exponent;
  if (shift < 0) {  // fine if the bits shifted out are zero (1.0 at exponent 0, say)
    if (shift < -63 || (mantissa & ((std::uint64_t{1} << -shift) - 1)) != 0) return overflowed();
    mantissa >>= -shift;
    shift = 0;
  }
  const int word = shift / 64, bit = shift % 64;
  if (word + 2 > kLimbs) return overflowed();
  for (int i = 0; i < word; ++i) r.limbs_[i] = 0;
  r.limbs_[word] = static_cast<mp_limb_t>(mantissa << bit);
  const auto high = bit == 0 ? std::uint64_t{0} : mantissa >> (64 - bit);
  r.limbs_[word + 1] = static_cast<mp_limb_t>(high);
  const int n = high != 0 ? word + 2 : word + 1;
  r.size_ = v < 0 ? -n : n;
  return r;
}

mpz_srcptr SmallInteger::view(mpz_t storage) const {
  return mpz_roinit_n(storage, limbs_.data(), size_);
}

SmallInteger SmallInteger::add(const SmallInteger& a, const SmallInteger& b, bool subtract) {
  if (a.overflow_ || b.overflow_) return overflowed();
  const int sign_a = a.sign(), sign_b = subtract ? -b.sign() : b.sign();
  if (sign_b == 0) return a;
  if (sign_a == 0) {
    SmallInteger r = b;
    if (subtract) r.size_ = -r.size_;
    return r;
  }
  const int na = a.length(), nb = b.length();
  SmallInteger r;
  if (sign_a == sign_b) {  // magnitudes add
    const bool a_longer = na >= nb;
    const SmallInteger& big = a_longer ? a : b;
    const SmallInteger& small = a_longer ? b : a;
    const int nbig = a_longer ? na : nb, nsmall = a_longer ? nb : na;
    mp_limb_t carry = 0;
    for (int i = 0; i < nbig; ++i) {
      const Wide sum = static_cast<Wide>(big.limbs_[i]) + (i < nsmall ? small.limbs_[i] : 0) + carry;
      r.limbs_[i] = static_cast<mp_limb_t>(sum);
      carry = static_cast<mp_limb_t>(sum >> 64);
    }
    int n = nbig;
    if (carry != 0) {
      if (n == kLimbs) return overflowed();
      r.limbs_[n++] = carry;
    }
    r.size_ = sign_a > 0 ? n : -n;
    return r;
  }
  // Magnitudes subtract: the larger minus the smaller, with the larger's sign.
  int order = na != nb ? (na > nb ? 1 : -1) : 0;
  for (int i = na - 1; order == 0 && i >= 0; --i)
    if (a.limbs_[i] != b.limbs_[i]) order = a.limbs_[i] > b.limbs_[i] ? 1 : -1;
  if (order == 0) return r;
  const SmallInteger& big = order > 0 ? a : b;
  const SmallInteger& small = order > 0 ? b : a;
  const int nbig = order > 0 ? na : nb, nsmall = order > 0 ? nb : na;
  mp_limb_t borrow = 0;
  for (int i = 0; i < nbig; ++i) {
    const mp_limb_t subtrahend = i < nsmall ? small.limbs_[i] : 0;
    const mp_limb_t x = big.limbs_[i];
    const mp_limb_t difference = x - subtrahend - borrow;
    borrow = (x < subtrahend || (x == subtrahend && borrow != 0)) ? 1 : 0;
    r.limbs_[i] = difference;
  }
  int n = nbig;
  while (n > 0 && r.limbs_[n - 1] == 0) --n;
  const int sign = order > 0 ? sign_a : sign_b;
  r.size_ = sign > 0 ? n : -n;
  return r;
}

SmallInteger operator*(const SmallInteger& a, const SmallInteger& b) {
  if (a.overflow_ || b.overflow_) return SmallInteger::overflowed();
  SmallInteger r;
  const int na = a.length(), nb = b.length();
  if (na == 0 || nb == 0) return r;
  if (na + nb > SmallInteger::kLimbs) return SmallInteger::overflowed();
  if (na * nb > 4) {  // GMP's assembler schoolbook beats the loop below from 2 x 3 limbs on
    if (na >= nb)
      mpn_mul(r.limbs_.data(), a.limbs_.data(), na, b.limbs_.data(), nb);
    else
      mpn_mul(r.limbs_.data(), b.limbs_.data(), nb, a.limbs_.data(), na);
    int n = na + nb;
    while (n > 0 && r.limbs_[n - 1] == 0) --n;
    r.size_ = (a.size_ < 0) != (b.size_ < 0) ? -n : n;
    return r;
  }
  // Schoolbook inline for the smallest (a library call per product costs more there).
  for (int i = 0; i < na + nb; ++i) r.limbs_[i] = 0;
  for (int i = 0; i < na; ++i) {
    mp_limb_t carry = 0;
    for (int j = 0; j < nb; ++j) {
      const Wide t =
          static_cast<Wide>(a.limbs_[i]) * b.limbs_[j] + r.limbs_[i + j] + carry;
      r.limbs_[i + j] = static_cast<mp_limb_t>(t);
      carry = static_cast<mp_limb_t>(t >> 64);
    }
    r.limbs_[i + nb] = carry;
  }
  int n = na + nb;
  while (n > 0 && r.limbs_[n - 1] == 0) --n;
  r.size_ = (a.size_ < 0) != (b.size_ < 0) ? -n : n;
  return r;
}

namespace {

int bit_length(const mp_limb_t* limbs, int n) { return (n - 1) * 64 + (64 - std::countl_zero(limbs[n - 1])); }

// limbs << shift into out (n + shift / 64 + 1 limbs); returns the used length.
int shifted_left(const mp_limb_t* limbs, int n, int shift, mp_limb_t* out) {
  const int words = shift / 64, bits = shift % 64;
  for (int i = 0; i < words; ++i) out[i] = 0;
  out[words + n] = bits == 0 ? 0 : mpn_lshift(out + words, limbs, n, static_cast<unsigned>(bits));
  if (bits == 0)
    for (int i = 0; i < n; ++i) out[words + i] = limbs[i];
  int length = words + n + 1;
  while (length > 0 && out[length - 1] == 0) --length;
  return length;
}

}  // namespace

std::optional<double> truncated_quotient(const SmallInteger& x, const SmallInteger& w, int exponent) {
  if (x.overflow_ || w.overflow_ || w.size_ <= 0) return std::nullopt;
  if (x.size_ == 0) return 0.0;
  const int nx = x.length(), nw = w.length();
  // About 64 quotient bits: numerator and denominator aligned so that their bit lengths
  // differ by 64 (as the mpz version does).
  const int shift = 64 - (bit_length(x.limbs_.data(), nx) - bit_length(w.limbs_.data(), nw));
  std::array<mp_limb_t, 2 * SmallInteger::kLimbs + 2> numerator, denominator, quotient, remainder;
  int nn = nx, nd = nw;
  const mp_limb_t* np = x.limbs_.data();
  const mp_limb_t* dp = w.limbs_.data();
  if (shift >= 0) {
    if (nx + shift / 64 + 1 > static_cast<int>(numerator.size())) return std::nullopt;
    nn = shifted_left(x.limbs_.data(), nx, shift, numerator.data());
    np = numerator.data();
  } else {
    if (nw + -shift / 64 + 1 > static_cast<int>(denominator.size())) return std::nullopt;
    nd = shifted_left(w.limbs_.data(), nw, -shift, denominator.data());
    dp = denominator.data();
  }
  if (nn < nd) return std::nullopt;  // cannot happen: the quotient has about 64 bits
  mpn_tdiv_qr(quotient.data(), remainder.data(), 0, np, nn, dp, nd);
  int nq = nn - nd + 1;
  while (nq > 0 && quotient[nq - 1] == 0) --nq;
  if (nq == 0) return x.size_ < 0 ? -0.0 : 0.0;
  // The leading 53 bits, truncated (what mpz_get_d does), then scaled back.
  const int length = bit_length(quotient.data(), nq);
  std::uint64_t top = 0;
  int dropped = 0;
  if (length <= 64) {
    top = quotient[0];
  } else {  // at most 2 limbs here
    dropped = length - 64;
    top = (quotient[1] << (64 - dropped)) | (quotient[0] >> dropped);
  }
  const int excess = std::max(0, static_cast<int>(std::bit_width(top)) - 53);
  top >>= excess;
  const double magnitude = std::ldexp(static_cast<double>(top), dropped + excess - shift + exponent);
  return x.size_ < 0 ? -magnitude : magnitude;
}

}  // namespace molsurf::geometry
