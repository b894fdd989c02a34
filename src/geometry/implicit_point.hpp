#pragma once
// Points of the arrangement of meshes, defined by the input doubles that make them
// (DESIGN: "implicit points"): an input vertex, the crossing of the line through two
// input points p, q with the plane through three input points a, b, c (LPI), or the
// crossing of three planes, each through three input points (TPI: where the traces of two
// neighbours cross inside a face, in the one-pass surface). Predicates
// on them are signs of polynomials in the input doubles: decided by interval arithmetic
// first, and by exact GMP rationals when the interval cannot tell. The double
// coordinates of an LPI point are only an output (rounded after every decision).
#include <array>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <gmpxx.h>

#include "geometry/interval.hpp"
#include "geometry/small_integer.hpp"
#include "molsurf/vec3.hpp"

namespace molsurf::geometry {

// Homogeneous integer coordinates (x, y, z, w), w > 0, of a point scaled by 2^-e for a
// common exponent e (see exact_integers.hpp): the exact path without fractions.
struct HomogeneousPoint {
  mpz_class x, y, z, w;
  const mpz_class& operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
};

// The same in inline fixed-size integers: the fast exact path. Falls back to the mpz form
// when overflow() (defining doubles of very different magnitudes).
struct SmallHomogeneousPoint {
  SmallInteger x, y, z, w;
  const SmallInteger& operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
  bool overflow() const { return x.overflow() || y.overflow() || z.overflow() || w.overflow(); }
};

struct ExactPoint {
  mpq_class x, y, z;
  const mpq_class& operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
};

class ImplicitPoint {
 public:
  static ImplicitPoint explicit_point(const Vec3& v);
  // The line pq must cross the plane abc at exactly one point (orient3d(a,b,c,p) !=
  // orient3d(a,b,c,q) exactly); the caller has decided that with exact predicates.
  static ImplicitPoint line_plane(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c);
  // The planes (a0 b0 c0), (a1 b1 c1), (a2 b2 c2) must meet at exactly one point (their
  // normals linearly independent, decided exactly by the caller).
  static ImplicitPoint three_planes(const std::array<Vec3, 9>& planes);

  enum class Kind : std::uint8_t { explicit_point, line_plane, three_planes };
  Kind kind() const { return kind_; }
  bool is_explicit() const { return kind_ == Kind::explicit_point; }
  const Vec3& explicit_value() const { return def_[0]; }  // explicit points only
  // Explicit: v; line-plane: p, q, a, b, c; three planes: a0 b0 c0 a1 b1 c1 a2 b2 c2.
  const std::array<Vec3, 9>& definition() const { return def_; }
  const Interval& coordinate(int axis) const { return box_[axis]; }

  ExactPoint exact() const;
  // The defining doubles (3 for an explicit point, 15 or 27 for a crossing), for choosing a
  // common exponent, and the homogeneous integer form scaled by 2^-exponent.
  std::span<const double> defining_values() const;
  HomogeneousPoint homogeneous(int exponent) const;
  SmallHomogeneousPoint small_homogeneous(int exponent) const;
  // Within one ulp of the exact point in each coordinate (truncated toward zero);
  // the input itself for explicit points.
  Vec3 rounded() const;

 private:
  // The filter's box can be unbounded (its denominator straddles zero when a line is
  // nearly parallel to a plane, or three planes nearly share a line): then it is replaced
  // by the one-ulp box around the exact value, so every box is finite.
  void bound_box_exactly();

  std::array<Vec3, 9> def_{};
  std::array<Interval, 3> box_{};
  Kind kind_ = Kind::explicit_point;
};

// Exact equality of two points (all three coordinates).
bool same_point(const ImplicitPoint& a, const ImplicitPoint& b);

// The common exponent of the defining doubles of some points.
int common_exponent_of(std::initializer_list<const ImplicitPoint*> points);

// Exact signs on homogeneous points of one common exponent.
int orient2d_homogeneous(const HomogeneousPoint& a, const HomogeneousPoint& b, const HomogeneousPoint& c, int u,
                         int v);
int compare_homogeneous(const HomogeneousPoint& a, const HomogeneousPoint& b, int axis);
// The same on the small forms; kSmallOverflow when an intermediate value does not fit.
inline constexpr int kSmallOverflow = 2;
int orient2d_homogeneous(const SmallHomogeneousPoint& a, const SmallHomogeneousPoint& b,
                         const SmallHomogeneousPoint& c, int u, int v);
int compare_homogeneous(const SmallHomogeneousPoint& a, const SmallHomogeneousPoint& b, int axis);

// orient2d of three points projected on the coordinate plane (u, v), u, v in {0,1,2}:
// sign of (b-a)_u (c-a)_v - (b-a)_v (c-a)_u.
int orient2d(const ImplicitPoint& a, const ImplicitPoint& b, const ImplicitPoint& c, int u, int v);
// orient3d(a, b, c, d) with input points a, b, c and an implicit point d (convention of
// predicates.hpp: +1 when d is on the side (b-a)x(c-a) points to).
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const ImplicitPoint& d);

}  // namespace molsurf::geometry
