#include "geometry/expansion.hpp"

#include <algorithm>
#include <climits>

namespace molsurf::geometry {

using expansion_detail::fast_two_sum;
using expansion_detail::two_product;
using expansion_detail::two_sum;

Expansion Expansion::difference_of(double a, double b) {
  Expansion e;
  double s = 0, err = 0;
  two_sum(a, -b, s, err);
  if (err != 0) e.parts_[e.size_++] = err;
  if (s != 0) e.parts_[e.size_++] = s;
  return e;
}

Expansion Expansion::product_of(double a, double b) {
  Expansion e;
  double p = 0, err = 0;
  two_product(a, b, p, err);
  if (err != 0) e.parts_[e.size_++] = err;
  if (p != 0) e.parts_[e.size_++] = p;
  return e;
}

Expansion Expansion::operator-() const {
  Expansion e = *this;
  for (int i = 0; i < size_; ++i) e.parts_[i] = -parts_[i];
  return e;
}

// Shewchuk's Fast-Expansion-Sum with zero elimination: merge by magnitude, then one
// sweep of exact sums; nonoverlapping inputs give a nonoverlapping result.
Expansion operator+(const Expansion& e, const Expansion& f) {
  if (!e.valid_ || !f.valid_) {
    Expansion bad;
    bad.valid_ = false;
    return bad;
  }
  if (e.size_ == 0) return f;
  if (f.size_ == 0) return e;
  std::array<double, 2 * Expansion::kCapacity> merged;
  int m = 0, i = 0, j = 0;
  while (i < e.size_ && j < f.size_)
    merged[m++] = std::fabs(f.parts_[j]) > std::fabs(e.parts_[i]) ? e.parts_[i++] : f.parts_[j++];
  while (i < e.size_) merged[m++] = e.parts_[i++];
  while (j < f.size_) merged[m++] = f.parts_[j++];
  Expansion h;
  double q = merged[0];
  for (int k = 1; k < m; ++k) {
    double s = 0, err = 0;
    two_sum(q, merged[k], s, err);
    if (err != 0) h.push(err);
    q = s;
  }
  if (q != 0) h.push(q);
  return h;
}

// Shewchuk's Scale-Expansion with zero elimination.
Expansion Expansion::scaled(double b) const {
  Expansion h;
  h.valid_ = valid_;
  if (!valid_ || size_ == 0 || b == 0) return h;
  double q = 0, err = 0;
  two_product(parts_[0], b, q, err);
  if (err != 0) h.push(err);
  for (int i = 1; i < size_; ++i) {
    double high = 0, low = 0, sum = 0;
    two_product(parts_[i], b, high, low);
    two_sum(q, low, sum, err);
    if (err != 0) h.push(err);
    fast_two_sum(high, sum, q, err);
    if (err != 0) h.push(err);
  }
  if (q != 0) h.push(q);
  return h;
}

// Shewchuk's Compress.
void Expansion::compress() {
  if (size_ < 2) return;
  std::array<double, kCapacity> g;
  int bottom = size_ - 1;
  double q = parts_[size_ - 1];
  for (int i = size_ - 2; i >= 0; --i) {
    double sum = 0, err = 0;
    fast_two_sum(q, parts_[i], sum, err);
    if (err != 0) {
      g[bottom--] = sum;
      q = err;
    } else {
      q = sum;
    }
  }
  int top = 0;
  for (int i = bottom + 1; i < size_; ++i) {
    double sum = 0, err = 0;
    fast_two_sum(g[i], q, sum, err);
    if (err != 0) parts_[top++] = err;
    q = sum;
  }
  parts_[top++] = q;
  size_ = top;
  while (size_ > 0 && parts_[size_ - 1] == 0) --size_;
}

Expansion operator*(const Expansion& e, const Expansion& f) {
  if (!e.valid_ || !f.valid_) {
    Expansion bad;
    bad.valid_ = false;
    return bad;
  }
  // Compressed factors keep the product's part count (up to 2 m n) small.
  Expansion e_compressed, f_compressed;
  const Expansion* a = &e;
  const Expansion* b = &f;
  if (e.size_ > 4) {
    e_compressed = e;
    e_compressed.compress();
    a = &e_compressed;
  }
  if (f.size_ > 4) {
    f_compressed = f;
    f_compressed.compress();
    b = &f_compressed;
  }
  if (a->size_ < b->size_) std::swap(a, b);
  Expansion product;
  for (int i = 0; i < b->size_; ++i) {
    product = product + a->scaled(b->parts_[i]);
    if (product.size_ > Expansion::kCapacity / 2) product.compress();
  }
  product.compress();
  return product;
}

ExpansionVec difference(const Vec3& a, const Vec3& b) {
  return {Expansion::difference_of(a.x, b.x), Expansion::difference_of(a.y, b.y), Expansion::difference_of(a.z, b.z)};
}

Expansion det3(const ExpansionVec& u, const ExpansionVec& v, const ExpansionVec& w) {
  const Expansion cross_x = u.y * v.z - u.z * v.y;
  const Expansion cross_y = u.z * v.x - u.x * v.z;
  const Expansion cross_z = u.x * v.y - u.y * v.x;
  Expansion det = w.x * cross_x + w.y * cross_y + w.z * cross_z;
  det.compress();
  return det;
}

bool fits_expansion_range(std::span<const double> values, int degree) {
  // Every part is a multiple of 2^(degree * lowest) where 2^lowest is the finest ulp of
  // the values: representable (as a subnormal at worst) while that is >= 2^-1074. The
  // largest part is below 2^(degree * (highest + 1) + a few bits for the sums).
  const int lowest_allowed = -1074 / degree;
  const int highest_allowed = 960 / degree - 2;  // room for the splitting factor 2^27
  // |v| in [2^(e-1), 2^e) has ulp 2^(e-53): e - 53 >= lowest_allowed and e <= highest_allowed
  // say |v| >= 2^(lowest_allowed + 52) and |v| < 2^highest_allowed (NaN and infinities fail).
  const double smallest = std::ldexp(1.0, lowest_allowed + 52), beyond = std::ldexp(1.0, highest_allowed);
  for (const double v : values) {
    if (v == 0) continue;
    const double magnitude = std::fabs(v);
    if (!(magnitude >= smallest && magnitude < beyond)) return false;
  }
  return true;
}

}  // namespace molsurf::geometry
