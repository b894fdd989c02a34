#include "geometry/implicit_point.hpp"

#include <cmath>

#include "geometry/double_double.hpp"
#include "geometry/exact_integers.hpp"
#include "geometry/expansion.hpp"
#include "geometry/predicates.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <climits>
#include <limits>

namespace molsurf::geometry {

namespace {

using IVec = std::array<Interval, 3>;

IVec to_interval(const Vec3& v) { return {Interval(v.x), Interval(v.y), Interval(v.z)}; }
IVec sub(const IVec& a, const IVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Interval det3(const IVec& u, const IVec& v, const IVec& w) {  // w . (u x v)
  return w[0] * (u[1] * v[2] - u[2] * v[1]) + w[1] * (u[2] * v[0] - u[0] * v[2]) + w[2] * (u[0] * v[1] - u[1] * v[0]);
}

// (x / w) * 2^exponent truncated toward zero to a double (w > 0), as SmallInteger's
// truncated_quotient: about 64 quotient bits, then mpz_get_d's truncation to 53.
double truncated_quotient(const mpz_class& x, const mpz_class& w, int exponent) {
  if (sgn(x) == 0) return 0.0;
  const long shift = 64 - (static_cast<long>(mpz_sizeinbase(x.get_mpz_t(), 2)) -
                           static_cast<long>(mpz_sizeinbase(w.get_mpz_t(), 2)));
  mpz_class q;
  if (shift >= 0) {
    mpz_class numerator;
    mpz_mul_2exp(numerator.get_mpz_t(), x.get_mpz_t(), static_cast<mp_bitcnt_t>(shift));
    mpz_tdiv_q(q.get_mpz_t(), numerator.get_mpz_t(), w.get_mpz_t());
  } else {
    mpz_class denominator;
    mpz_mul_2exp(denominator.get_mpz_t(), w.get_mpz_t(), static_cast<mp_bitcnt_t>(-shift));
    mpz_tdiv_q(q.get_mpz_t(), x.get_mpz_t(), denominator.get_mpz_t());
  }
  return std::ldexp(q.get_d(), static_cast<int>(exponent - shift));
}

int sign_of(const mpz_class& v) { return sgn(v); }
int sign_of(const SmallInteger& v) { return v.sign(); }

// Homogeneous integer coordinates (X, Y, Z, W), W > 0, of the crossing of line pq with
// plane abc, for any integer type with + - * (`scale` turns a defining double into one):
// P = (q dp - p dq) / (dp - dq), dp = det[b-a, c-a, p-a], dq = det[b-a, c-a, q-a].
template <class Int, class Scale>
std::array<Int, 4> line_plane_homogeneous(const std::array<Vec3, 9>& def, Scale scale) {
  std::array<Int, 3> p, q, u, v, pa, qa, normal;
  for (int i = 0; i < 3; ++i) {
    const Int a = scale(def[2][i]);
    p[i] = scale(def[0][i]);
    q[i] = scale(def[1][i]);
    u[i] = scale(def[3][i]) - a;
    v[i] = scale(def[4][i]) - a;
    pa[i] = p[i] - a;
    qa[i] = q[i] - a;
  }
  for (int i = 0; i < 3; ++i) {  // normal = u x v
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    normal[i] = u[j] * v[k] - u[k] * v[j];
  }
  const Int dp = pa[0] * normal[0] + pa[1] * normal[1] + pa[2] * normal[2];
  const Int dq = qa[0] * normal[0] + qa[1] * normal[1] + qa[2] * normal[2];
  std::array<Int, 4> h{q[0] * dp - p[0] * dq, q[1] * dp - p[1] * dq, q[2] * dp - p[2] * dq, dp - dq};
  if (sign_of(h[3]) < 0)
    for (Int& x : h) x = -x;
  return h;
}

// Homogeneous integer coordinates of the point where three planes meet, each plane given
// by three points (a, b, c): normal n = (b - a) x (c - a), offset d = n . a; the point is
// (d0 n1 x n2 + d1 n2 x n0 + d2 n0 x n1) / (n0 . n1 x n2) (Cramer's rule).
template <class Int, class Scale>
std::array<Int, 4> three_planes_homogeneous(const std::array<Vec3, 9>& def, Scale scale) {
  std::array<std::array<Int, 3>, 3> n;
  std::array<Int, 3> d;
  for (int k = 0; k < 3; ++k) {
    std::array<Int, 3> a, u, v;
    for (int i = 0; i < 3; ++i) {
      a[i] = scale(def[3 * k][i]);
      u[i] = scale(def[3 * k + 1][i]) - a[i];
      v[i] = scale(def[3 * k + 2][i]) - a[i];
    }
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, l = (i + 2) % 3;
      n[k][i] = u[j] * v[l] - u[l] * v[j];
    }
    d[k] = n[k][0] * a[0] + n[k][1] * a[1] + n[k][2] * a[2];
  }
  auto cross = [](const std::array<Int, 3>& x, const std::array<Int, 3>& y) {
    return std::array<Int, 3>{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  const std::array<Int, 3> c12 = cross(n[1], n[2]), c20 = cross(n[2], n[0]), c01 = cross(n[0], n[1]);
  std::array<Int, 4> h;
  for (int i = 0; i < 3; ++i) h[i] = d[0] * c12[i] + d[1] * c20[i] + d[2] * c01[i];
  h[3] = n[0][0] * c12[0] + n[0][1] * c12[1] + n[0][2] * c12[2];
  if (sign_of(h[3]) < 0)
    for (Int& x : h) x = -x;
  return h;
}

// The one-ulp box that holds a value truncated toward zero.
Interval truncation_box(double r) {
  if (r > 0) return {r, interval_detail::up(r)};
  if (r < 0) return {interval_detail::down(r), r};
  return {interval_detail::down(0.0), interval_detail::up(0.0)};
}

// The crossing of line pq with plane abc truncated toward zero, from a double-double
// estimate: P = p + t (q - p) with t = dp / (dp - dq), dp = det[b-a, c-a, p-a] and dq the
// same for q. Every step errs by a few units of 2^-104 of the magnitudes it combines, so
// the estimate is within 2^-99 of the sums of magnitudes below (the determinants'
// permanents, and what t and the step add); `reach` is 2^19 times that. The truncation is
// read off the estimate when that lies clearly inside one ulp; within `reach` of a double
// (the exact value may be that double: degenerate inputs) nothing is returned, and the
// integer form decides. Nothing too when a difference of the defining doubles is not a
// double (far apart, or on both sides of zero), dp - dq nearly cancels, or a value is out
// of the expansions' range.
std::optional<Vec3> line_plane_truncated(const std::array<Vec3, 9>& def) {
  if (!fits_expansion_range({&def[0].x, 15}, 5)) return std::nullopt;
  const Vec3 &p = def[0], &q = def[1], &a = def[2];
  std::array<double, 12> d;  // b - a, c - a, p - a, q - a
  const std::array<const Vec3*, 4> from{&def[3], &def[4], &p, &q};
  for (int k = 0; k < 12; ++k) {
    double err = 0;
    expansion_detail::two_sum((*from[k / 3])[k % 3], -a[k % 3], d[k], err);
    if (err != 0) return std::nullopt;
  }
  const double ux = d[0], uy = d[1], uz = d[2], vx = d[3], vy = d[4], vz = d[5];
  const std::array<DoubleDouble, 3> normal{product_difference_dd(uy, vz, uz, vy), product_difference_dd(uz, vx, ux, vz),
                                           product_difference_dd(ux, vy, uy, vx)};
  const std::array<double, 3> magnitude{std::fabs(uy * vz) + std::fabs(uz * vy), std::fabs(uz * vx) + std::fabs(ux * vz),
                                        std::fabs(ux * vy) + std::fabs(uy * vx)};
  auto along_normal = [&](const double* x) { return normal[0] * x[0] + normal[1] * x[1] + normal[2] * x[2]; };
  auto permanent = [&](const double* x) {
    return magnitude[0] * std::fabs(x[0]) + magnitude[1] * std::fabs(x[1]) + magnitude[2] * std::fabs(x[2]);
  };
  const DoubleDouble dp = along_normal(&d[6]), w = dp - along_normal(&d[9]);
  const double dp_permanent = permanent(&d[6]), all_permanent = dp_permanent + permanent(&d[9]);
  if (!(std::fabs(w.hi) > 0x1p-40 * all_permanent)) return std::nullopt;
  const DoubleDouble t = dp / w;
  const double t_spread = (dp_permanent + std::fabs(t.hi) * all_permanent) / std::fabs(w.hi);
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  Vec3 out;
  for (int axis = 0; axis < 3; ++axis) {
    DoubleDouble step;
    expansion_detail::two_sum(q[axis], -p[axis], step.hi, step.lo);
    const DoubleDouble x = DoubleDouble{p[axis], 0} + t * step;
    const double reach = 0x1p-80 * (std::fabs(p[axis]) + std::fabs(step.hi) * (std::fabs(t.hi) + t_spread));
    if (!(std::fabs(x.hi) > 0x1p-900) || !(reach > 0x1p-1000) || !std::isfinite(reach)) return std::nullopt;
    // The exact value lies within `reach` of x.hi + x.lo, and |x.lo| <= ulp(x.hi) / 2.
    const double beyond = x.hi > 0 ? x.lo : -x.lo;  // > 0: away from zero past x.hi
    if (beyond >= 2 * reach)
      out[axis] = x.hi;
    else if (beyond <= -2 * reach)
      out[axis] = std::nextafter(x.hi, x.hi > 0 ? -kInfinity : kInfinity);
    else
      return std::nullopt;
  }
  return out;
}

}  // namespace

ImplicitPoint ImplicitPoint::explicit_point(const Vec3& v) {
  ImplicitPoint point;
  point.def_[0] = v;
  point.box_ = to_interval(v);
  return point;
}

ImplicitPoint ImplicitPoint::line_plane(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  ImplicitPoint point;
  point.kind_ = Kind::line_plane;
  point.def_ = {p, q, a, b, c};
  // P = p + t (q - p), t = det[b-a, c-a, p-a] / (det[b-a, c-a, p-a] - det[b-a, c-a, q-a]).
  const IVec ia = to_interval(a), ip = to_interval(p), iq = to_interval(q);
  const IVec u = sub(to_interval(b), ia), v = sub(to_interval(c), ia);
  const Interval dp = det3(u, v, sub(ip, ia)), dq = det3(u, v, sub(iq, ia));
  const Interval t = dp / (dp - dq);
  for (int i = 0; i < 3; ++i) point.box_[i] = ip[i] + t * (iq[i] - ip[i]);
  point.bound_box_exactly();
  return point;
}

ImplicitPoint ImplicitPoint::three_planes(const std::array<Vec3, 9>& planes) {
  ImplicitPoint point;
  point.kind_ = Kind::three_planes;
  point.def_ = planes;
  IVec n[3];
  Interval d[3];
  for (int k = 0; k < 3; ++k) {
    const IVec a = to_interval(planes[3 * k]);
    const IVec u = sub(to_interval(planes[3 * k + 1]), a), v = sub(to_interval(planes[3 * k + 2]), a);
    n[k] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    d[k] = n[k][0] * a[0] + n[k][1] * a[1] + n[k][2] * a[2];
  }
  auto cross = [](const IVec& x, const IVec& y) {
    return IVec{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  const IVec c12 = cross(n[1], n[2]), c20 = cross(n[2], n[0]), c01 = cross(n[0], n[1]);
  const Interval w = n[0][0] * c12[0] + n[0][1] * c12[1] + n[0][2] * c12[2];
  for (int i = 0; i < 3; ++i) point.box_[i] = (d[0] * c12[i] + d[1] * c20[i] + d[2] * c01[i]) / w;
  point.bound_box_exactly();
  return point;
}

void ImplicitPoint::bound_box_exactly() {
  bool bounded = true;
  for (const Interval& i : box_) bounded = bounded && std::isfinite(i.lo) && std::isfinite(i.hi);
  if (bounded) return;
  const Vec3 r = rounded();
  for (int i = 0; i < 3; ++i) box_[i] = truncation_box(r[i]);
}

ExactPoint ImplicitPoint::exact() const {
  if (is_explicit()) return {mpq_class(def_[0].x), mpq_class(def_[0].y), mpq_class(def_[0].z)};
  const int e = common_exponent(defining_values());
  const HomogeneousPoint h = homogeneous(e);
  ExactPoint out;
  for (int i = 0; i < 3; ++i) {
    mpq_class& x = i == 0 ? out.x : (i == 1 ? out.y : out.z);
    x = mpq_class(h[i], h.w);
    x.canonicalize();
    if (e > 0)
      mpq_mul_2exp(x.get_mpq_t(), x.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
    else if (e < 0)
      mpq_div_2exp(x.get_mpq_t(), x.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
  }
  return out;
}

std::span<const double> ImplicitPoint::defining_values() const {
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  const std::size_t count = kind_ == Kind::explicit_point ? 3 : (kind_ == Kind::line_plane ? 15 : 27);
  return {&def_[0].x, count};
}

HomogeneousPoint ImplicitPoint::homogeneous(int exponent) const {
  if (is_explicit()) {
    const IntVec v = scaled(def_[0], exponent);
    return {v.x, v.y, v.z, 1};
  }
  const auto scale = [&](double x) { return scaled_integer(x, exponent); };
  auto h = kind_ == Kind::line_plane ? line_plane_homogeneous<mpz_class>(def_, scale)
                                     : three_planes_homogeneous<mpz_class>(def_, scale);
  return {std::move(h[0]), std::move(h[1]), std::move(h[2]), std::move(h[3])};
}

SmallHomogeneousPoint ImplicitPoint::small_homogeneous(int exponent) const {
  if (is_explicit())
    return {SmallInteger::scaled(def_[0].x, exponent), SmallInteger::scaled(def_[0].y, exponent),
            SmallInteger::scaled(def_[0].z, exponent), SmallInteger::scaled(1.0, 0)};
  const auto scale = [&](double x) { return SmallInteger::scaled(x, exponent); };
  auto h = kind_ == Kind::line_plane ? line_plane_homogeneous<SmallInteger>(def_, scale)
                                     : three_planes_homogeneous<SmallInteger>(def_, scale);
  return {h[0], h[1], h[2], h[3]};
}

int common_exponent_of(std::initializer_list<const ImplicitPoint*> points) {
  int lowest = INT_MAX;
  for (const ImplicitPoint* p : points) lowest = std::min(lowest, common_exponent(p->defining_values()));
  return lowest == INT_MAX ? 0 : lowest;
}

int orient2d_homogeneous(const HomogeneousPoint& a, const HomogeneousPoint& b, const HomogeneousPoint& c, int u,
                         int v) {
  // det [[a_u, a_v, a_w], [b_u, b_v, b_w], [c_u, c_v, c_w]]: orient2d of the projected
  // points when every w is positive. In place: no temporaries.
  mpz_class minor, det;
  mpz_mul(minor.get_mpz_t(), b[v].get_mpz_t(), c.w.get_mpz_t());
  mpz_submul(minor.get_mpz_t(), b.w.get_mpz_t(), c[v].get_mpz_t());
  mpz_mul(det.get_mpz_t(), a[u].get_mpz_t(), minor.get_mpz_t());
  mpz_mul(minor.get_mpz_t(), b[u].get_mpz_t(), c.w.get_mpz_t());
  mpz_submul(minor.get_mpz_t(), b.w.get_mpz_t(), c[u].get_mpz_t());
  mpz_submul(det.get_mpz_t(), a[v].get_mpz_t(), minor.get_mpz_t());
  mpz_mul(minor.get_mpz_t(), b[u].get_mpz_t(), c[v].get_mpz_t());
  mpz_submul(minor.get_mpz_t(), b[v].get_mpz_t(), c[u].get_mpz_t());
  mpz_addmul(det.get_mpz_t(), a.w.get_mpz_t(), minor.get_mpz_t());
  return sgn(det);
}

int orient2d_homogeneous(const SmallHomogeneousPoint& a, const SmallHomogeneousPoint& b,
                         const SmallHomogeneousPoint& c, int u, int v) {
  const SmallInteger det = a[u] * (b[v] * c.w - b.w * c[v]) - a[v] * (b[u] * c.w - b.w * c[u]) +
                           a.w * (b[u] * c[v] - b[v] * c[u]);
  return det.overflow() ? kSmallOverflow : det.sign();
}

int compare_homogeneous(const SmallHomogeneousPoint& a, const SmallHomogeneousPoint& b, int axis) {
  const SmallInteger difference = a[axis] * b.w - b[axis] * a.w;
  return difference.overflow() ? kSmallOverflow : difference.sign();
}

int compare_homogeneous(const HomogeneousPoint& a, const HomogeneousPoint& b, int axis) {
  mpz_class left, right;
  mpz_mul(left.get_mpz_t(), a[axis].get_mpz_t(), b.w.get_mpz_t());
  mpz_mul(right.get_mpz_t(), b[axis].get_mpz_t(), a.w.get_mpz_t());
  return cmp(left, right);
}

Vec3 ImplicitPoint::rounded() const {
  if (is_explicit()) return def_[0];
  if (kind_ == Kind::line_plane)
    if (const auto r = line_plane_truncated(def_)) return *r;
  // X / W from the integer form, as a quotient of about 64 bits (one truncating integer
  // division per coordinate: far cheaper than a canonical rational).
  const int exponent = common_exponent(defining_values());
  if (const SmallHomogeneousPoint small = small_homogeneous(exponent); !small.overflow()) {
    const auto x = truncated_quotient(small.x, small.w, exponent), y = truncated_quotient(small.y, small.w, exponent),
               z = truncated_quotient(small.z, small.w, exponent);
    if (x && y && z) return {*x, *y, *z};
  }
  const HomogeneousPoint h = homogeneous(exponent);
  return {truncated_quotient(h.x, h.w, exponent), truncated_quotient(h.y, h.w, exponent),
          truncated_quotient(h.z, h.w, exponent)};
}

int orient2d(const ImplicitPoint& a, const ImplicitPoint& b, const ImplicitPoint& c, int u, int v) {
  if (a.is_explicit() && b.is_explicit() && c.is_explicit()) {
    const Vec3 &pa = a.explicit_value(), &pb = b.explicit_value(), &pc = c.explicit_value();
    return geometry::orient2d(pa[u], pa[v], pb[u], pb[v], pc[u], pc[v]);
  }
  const Interval filtered = (b.coordinate(u) - a.coordinate(u)) * (c.coordinate(v) - a.coordinate(v)) -
                            (b.coordinate(v) - a.coordinate(v)) * (c.coordinate(u) - a.coordinate(u));
  if (const int s = filtered.certain_sign()) return s;
  const int e = common_exponent_of({&a, &b, &c});
  const int s = orient2d_homogeneous(a.small_homogeneous(e), b.small_homogeneous(e), c.small_homogeneous(e), u, v);
  if (s != kSmallOverflow) return s;
  return orient2d_homogeneous(a.homogeneous(e), b.homogeneous(e), c.homogeneous(e), u, v);
}

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const ImplicitPoint& d) {
  if (d.is_explicit()) return geometry::orient3d(a, b, c, d.explicit_value());
  {
    // Semi-static filter (the hot path of the one-pass union): the determinant at the
    // box's midpoint m, in doubles, and a bound on its error plus the change over the box.
    // Evaluation error: at most 8 eps times the permanent (Shewchuk's bound is 7 eps for
    // this expression); the point lies within h of m on each axis, which moves the exact
    // determinant by at most sum h_k |normal_k| <= sum h_k (|u_j v_l| + |u_l v_j|)(1 + 4 eps).
    constexpr double eps = 0x1p-53;
    const Vec3 u = b - a, v = c - a;
    double mk[3], hk[3];
    for (int k = 0; k < 3; ++k) {
      const Interval& i = d.coordinate(k);
      mk[k] = 0.5 * (i.lo + i.hi);
      hk[k] = std::max(i.hi - mk[k], mk[k] - i.lo) * (1 + 4 * eps);
    }
    const Vec3 m{mk[0], mk[1], mk[2]}, h{hk[0], hk[1], hk[2]};
    const Vec3 w = m - a;
    const double n0 = u.y * v.z - u.z * v.y, n1 = u.z * v.x - u.x * v.z, n2 = u.x * v.y - u.y * v.x;
    const double a0 = std::fabs(u.y * v.z) + std::fabs(u.z * v.y), a1 = std::fabs(u.z * v.x) + std::fabs(u.x * v.z),
                 a2 = std::fabs(u.x * v.y) + std::fabs(u.y * v.x);
    const double det = w.x * n0 + w.y * n1 + w.z * n2;
    const double permanent = std::fabs(w.x) * a0 + std::fabs(w.y) * a1 + std::fabs(w.z) * a2;
    const double spread = (h.x * a0 + h.y * a1 + h.z * a2) * (1 + 16 * eps);
    const double bound = 8 * eps * permanent + spread + 0x1p-900;
    if (std::isfinite(bound) && std::isfinite(det) && std::fabs(det) > bound) return (det > 0) - (det < 0);
  }
  const IVec ia = to_interval(a);
  const IVec id = {d.coordinate(0), d.coordinate(1), d.coordinate(2)};
  const Interval filtered = det3(sub(to_interval(b), ia), sub(to_interval(c), ia), sub(id, ia));
  if (const int s = filtered.certain_sign()) return s;
  // det[b-a, c-a, D/w - a] has the sign of det[b-a, c-a, D - a w] (w > 0).
  const double abc[] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z};
  const int e = std::min(common_exponent(abc), common_exponent_of({&d}));
  if (const SmallHomogeneousPoint h = d.small_homogeneous(e); !h.overflow()) {
    std::array<SmallInteger, 3> za, u, v, shifted;
    for (int i = 0; i < 3; ++i) {
      za[i] = SmallInteger::scaled(a[i], e);
      u[i] = SmallInteger::scaled(b[i], e) - za[i];
      v[i] = SmallInteger::scaled(c[i], e) - za[i];
      shifted[i] = h[i] - za[i] * h.w;
    }
    const SmallInteger det = shifted[0] * (u[1] * v[2] - u[2] * v[1]) + shifted[1] * (u[2] * v[0] - u[0] * v[2]) +
                             shifted[2] * (u[0] * v[1] - u[1] * v[0]);
    if (!det.overflow()) return det.sign();
  }
  const HomogeneousPoint h = d.homogeneous(e);
  const IntVec za = scaled(a, e);
  const IntVec shifted{h.x - za.x * h.w, h.y - za.y * h.w, h.z - za.z * h.w};
  return sgn(det3(scaled(b, e) - za, scaled(c, e) - za, shifted));
}

}  // namespace molsurf::geometry

namespace molsurf::geometry {

bool same_point(const ImplicitPoint& a, const ImplicitPoint& b) {
  for (int axis = 0; axis < 3; ++axis) {
    const Interval &x = a.coordinate(axis), &y = b.coordinate(axis);
    if (x.hi < y.lo || y.hi < x.lo) return false;
  }
  if (a.is_explicit() && b.is_explicit()) return a.explicit_value() == b.explicit_value();
  const int e = common_exponent_of({&a, &b});
  const SmallHomogeneousPoint sa = a.small_homogeneous(e), sb = b.small_homogeneous(e);
  if (!sa.overflow() && !sb.overflow()) {
    bool decided = true;
    for (int axis = 0; axis < 3; ++axis) {
      const int c = compare_homogeneous(sa, sb, axis);
      if (c == kSmallOverflow) {
        decided = false;
        break;
      }
      if (c != 0) return false;
    }
    if (decided) return true;
  }
  const HomogeneousPoint ha = a.homogeneous(e), hb = b.homogeneous(e);
  for (int axis = 0; axis < 3; ++axis)
    if (compare_homogeneous(ha, hb, axis) != 0) return false;
  return true;
}

}  // namespace molsurf::geometry
