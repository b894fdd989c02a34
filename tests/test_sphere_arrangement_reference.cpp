// Independent references for the exact arrangement of a union of balls
// (include/molsurf/sphere_arrangement.hpp), written apart from its implementation:
//   - closed forms (one and two spheres, three spheres on an equilateral triangle, the
//     octahedral six with and without a cavity, four spheres through one point, lattices,
//     tangent chains, nested, duplicate and internally tangent spheres);
//   - Monte Carlo estimates of the volume and of each ball's exposed area, with tolerances
//     from the binomial standard error;
//   - measure_ball_union (include/molsurf/ball_union.hpp, slices) where no closed form is
//     at hand, with a tolerance justified by its measured convergence;
//   - invariance under translation, permutation and thread count, on degenerate placements.
//
// Tolerances. The arrangement is meant to be exact to rounding: every combinatorial decision
// is exact and areas and volumes are sums of closed-form terms in doubles. A few hundred
// roundings of ~1.1e-16 each, with mild cancellation (a sphere's exposed area is 4 pi r^2
// minus caps plus lenses), stay below 1e-12 relative; kExact = 1e-9 leaves three orders of
// magnitude for that and for the references' own rounding (acos near a few degrees), while
// any wrong arc, missed circle or wrong tie rule moves a result by far more (a cap of the
// smallest angle used here is > 1e-2 of its sphere). Per-sphere areas are compared with an
// absolute tolerance kExact * 4 pi r^2: the rounding of a sphere's Gauss-Bonnet sum scales
// with its full area, not with what is left exposed (which may be tiny or zero).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "arrangement/sphere_arrangement.hpp"
#include "support/ball_union.hpp"

namespace molsurf {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kExact = 1e-9;   // closed-form and invariance comparisons (see the top)
constexpr double kSumExact = 1e-12;  // sum of per-sphere areas against the total (brief: same numbers summed)

double sphere_area(double r) { return 4 * kPi * r * r; }
double ball_volume(double r) { return 4.0 / 3 * kPi * r * r * r; }
// Volume of a cap of height h cut from a ball of radius r (0 <= h <= 2r).
double cap_volume(double r, double h) { return kPi * h * h * (3 * r - h) / 3; }

// Compensated (Neumaier) sum: the reference total, free of the summation order.
double exact_sum(std::span<const double> v) {
  double s = 0, c = 0;
  for (double x : v) {
    const double t = s + x;
    c += std::abs(s) >= std::abs(x) ? (s - t) + x : (x - t) + s;
    s = t;
  }
  return s + c;
}

void expect_relative(double actual, double expected, double rel, const std::string& what) {
  EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << what;
}

// ---------------------------------------------------------------------------------------
// Two balls, |r1 - r2| < d < r1 + r2. The radical plane lies at x1 = (d^2 + r1^2 - r2^2)/(2d)
// from c1 towards c2 (x1 may be negative when c1 lies inside ball 2). Ball 2 covers the cap of
// sphere 1 beyond that plane, of height h1 = r1 - x1 and area 2 pi r1 h1 (Archimedes), so
// sphere 1 keeps 4 pi r1^2 - 2 pi r1 h1 = 2 pi r1 (r1 + x1). The union's volume is the two
// balls minus their lens, the lens being the two caps cut off by the plane.
struct TwoBalls {
  double exposed1 = 0, exposed2 = 0, volume = 0;
};
TwoBalls two_balls(double r1, double r2, double d) {
  const double x1 = (d * d + r1 * r1 - r2 * r2) / (2 * d), x2 = d - x1;
  TwoBalls t;
  t.exposed1 = 2 * kPi * r1 * (r1 + x1);
  t.exposed2 = 2 * kPi * r2 * (r2 + x2);
  t.volume = ball_volume(r1) + ball_volume(r2) - cap_volume(r1, r1 - x1) - cap_volume(r2, r2 - x2);
  return t;
}

// ---------------------------------------------------------------------------------------
// The intersection of two caps on the unit sphere, by Gauss-Bonnet.
//
// Two open caps of angular radius alpha whose centres a, b are theta apart
// (0 < theta < 2 alpha <= pi) meet in a lens L bounded by two circle arcs that meet at two
// vertices P, P'.
//  * The spherical triangle (a, b, P) has sides |aP| = |bP| = alpha, |ab| = theta. By the
//    spherical law of cosines its angle at a is phi, cos phi = cot(alpha) tan(theta/2): the
//    arc of circle a inside cap b spans 2 phi of azimuth about a (length 2 phi sin alpha).
//    Its angle at P is gamma, cos gamma = (cos theta - cos^2 alpha) / sin^2 alpha.
//  * A circle of angular radius alpha has geodesic curvature cot(alpha), towards its centre.
//    L lies on the centre side of both arcs: the boundary's integral of k_g is
//    2 (2 phi sin alpha) cot(alpha) = 4 phi cos alpha.
//  * At P each arc is perpendicular to its radius (Pa, Pb), and those meet at gamma, so L's
//    interior angle is pi - gamma and the boundary turns by gamma at each vertex.
//  * Gauss-Bonnet with K = 1: area(L) = 2 pi - 4 phi cos alpha - 2 gamma.
//    (theta -> 0: phi -> pi/2, gamma -> 0, area -> 2 pi (1 - cos alpha), the whole cap;
//     theta -> 2 alpha: phi -> 0, gamma -> pi, area -> 0.)
// The vector area (the integral of the normal over L, for volumes by the divergence
// theorem) is (1/2) of the loop integral of x cross dx over the boundary (Stokes), run with L
// on the left seen from outside. On circle a, x(t) = cos(alpha) a + sin(alpha)(cos t e1 +
// sin t e2), e1 the unit tangent at a towards b, e2 = a x e1, t in [-phi, phi]:
//     (1/2) int x cross x' dt = -cos(alpha) sin(alpha) sin(phi) e1 + phi sin^2(alpha) a.
// With m = (a + b)/|a + b| (a.m = cos(theta/2), e1.m = sin(theta/2)) the parts across m
// cancel between the two arcs:
//     VA(L) = 2 [phi sin^2 alpha cos(theta/2) - cos alpha sin alpha sin phi sin(theta/2)] m.
// (theta -> 0 gives pi sin^2(alpha) a: the cap's base disc, as it must.)
// Checked numerically while writing this file by 2e7-point Monte Carlo (agreement to its
// 1-sigma error) and against measure_ball_union.
struct CapLens {
  double area = 0;           // unit sphere
  double vector_area = 0;    // along the bisector m
  double phi = 0, gamma = 0;
};
CapLens cap_lens(double alpha, double theta) {
  CapLens l;
  l.phi = std::acos(std::tan(theta / 2) / std::tan(alpha));
  const double sa = std::sin(alpha), ca = std::cos(alpha);
  l.gamma = std::acos((std::cos(theta) - ca * ca) / (sa * sa));
  l.area = 2 * kPi - 4 * l.phi * ca - 2 * l.gamma;
  l.vector_area = 2 * (l.phi * sa * sa * std::cos(theta / 2) - ca * sa * std::sin(l.phi) * std::sin(theta / 2));
  return l;
}

// The volume of a union from its exposed patches (divergence theorem): on sphere i,
// x = c_i + r_i n, so a patch contributes (1/3)[r_i area + c_i . vector_area].

// ---------------------------------------------------------------------------------------
// Three balls of radius r centred on an equilateral triangle of side s (r < s < 2r).
// On sphere i the two neighbours cut caps of angular radius alpha, cos alpha = s / (2r),
// whose axes are theta = 60 degrees apart; the caps overlap iff 2 alpha > 60 degrees, i.e.
// s < sqrt(3) r, which is also when the three balls share points (the triangle's
// circumradius s / sqrt(3) is below r): then the surface has two vertices, at height
// +-sqrt(r^2 - s^2/3) above the centroid.
//   exposed area of each sphere: r^2 [4 pi - 2 * 2 pi (1 - cos alpha) + L.area]
//   (L = the caps' lens, empty when s >= sqrt(3) r).
// Vector area of sphere i's exposed part: -VA(cap_j) - VA(cap_k) + VA(L), the whole sphere's
// being 0. A cap's is pi sin^2(alpha) times its axis; the two axes sum to sqrt(3) m with m the
// unit vector from c_i towards the centroid O. With O as origin (|c_i| = s/sqrt(3), c_i.m =
// -s/sqrt(3)):  c_i . VA_i = (s / sqrt 3) r^2 (sqrt(3) pi sin^2 alpha - L.vector_area), and
//   V = 3 * (1/3) [r A_i + c_i . VA_i].
// Without the lens this equals inclusion-exclusion, 3 balls - 3 lenses (checked in the test).
struct EquilateralTriple {
  double exposed_each = 0, volume = 0;
  double arc_angle = 0;  // exposed azimuth of each circle on each sphere
  double vertex_height = 0;  // 0 when the three balls share no point
};
EquilateralTriple equilateral_triple(double r, double s) {
  const double ca = s / (2 * r), alpha = std::acos(ca), sa2 = std::sin(alpha) * std::sin(alpha);
  EquilateralTriple t;
  CapLens lens;
  if (s < std::sqrt(3.0) * r) {
    lens = cap_lens(alpha, kPi / 3);
    t.arc_angle = 2 * kPi - 2 * lens.phi;
    t.vertex_height = std::sqrt(r * r - s * s / 3);
  } else {
    t.arc_angle = 2 * kPi;
  }
  t.exposed_each = r * r * (4 * kPi - 4 * kPi * (1 - ca) + lens.area);
  t.volume = r * t.exposed_each + s / std::sqrt(3.0) * r * r * (std::sqrt(3.0) * kPi * sa2 - lens.vector_area);
  return t;
}

// ---------------------------------------------------------------------------------------
// Six balls of radius r centred at +-d on the axes, with d sqrt(2) < 2r (neighbours on
// adjacent axes overlap) and r <= d (opposite ones do not: they are apart or tangent).
// On sphere +x the four neighbours cut caps of angular radius alpha, cos alpha = d / (r sqrt 2),
// with axes (-1, +-1, 0)/sqrt 2 and (-1, 0, +-1)/sqrt 2: adjacent axes 60 degrees apart,
// opposite ones 90 degrees. 2 alpha <= 90 degrees (from r <= d), so opposite caps are disjoint
// or tangent and every three caps include such a pair: the caps' union is 4 caps - 4 lenses
// (theta = 60 degrees), when 2 alpha > 60 degrees (d < r sqrt(3/2)).
//   exposed area of each sphere: r^2 [4 pi - 4 * 2 pi (1 - cos alpha) + 4 L.area]
//   vector area: the four cap axes sum to -2 sqrt(2) x, the four lens bisectors
//   (-2, +-1, +-1)/sqrt 6 to -(8 / sqrt 6) x, so VA = r^2 [2 sqrt(2) pi sin^2 alpha -
//   8 L.vector_area / sqrt 6] x and V = 6 * (1/3) [r A + d VA.x].
// When r > d sqrt(2/3) every point of the octahedron spanned by the centres lies within r of a
// centre (a face's farthest point from its corners is its circumcentre, at d sqrt(2/3)), while
// the origin (at d > r from all) is free: the union encloses a cavity. Its wall on sphere +x is
// the patch around -x inside the ring of caps, bounded by four arcs (one per cap, the patch on
// the arc's right: k_g = -cot alpha) meeting at four vertices where the boundary turns by gamma
// (the vertical angle of the lens's pi - gamma). Seen from a cap's axis a, the axes of its two
// adjacent caps lie psi = arccos(-1/3) apart in azimuth, symmetric about the direction e_p
// towards -x; cap b covers azimuths within phi of psi/2, so the inner arc runs over
// [-beta, beta], beta = psi/2 - phi:
//   inner area (unit sphere) = 2 pi - 4 gamma + 4 (2 beta) cos alpha.
// Each inner arc, run from +beta to -beta, gives (1/2) int x cross dx =
// cos(alpha) sin(alpha) sin(beta) e_p - beta sin^2(alpha) a; both e_p and a make 45 degrees
// with -x, so VA_in = 2 sqrt(2) [cos alpha sin alpha sin beta - beta sin^2 alpha] (along -x),
// and the cavity's (signed) volume is 6 * (1/3) [r^3 A_in - d r^2 VA_in].
struct OctahedralSix {
  double exposed_each = 0, volume = 0;
  double cavity_area = 0, cavity_volume = 0;  // 0 when there is no cavity
};
OctahedralSix octahedral_six(double d, double r) {
  const double ca = d / (r * std::sqrt(2.0)), alpha = std::acos(ca), sa = std::sin(alpha), sa2 = sa * sa;
  const CapLens lens = cap_lens(alpha, kPi / 3);
  OctahedralSix o;
  const double a_unit = 4 * kPi - 8 * kPi * (1 - ca) + 4 * lens.area;
  const double va_unit = 2 * std::sqrt(2.0) * kPi * sa2 - 8 * lens.vector_area / std::sqrt(6.0);
  o.exposed_each = r * r * a_unit;
  o.volume = 2 * (r * r * r * a_unit + d * r * r * va_unit);
  if (r > d * std::sqrt(2.0 / 3.0) && r < d) {
    const double psi = std::acos(-1.0 / 3), beta = psi / 2 - lens.phi;
    const double a_in = 2 * kPi - 4 * lens.gamma + 8 * beta * ca;
    const double va_in = 2 * std::sqrt(2.0) * (ca * sa * std::sin(beta) - beta * sa2);
    o.cavity_area = 6 * r * r * a_in;
    o.cavity_volume = 2 * r * r * (r * a_in - d * va_in);
  }
  return o;
}

std::vector<Vec3> octahedral_centres(double d) {
  return {{d, 0, 0}, {-d, 0, 0}, {0, d, 0}, {0, -d, 0}, {0, 0, d}, {0, 0, -d}};
}

// ---------------------------------------------------------------------------------------
// What every result must satisfy.
void expect_consistent(const SphereArrangement& a, std::span<const double> radii, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(a.area_per_sphere.size(), radii.size());
  EXPECT_TRUE(std::isfinite(a.area));
  EXPECT_TRUE(std::isfinite(a.volume));
  EXPECT_GE(a.area, 0);
  EXPECT_GE(a.volume, 0);
  for (std::size_t i = 0; i < radii.size(); ++i) {
    EXPECT_TRUE(std::isfinite(a.area_per_sphere[i])) << "sphere " << i;
    EXPECT_GE(a.area_per_sphere[i], 0) << "sphere " << i;
    // Allowing for rounding only: no sphere exposes more than its whole area.
    EXPECT_LE(a.area_per_sphere[i], sphere_area(radii[i]) * (1 + kExact)) << "sphere " << i;
  }
  // The total is the per-sphere areas summed (in some order): rounding only.
  EXPECT_NEAR(exact_sum(a.area_per_sphere), a.area, kSumExact * a.area + 1e-300);
  for (const ArrangementVertex& v : a.vertices) {
    EXPECT_TRUE(std::isfinite(v.point.x) && std::isfinite(v.point.y) && std::isfinite(v.point.z));
    EXPECT_TRUE(v.side == 1 || v.side == -1);
    EXPECT_TRUE(v.spheres[0] < v.spheres[1] && v.spheres[1] < v.spheres[2]);
  }
  for (const ArrangementArc& arc : a.arcs) {
    EXPECT_TRUE(arc.angle >= 0 && arc.angle <= 2 * kPi * (1 + 1e-15)) << "arc angle " << arc.angle;
    if (arc.angle == 0) {  // only between two vertices at one point, up to their rounding
      // (near a tangency the two crossings lie the square root of the rounding apart, some
      // 3e-8 of the radius: up to 1.6e-7 A on rings of spheres through their centre)
      ASSERT_TRUE(arc.from >= 0 && arc.to >= 0);
      const Vec3 p = a.vertices[static_cast<std::size_t>(arc.from)].point;
      const Vec3 q = a.vertices[static_cast<std::size_t>(arc.to)].point;
      const double largest = radii.empty() ? 0 : *std::max_element(radii.begin(), radii.end());
      EXPECT_LE(norm(p - q), 4 * std::sqrt(1e-15) * (largest + norm(p))) << "a zero arc between vertices apart";
    }
    EXPECT_LT(arc.patch, a.patches.size());
  }
  // Patches: per sphere they add up to the sphere's area; each lies on a shell.
  std::vector<double> patch_sum(radii.size(), 0);
  std::vector<std::vector<double>> shell_parts(a.shells.size());
  for (const ArrangementPatch& p : a.patches) {
    ASSERT_LT(p.sphere, radii.size());
    ASSERT_LT(p.shell, a.shells.size());
    EXPECT_TRUE(std::isfinite(p.area));
    EXPECT_GE(p.area, 0);
    patch_sum[p.sphere] += p.area;
    shell_parts[p.shell].push_back(p.area);
  }
  for (std::size_t i = 0; i < radii.size(); ++i)
    EXPECT_NEAR(patch_sum[i], a.area_per_sphere[i], kSumExact * sphere_area(radii[i])) << "patches of sphere " << i;
  // Shells: they partition the area and the volume (outer volume minus the cavities').
  std::vector<double> shell_areas, shell_volumes;
  for (std::size_t k = 0; k < a.shells.size(); ++k) {
    const ArrangementShell& s = a.shells[k];
    EXPECT_TRUE(std::isfinite(s.area) && std::isfinite(s.volume)) << "shell " << k;
    // Not > 0: a real cavity of size ~1e-12 (a near-degenerate placement) has an area far
    // below the rounding of the sums that give it, and rounds to 0. Rounding errors scale with
    // the whole surface, hence the tolerance on the total.
    EXPECT_GE(s.area, 0) << "shell " << k;
    EXPECT_NEAR(exact_sum(shell_parts[k]), s.area, kExact * a.area) << "shell " << k << " against its patches";
    EXPECT_TRUE(std::is_sorted(s.spheres.begin(), s.spheres.end())) << "shell " << k;
    shell_areas.push_back(s.area);
    shell_volumes.push_back(s.volume);
  }
  if (a.area > 0) {
    ASSERT_FALSE(a.shells.empty());
    EXPECT_FALSE(a.shells[0].cavity()) << "the largest outer shell comes first";
  }
  EXPECT_NEAR(exact_sum(shell_areas), a.area, kExact * a.area);
  EXPECT_NEAR(exact_sum(shell_volumes), a.volume, kExact * a.volume);
}

void expect_per_sphere(const SphereArrangement& a, std::span<const double> radii, std::span<const double> expected,
                       const std::string& what) {
  ASSERT_EQ(a.area_per_sphere.size(), expected.size()) << what;
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(a.area_per_sphere[i], expected[i], kExact * sphere_area(radii[i])) << what << ", sphere " << i;
}

// ---------------------------------------------------------------------------------------
// 1. Closed forms: one and two spheres.

TEST(ArrangementReference, OneSphere) {
  const std::vector<Vec3> c{{1.25, -2.5, 3.0}};
  const std::vector<double> r{1.7};
  const SphereArrangement a = arrange_spheres(c, r);
  expect_consistent(a, r, "one sphere");
  expect_relative(a.area, sphere_area(1.7), kExact, "area");
  expect_relative(a.volume, ball_volume(1.7), kExact, "volume");
  expect_relative(a.area_per_sphere[0], sphere_area(1.7), kExact, "area of the sphere");
  EXPECT_TRUE(a.vertices.empty());
  EXPECT_TRUE(a.arcs.empty());
  ASSERT_EQ(a.patches.size(), 1u);
  ASSERT_EQ(a.shells.size(), 1u);
  EXPECT_FALSE(a.shells[0].cavity());
  expect_relative(a.shells[0].volume, ball_volume(1.7), kExact, "shell volume");
  EXPECT_EQ(a.shells[0].spheres, std::vector<std::uint32_t>{0});
  // The centroid of a whole sphere's surface is its centre.
  EXPECT_NEAR(norm(a.shells[0].centroid - c[0]), 0, kExact * 4);
}

TEST(ArrangementReference, TwoOverlappingSpheresOfDifferentRadii) {
  struct Pair {
    double r1, r2;
    Vec3 c1, offset;
    const char* what;
  };
  const Pair pairs[] = {
      {1.5, 1.2, {0.1, 0.2, 0.3}, {1.2, -1.6, 0.0}, "radical plane between the centres (d = 2, off axis)"},
      {2.0, 1.0, {-0.5, 0.25, 4.0}, {0.0, 0.9, 1.2}, "small centre inside the big ball (d = 1.5)"},
      {1.0, 1.0, {0, 0, 0}, {0.125, 0.25, 0.5}, "equal radii, deep overlap"},
  };
  for (const Pair& p : pairs) {
    SCOPED_TRACE(p.what);
    const std::vector<Vec3> c{p.c1, p.c1 + p.offset};
    const std::vector<double> r{p.r1, p.r2};
    const double d = norm(c[1] - c[0]);  // of the doubles actually passed
    const TwoBalls ref = two_balls(p.r1, p.r2, d);
    const SphereArrangement a = arrange_spheres(c, r);
    expect_consistent(a, r, p.what);
    expect_per_sphere(a, r, std::vector<double>{ref.exposed1, ref.exposed2}, "lens");
    expect_relative(a.area, ref.exposed1 + ref.exposed2, kExact, "area");
    expect_relative(a.volume, ref.volume, kExact, "volume");
    // One circle, exposed whole on each sphere: no vertices, one whole-circle arc per sphere.
    EXPECT_TRUE(a.vertices.empty());
    ASSERT_EQ(a.arcs.size(), 2u);
    for (const ArrangementArc& arc : a.arcs) {
      EXPECT_EQ(arc.from, -1);
      EXPECT_EQ(arc.to, -1);
      EXPECT_NEAR(arc.angle, 2 * kPi, 1e-12);
      EXPECT_EQ(arc.other, 1 - arc.sphere);
    }
    ASSERT_EQ(a.shells.size(), 1u);
    EXPECT_EQ(a.shells[0].spheres, (std::vector<std::uint32_t>{0, 1}));
  }
}

TEST(ArrangementReference, NestedSphereIsBuried) {
  const std::vector<Vec3> c{{0.5, 0.25, -1.0}, {1.0, 0.25, -1.0}};
  const std::vector<double> r{2.0, 0.75};
  const SphereArrangement a = arrange_spheres(c, r);
  expect_consistent(a, r, "nested");
  EXPECT_EQ(a.area_per_sphere[1], 0.0);
  expect_relative(a.area_per_sphere[0], sphere_area(2.0), kExact, "outer sphere");
  expect_relative(a.area, sphere_area(2.0), kExact, "area");
  expect_relative(a.volume, ball_volume(2.0), kExact, "volume");
  ASSERT_EQ(a.shells.size(), 1u);
  EXPECT_EQ(a.shells[0].spheres, std::vector<std::uint32_t>{0});
  // Inner sphere given first: the rule is geometric, not by index.
  const std::vector<Vec3> c2{c[1], c[0]};
  const std::vector<double> r2{r[1], r[0]};
  const SphereArrangement b = arrange_spheres(c2, r2);
  EXPECT_EQ(b.area_per_sphere[0], 0.0);
  expect_relative(b.area_per_sphere[1], sphere_area(2.0), kExact, "outer sphere, given second");
}

TEST(ArrangementReference, DisjointSpheres) {
  const std::vector<Vec3> c{{0, 0, 0}, {5, 0.5, -0.25}};
  const std::vector<double> r{0.5, 1.0};
  const SphereArrangement a = arrange_spheres(c, r);
  expect_consistent(a, r, "disjoint");
  expect_per_sphere(a, r, std::vector<double>{sphere_area(0.5), sphere_area(1.0)}, "disjoint");
  expect_relative(a.area, sphere_area(0.5) + sphere_area(1.0), kExact, "area");
  expect_relative(a.volume, ball_volume(0.5) + ball_volume(1.0), kExact, "volume");
  // Two outer shells, the larger first.
  ASSERT_EQ(a.shells.size(), 2u);
  EXPECT_FALSE(a.shells[0].cavity());
  EXPECT_FALSE(a.shells[1].cavity());
  EXPECT_EQ(a.shells[0].spheres, std::vector<std::uint32_t>{1});
  EXPECT_EQ(a.shells[1].spheres, std::vector<std::uint32_t>{0});
  expect_relative(a.shells[0].volume, ball_volume(1.0), kExact, "larger shell's volume");
}

TEST(ArrangementReference, ExternallyTangentSpheresKeepTheirWholeAreas) {
  // d = r1 + r2 exactly: on the axis, and along a 3-4-5 direction (all integers).
  const std::vector<std::vector<Vec3>> placements{{{0, 0, 0}, {1.5, 0, 0}}, {{1, 2, 3}, {4, 6, 3}}};
  const std::vector<std::vector<double>> radii{{1.0, 0.5}, {3.0, 2.0}};
  for (std::size_t k = 0; k < placements.size(); ++k) {
    const auto& c = placements[k];
    const auto& r = radii[k];
    const SphereArrangement a = arrange_spheres(c, r);
    expect_consistent(a, r, "tangent " + std::to_string(k));
    expect_per_sphere(a, r, std::vector<double>{sphere_area(r[0]), sphere_area(r[1])}, "tangent");
    expect_relative(a.volume, ball_volume(r[0]) + ball_volume(r[1]), kExact, "volume");
    EXPECT_TRUE(a.arcs.empty()) << "tangent spheres do not cut each other";
    EXPECT_TRUE(a.vertices.empty());
  }
}

TEST(ArrangementReference, IdenticalDuplicatesCountOnce) {
  // 0: A, 1: B, 2: A, 3: A. A and B overlap (d = 1.5).
  const Vec3 ca{0.5, 0.5, 0.5}, cb{2.0, 0.5, 0.5};
  const std::vector<Vec3> c{ca, cb, ca, ca};
  const std::vector<double> r{1.25, 1.0, 1.25, 1.25};
  const TwoBalls ref = two_balls(1.25, 1.0, 1.5);
  const SphereArrangement a = arrange_spheres(c, r);
  expect_consistent(a, r, "duplicates");
  EXPECT_EQ(a.area_per_sphere[2], 0.0);
  EXPECT_EQ(a.area_per_sphere[3], 0.0);
  expect_per_sphere(a, r, std::vector<double>{ref.exposed1, ref.exposed2, 0, 0}, "duplicates");
  expect_relative(a.volume, ref.volume, kExact, "volume");
  ASSERT_EQ(a.shells.size(), 1u);
  EXPECT_EQ(a.shells[0].spheres, (std::vector<std::uint32_t>{0, 1}));
  // Three copies alone: the first keeps the sphere.
  const std::vector<Vec3> c3{ca, ca, ca};
  const std::vector<double> r3{1.25, 1.25, 1.25};
  const SphereArrangement b = arrange_spheres(c3, r3);
  expect_per_sphere(b, r3, std::vector<double>{sphere_area(1.25), 0, 0}, "three copies");
  EXPECT_EQ(b.area_per_sphere[1], 0.0);
  EXPECT_EQ(b.area_per_sphere[2], 0.0);
  expect_relative(b.volume, ball_volume(1.25), kExact, "three copies' volume");
}

// ---------------------------------------------------------------------------------------
// 2. Three spheres (closed forms derived above).

// Centres (0,0,0), (s,0,0), (s/2, s sqrt(3)/2, 0): only the last y is rounded (its effect,
// ~1e-16 relative, is far below kExact).
std::vector<Vec3> triangle_centres(double s) { return {{0, 0, 0}, {s, 0, 0}, {s / 2, s * std::sqrt(3.0) / 2, 0}}; }

TEST(ArrangementReference, EquilateralTripleWithCommonPoints) {
  for (const double s : {1.25, 1.5, 1.625}) {  // < sqrt(3) r = 1.732: the three balls share points
    SCOPED_TRACE("s = " + std::to_string(s));
    const double r = 1.0;
    const std::vector<Vec3> c = triangle_centres(s);
    const std::vector<double> radii(3, r);
    const EquilateralTriple ref = equilateral_triple(r, s);
    const SphereArrangement a = arrange_spheres(c, radii);
    expect_consistent(a, radii, "equilateral, common points");
    expect_per_sphere(a, radii, std::vector<double>(3, ref.exposed_each), "equilateral");
    expect_relative(a.area, 3 * ref.exposed_each, kExact, "area");
    expect_relative(a.volume, ref.volume, kExact, "volume");
    // The reference itself against the slice reference (its error ~1e-6 here, see below).
    const BallUnionMeasure slices = measure_ball_union(c, radii, 8000);
    EXPECT_NEAR(ref.volume, slices.volume, 2e-5 * slices.volume) << "derivation check";
    // Two vertices, on the normal through the centroid at +-sqrt(r^2 - s^2/3); `side` is the
    // sign of orient3d(c0, c1, c2, point), i.e. of the point's z here.
    const Vec3 centroid = (c[0] + c[1] + c[2]) / 3;
    ASSERT_EQ(a.vertices.size(), 2u);
    for (const ArrangementVertex& v : a.vertices) {
      EXPECT_EQ(v.spheres, (std::array<std::uint32_t, 3>{0, 1, 2}));
      const Vec3 expected = centroid + Vec3{0, 0, v.side * ref.vertex_height};
      EXPECT_NEAR(norm(v.point - expected), 0, 1e-12) << "vertex on side " << v.side;
    }
    EXPECT_NE(a.vertices[0].side, a.vertices[1].side);
    // On each sphere, each neighbour's circle is exposed outside the other neighbour's cap.
    std::vector<double> angle(9, 0);
    for (const ArrangementArc& arc : a.arcs) angle[3 * arc.sphere + arc.other] += arc.angle;
    for (std::uint32_t i = 0; i < 3; ++i)
      for (std::uint32_t j = 0; j < 3; ++j)
        if (i != j) {
          EXPECT_NEAR(angle[3 * i + j], ref.arc_angle, 1e-12 * 2 * kPi) << "circle " << j << " on " << i;
        }
    ASSERT_EQ(a.shells.size(), 1u);
    EXPECT_EQ(a.patches.size(), 3u);
  }
}

TEST(ArrangementReference, EquilateralTripleWithoutCommonPoint) {
  // sqrt(3) r < s < 2 r: pairwise lenses but no triple point; the union is a solid torus.
  for (const double s : {1.75, 1.875, 1.96875}) {
    SCOPED_TRACE("s = " + std::to_string(s));
    const double r = 1.0;
    const std::vector<Vec3> c = triangle_centres(s);
    const std::vector<double> radii(3, r);
    const EquilateralTriple ref = equilateral_triple(r, s);
    // Two independent references must agree: the divergence form above, and inclusion-
    // exclusion with an empty triple intersection (3 balls - 3 lenses).
    const double lens = 2 * cap_volume(r, r - s / 2);
    EXPECT_NEAR(ref.volume, 3 * ball_volume(r) - 3 * lens, 1e-13 * ref.volume) << "derivation check";
    EXPECT_NEAR(ref.exposed_each, 2 * kPi * r * s, 1e-13 * ref.exposed_each) << "derivation check";
    const SphereArrangement a = arrange_spheres(c, radii);
    expect_consistent(a, radii, "equilateral, no common point");
    expect_per_sphere(a, radii, std::vector<double>(3, ref.exposed_each), "equilateral");
    expect_relative(a.volume, ref.volume, kExact, "volume");
    EXPECT_TRUE(a.vertices.empty());
    ASSERT_EQ(a.arcs.size(), 6u);  // every circle whole, on both its spheres
    for (const ArrangementArc& arc : a.arcs) EXPECT_NEAR(arc.angle, 2 * kPi, 1e-12);
    ASSERT_EQ(a.shells.size(), 1u);
    EXPECT_EQ(a.shells[0].spheres, (std::vector<std::uint32_t>{0, 1, 2}));
  }
}

// The slice reference, for placements without a closed form. Its error falls about as
// 1/slices with an oscillating constant; measured against 64 000 slices while writing this
// file, on the degenerate placements used here, it is <= 2e-6 relative at 4000 and 8000
// slices (1e-5 on test_ball_union's lens at 4000). We compare at kSliceTolerance = 2e-5, ten
// times that, and check on every use that the reference at 4000 and 8000 slices agrees to a
// quarter of it, so the tolerance is backed by the convergence seen on that very case.
constexpr double kSliceTolerance = 2e-5;
constexpr int kSlices = 8000;

void expect_matches_slices(const SphereArrangement& a, std::span<const Vec3> c, std::span<const double> r,
                           const std::string& what) {
  SCOPED_TRACE(what);
  const BallUnionMeasure fine = measure_ball_union(c, r, kSlices), coarse = measure_ball_union(c, r, kSlices / 2);
  EXPECT_NEAR(fine.area, coarse.area, kSliceTolerance / 4 * fine.area) << "slice reference not converged";
  EXPECT_NEAR(fine.volume, coarse.volume, kSliceTolerance / 4 * fine.volume) << "slice reference not converged";
  EXPECT_NEAR(a.area, fine.area, kSliceTolerance * fine.area);
  EXPECT_NEAR(a.volume, fine.volume, kSliceTolerance * fine.volume);
  for (std::size_t i = 0; i < r.size(); ++i)
    EXPECT_NEAR(a.area_per_sphere[i], fine.area_per_ball[i], kSliceTolerance * sphere_area(r[i])) << "sphere " << i;
}

TEST(ArrangementReference, ThreeUnequalSpheresAgainstSlices) {
  const std::vector<Vec3> c{{0.1, -0.2, 0.3}, {1.6, 0.3, -0.1}, {0.7, 1.3, 0.6}};
  const std::vector<double> r{1.2, 1.5, 0.9};
  const SphereArrangement a = arrange_spheres(c, r);
  expect_consistent(a, r, "three unequal");
  EXPECT_EQ(a.vertices.size(), 2u);
  expect_matches_slices(a, c, r, "three unequal");
}

// ---------------------------------------------------------------------------------------
// 3. Monte Carlo.

double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

struct BallSet {
  std::vector<Vec3> centres;
  std::vector<double> radii;
};

// 3 to 12 balls, radii in [1, 2], centres in a cube sized so most overlap (some balls buried,
// some sets in several pieces).
BallSet random_ball_set(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  BallSet b;
  const int n = 3 + static_cast<int>(rng() % 10);
  const double side = 2.0 * std::cbrt(static_cast<double>(n));
  for (int i = 0; i < n; ++i) {
    b.centres.push_back({side * uniform01(rng), side * uniform01(rng), side * uniform01(rng)});
    b.radii.push_back(1 + uniform01(rng));
  }
  return b;
}

// |count - N p_ref| within 4 binomial standard deviations. The standard deviation is taken at
// the larger of the binomial variances over [p_ref, p_hat] (q(1-q) for q between the reference
// fraction and the estimate): under the hypothesis that the arrangement is right it is at
// least the true one, and it stays honest where a fraction is near 0 or 1 (a buried or
// untouched ball: there the variance is 0 and any disagreement is a real one, since a set of
// positive measure was missed).
void expect_binomial(std::int64_t count, std::int64_t n, double p_ref, const std::string& what) {
  const double p_hat = static_cast<double>(count) / n;
  const double lo = std::min(p_ref, p_hat), hi = std::max(p_ref, p_hat);
  const double q = std::clamp(0.5, lo, hi);  // q(1-q) is largest at the point of [lo, hi] nearest 1/2
  const double sigma = std::sqrt(n * q * (1 - q));
  EXPECT_LE(std::abs(count - n * p_ref), 4 * sigma)
      << what << ": Monte Carlo fraction " << p_hat << ", arrangement " << p_ref << ", sigma " << sigma / n;
}

TEST(ArrangementReference, MonteCarloVolume) {
  // 2e6 points per set: at a fill fraction p ~ 0.3 the relative standard error is
  // sqrt((1-p)/(p N)) ~ 1.1e-3, so 4 sigma ~ 0.45 %.
  constexpr std::int64_t kSamples = 2'000'000;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const BallSet b = random_ball_set(seed);
    const std::string what = "set " + std::to_string(seed) + " (" + std::to_string(b.radii.size()) + " balls)";
    const SphereArrangement a = arrange_spheres(b.centres, b.radii);
    expect_consistent(a, b.radii, what);
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (std::size_t i = 0; i < b.radii.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], b.centres[i][k] - b.radii[i]);
        hi[k] = std::max(hi[k], b.centres[i][k] + b.radii[i]);
      }
    const Vec3 size = hi - lo;
    const double box = size.x * size.y * size.z;
    std::mt19937_64 rng(1000 + seed);
    std::int64_t inside = 0;
    for (std::int64_t s = 0; s < kSamples; ++s) {
      const Vec3 p{lo.x + size.x * uniform01(rng), lo.y + size.y * uniform01(rng), lo.z + size.z * uniform01(rng)};
      for (std::size_t i = 0; i < b.radii.size(); ++i) {
        const Vec3 q = p - b.centres[i];
        if (dot(q, q) < b.radii[i] * b.radii[i]) {
          ++inside;
          break;
        }
      }
    }
    expect_binomial(inside, kSamples, a.volume / box, what + " volume");
  }
}

TEST(ArrangementReference, MonteCarloExposedAreaPerBall) {
  // 1.5e5 uniform points per sphere (z uniform in [-1, 1] and a uniform azimuth: Archimedes):
  // the exposed fraction's standard error is at most 0.5 / sqrt(N) = 1.3e-3, so 4 sigma is at
  // most 0.5 % of the sphere's area. On these seeds the largest deviation is 3.6 sigma (set 3,
  // ball 9; the slice reference agrees with the arrangement there to 2e-8 of the sphere, so
  // that is the sample's own fluctuation: among 72 draws, a 3.6-sigma one has a few per cent
  // chance). A new seed may need a look before blaming the arrangement.
  constexpr std::int64_t kSamples = 150'000;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const BallSet b = random_ball_set(seed);
    const std::size_t n = b.radii.size();
    const SphereArrangement a = arrange_spheres(b.centres, b.radii);
    ASSERT_EQ(a.area_per_sphere.size(), n);
    std::mt19937_64 rng(2000 + seed);
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<std::size_t> near;
      for (std::size_t j = 0; j < n; ++j)
        if (j != i && norm(b.centres[j] - b.centres[i]) < b.radii[i] + b.radii[j]) near.push_back(j);
      std::int64_t exposed = 0;
      for (std::int64_t s = 0; s < kSamples; ++s) {
        const double z = 2 * uniform01(rng) - 1, t = 2 * kPi * uniform01(rng), w = std::sqrt(1 - z * z);
        const Vec3 p = b.centres[i] + Vec3{w * std::cos(t), w * std::sin(t), z} * b.radii[i];
        bool out = true;
        for (std::size_t j : near) {
          const Vec3 q = p - b.centres[j];
          if (dot(q, q) < b.radii[j] * b.radii[j]) {
            out = false;
            break;
          }
        }
        exposed += out;
      }
      expect_binomial(exposed, kSamples, a.area_per_sphere[i] / sphere_area(b.radii[i]),
                      "set " + std::to_string(seed) + ", ball " + std::to_string(i));
    }
  }
}

// The same random sets against the slice reference: far tighter than Monte Carlo (kSliceTolerance).
TEST(ArrangementReference, RandomSetsAgainstSlices) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const BallSet b = random_ball_set(seed);
    const SphereArrangement a = arrange_spheres(b.centres, b.radii);
    expect_matches_slices(a, b.centres, b.radii, "set " + std::to_string(seed));
  }
}

// ---------------------------------------------------------------------------------------
// 4. Degenerate placements: references and invariances.

struct Case {
  std::string name;
  std::vector<Vec3> centres;
  std::vector<double> radii;
  bool closed_form = false;  // else: the slice reference
  double area = 0, volume = 0;
  std::vector<double> area_per_sphere;
};

// Coordinates on multiples of 2^-40, so adding any offset up to 4096 in magnitude is exact:
// a translated placement is then the same geometry, bit for bit.
Vec3 snapped(const Vec3& v) {
  auto s = [](double x) { return std::ldexp(std::round(std::ldexp(x, 40)), -40); };
  return {s(v.x), s(v.y), s(v.z)};
}

std::vector<Case> degenerate_cases() {
  std::vector<Case> cases;
  auto closed = [&](std::string name, std::vector<Vec3> c, std::vector<double> r, std::vector<double> per,
                    double volume) {
    Case k{std::move(name), std::move(c), std::move(r), true, 0, volume, std::move(per)};
    k.area = exact_sum(k.area_per_sphere);
    cases.push_back(std::move(k));
  };
  auto sliced = [&](std::string name, std::vector<Vec3> c, std::vector<double> r) {
    cases.push_back(Case{std::move(name), std::move(c), std::move(r), false, 0, 0, {}});
  };

  // Four spheres through one point, exactly: integer centres of length 3 (2^2 + 2^2 + 1 = 9),
  // radius 3, spread like a tetrahedron around the origin, which lies on all four spheres and
  // is otherwise covered (an isolated point outside the open balls).
  sliced("four spheres through the origin (|c| = r = 3)", {{2, 2, 1}, {2, -2, -1}, {-2, 2, -1}, {-2, -2, 1}},
         {3, 3, 3, 3});
  {
    // A regular tetrahedron scaled so unit spheres pass through its centre, rounded: nearly
    // degenerate (sqrt(1/3) is not a double).
    const double t = 1 / std::sqrt(3.0);
    sliced("regular tetrahedron through its centre (rounded)",
           {snapped({t, t, t}), snapped({t, -t, -t}), snapped({-t, t, -t}), snapped({-t, -t, t})}, {1, 1, 1, 1});
  }
  {
    // Six unit spheres on the axes at distance 1: all pass through the origin; opposite
    // spheres are tangent there and, on every sphere, opposite circles are tangent there.
    const OctahedralSix o = octahedral_six(1.0, 1.0);
    closed("six unit spheres at +-1 on the axes", octahedral_centres(1.0), std::vector<double>(6, 1.0),
           std::vector<double>(6, o.exposed_each), o.volume);
  }
  {
    // Radius 5 at (+-3, +-4, 0): four spheres through the origin, where the union pinches
    // (the z axis is outside every ball). Neighbours at 6 and 8 cut caps of heights 2 and 1;
    // diagonal ones are tangent (d = 10), and on each sphere the two circles are tangent at
    // the origin (53.13 + 36.87 degrees = the 90 degrees between their axes). Triple
    // intersections each hold a tangent pair: measure zero.
    const double per = sphere_area(5) - 2 * kPi * 5 * 2 - 2 * kPi * 5 * 1;  // 70 pi
    const double volume = 4 * ball_volume(5) - 2 * 2 * cap_volume(5, 2) - 2 * 2 * cap_volume(5, 1);
    closed("four spheres through a pinch point, tangent circles", {{3, 4, 0}, {-3, 4, 0}, {-3, -4, 0}, {3, -4, 0}},
           {5, 5, 5, 5}, std::vector<double>(4, per), volume);
  }
  {
    // 3x3x3 cubic lattice, spacing 1.5, radius 1: each sphere is cut by its axis neighbours
    // only (face diagonal 2.12 > 2), caps of height 0.25 at 90 degrees (disjoint, no triple
    // overlap): area 4 pi - k pi / 2 for k neighbours; 54 neighbour pairs.
    std::vector<Vec3> c;
    std::vector<double> per;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) {
          c.push_back({1.5 * i, 1.5 * j, 1.5 * k});
          const int neighbours = (i == 1 ? 2 : 1) + (j == 1 ? 2 : 1) + (k == 1 ? 2 : 1);
          per.push_back(sphere_area(1) - neighbours * 2 * kPi * 1 * 0.25);
        }
    closed("cubic lattice 3x3x3, spacing 1.5, radius 1", c, std::vector<double>(27, 1.0), per,
           27 * ball_volume(1) - 54 * 2 * cap_volume(1, 0.25));
  }
  {
    // 3x3x2 lattice with spacing = radius = 1: the four spheres of each unit square meet at
    // two points (0.5, 0.5, +-sqrt(1/2)) exactly (0.25 + 0.25 + 0.5 = 1); next-nearest
    // neighbours at distance 2 are tangent.
    std::vector<Vec3> c;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 2; ++k) c.push_back({double(i), double(j), double(k)});
    sliced("lattice 3x3x2, spacing = radius = 1", c, std::vector<double>(c.size(), 1.0));
  }
  {
    // Tangent chain and tangent square grid: radius 0.5, spacing 1: every sphere whole.
    std::vector<Vec3> chain, grid;
    for (int i = 0; i < 8; ++i) chain.push_back({double(i), 0.5, -0.5});
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) grid.push_back({double(i), double(j), 0});
    closed("tangent chain of 8, radius 0.5, spacing 1", chain, std::vector<double>(8, 0.5),
           std::vector<double>(8, sphere_area(0.5)), 8 * ball_volume(0.5));
    closed("tangent 4x4 grid, radius 0.5, spacing 1", grid, std::vector<double>(16, 0.5),
           std::vector<double>(16, sphere_area(0.5)), 16 * ball_volume(0.5));
  }
  {
    // A sphere inside another touching it internally at (2,0,0), and a third touching both
    // there from outside: the inner one is buried, the others whole.
    closed("internal and external tangency at one point", {{0, 0, 0}, {1, 0, 0}, {3, 0, 0}}, {2, 1, 1},
           {sphere_area(2), 0, sphere_area(1)}, ball_volume(2) + ball_volume(1));
    // The same inner sphere, with a third cutting the outer one near the tangency point (and
    // the inner one, inside the outer).
    const TwoBalls t = two_balls(2, 1, std::sqrt(5.0));
    closed("internally tangent sphere and a cutting neighbour", {{0, 0, 0}, {1, 0, 0}, {2, 0, 1}}, {2, 1, 1},
           {t.exposed1, 0, t.exposed2}, t.volume);
  }
  {
    // Many identical copies of two overlapping spheres, interleaved: the first of each kind
    // keeps the area.
    const Vec3 ca{0, 0, 0}, cb{2, 0, 0};
    std::vector<Vec3> c;
    std::vector<double> r, per;
    const TwoBalls t = two_balls(1.5, 1.0, 2.0);
    bool seen_a = false, seen_b = false;
    for (int i = 0; i < 24; ++i) {
      const bool is_b = i % 5 == 0;
      c.push_back(is_b ? cb : ca);
      r.push_back(is_b ? 1.0 : 1.5);
      bool& seen = is_b ? seen_b : seen_a;
      per.push_back(seen ? 0.0 : (is_b ? t.exposed2 : t.exposed1));
      seen = true;
    }
    closed("24 identical copies of two spheres", c, r, per, t.volume);
  }
  {
    const OctahedralSix o = octahedral_six(2.0, 1.75);
    closed("octahedral six around a cavity (d = 2, r = 1.75)", octahedral_centres(2.0), std::vector<double>(6, 1.75),
           std::vector<double>(6, o.exposed_each), o.volume);
  }
  return cases;
}

TEST(ArrangementReference, DegeneratePlacementsMatchReferences) {
  for (const Case& k : degenerate_cases()) {
    SCOPED_TRACE(k.name);
    const SphereArrangement a = arrange_spheres(k.centres, k.radii);
    expect_consistent(a, k.radii, k.name);
    if (k.closed_form) {
      expect_per_sphere(a, k.radii, k.area_per_sphere, k.name);
      expect_relative(a.area, k.area, kExact, "area");
      expect_relative(a.volume, k.volume, kExact, "volume");
      // Buried and duplicate spheres are exactly 0, not rounding residue.
      for (std::size_t i = 0; i < k.radii.size(); ++i)
        if (k.area_per_sphere[i] == 0) {
          EXPECT_EQ(a.area_per_sphere[i], 0.0) << "sphere " << i;
        }
    } else {
      expect_matches_slices(a, k.centres, k.radii, k.name);
    }
  }
}

TEST(ArrangementReference, TranslationByLargeOffsets) {
  // The offsets are exact on these coordinates (multiples of 2^-40), so the geometry is the
  // same: the same combinatorics, and areas and volumes equal to rounding, which at
  // coordinates ~1e3 is ~1e3 * 2^-52 ~ 2e-13 relative to the radii: kExact.
  const Vec3 offsets[] = {{1000, 1000, 1000}, {-1000, 2000, 0.5}};
  for (const Case& k : degenerate_cases()) {
    SCOPED_TRACE(k.name);
    const SphereArrangement a = arrange_spheres(k.centres, k.radii);
    for (const Vec3& offset : offsets) {
      std::vector<Vec3> moved;
      for (const Vec3& c : k.centres) {
        moved.push_back(c + offset);
        ASSERT_EQ(moved.back() - offset, c) << "offset not exact";
      }
      const SphereArrangement b = arrange_spheres(moved, k.radii);
      expect_consistent(b, k.radii, k.name + " translated");
      expect_relative(b.area, a.area, kExact, "area");
      expect_relative(b.volume, a.volume, kExact, "volume");
      expect_per_sphere(b, k.radii, a.area_per_sphere, "translated");
      EXPECT_EQ(b.vertices.size(), a.vertices.size());
      EXPECT_EQ(b.arcs.size(), a.arcs.size());
      EXPECT_EQ(b.patches.size(), a.patches.size());
      ASSERT_EQ(b.shells.size(), a.shells.size());
      for (std::size_t s = 0; s < a.shells.size(); ++s) {
        // Rounding scales with the whole surface (a tiny shell's own size is no scale).
        EXPECT_NEAR(b.shells[s].area, a.shells[s].area, kExact * a.area) << "shell " << s;
        EXPECT_NEAR(b.shells[s].volume, a.shells[s].volume, kExact * a.volume) << "shell " << s;
        EXPECT_EQ(b.shells[s].spheres, a.shells[s].spheres);
        if (a.shells[s].area > kExact * a.area) {  // a zero-area shell's centroid means nothing
          EXPECT_NEAR(norm(b.shells[s].centroid - (a.shells[s].centroid + offset)), 0, 1e-9 * norm(offset));
        }
      }
    }
  }
}

// The spheres grouped by identity (same centre and radius): within a group only the lowest
// index counts, so under a permutation a group's area moves to its new lowest index.
std::vector<std::size_t> first_of_group(const std::vector<Vec3>& c, const std::vector<double>& r) {
  std::vector<std::size_t> first(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    first[i] = i;
    for (std::size_t j = 0; j < i; ++j)
      if (c[j] == c[i] && r[j] == r[i]) {
        first[i] = j;
        break;
      }
  }
  return first;
}

TEST(ArrangementReference, PermutationOfTheInput) {
  // A different order changes which sphere owns a shared circle and the order of sums:
  // rounding only (kExact); per-sphere areas follow their spheres.
  std::mt19937_64 rng(7);
  for (const Case& k : degenerate_cases()) {
    SCOPED_TRACE(k.name);
    const std::size_t n = k.radii.size();
    const SphereArrangement a = arrange_spheres(k.centres, k.radii);
    const std::vector<std::size_t> group = first_of_group(k.centres, k.radii);
    std::vector<std::size_t> reversed(n), shuffled(n);
    std::iota(shuffled.begin(), shuffled.end(), 0);
    for (std::size_t i = 0; i < n; ++i) reversed[i] = n - 1 - i;
    for (std::size_t i = n; i > 1; --i) std::swap(shuffled[i - 1], shuffled[rng() % i]);
    for (const auto& perm : {reversed, shuffled}) {
      std::vector<Vec3> c;
      std::vector<double> r;
      for (std::size_t i : perm) {
        c.push_back(k.centres[i]);
        r.push_back(k.radii[i]);
      }
      const SphereArrangement b = arrange_spheres(c, r);
      expect_consistent(b, r, k.name + " permuted");
      expect_relative(b.area, a.area, kExact, "area");
      expect_relative(b.volume, a.volume, kExact, "volume");
      // New position p holds old sphere perm[p]. Per group: the sum is the same, and it sits on
      // the group's lowest new position.
      std::vector<std::size_t> lowest_new(n, n);
      for (std::size_t p = 0; p < n; ++p) lowest_new[group[perm[p]]] = std::min(lowest_new[group[perm[p]]], p);
      for (std::size_t p = 0; p < n; ++p) {
        const std::size_t old = perm[p], g = group[old];
        const double expected = p == lowest_new[g] ? a.area_per_sphere[g] : 0.0;
        EXPECT_NEAR(b.area_per_sphere[p], expected, kExact * sphere_area(r[p])) << "old sphere " << old;
      }
      ASSERT_EQ(b.shells.size(), a.shells.size());
      std::vector<double> sa, sb;
      for (const auto& s : a.shells) sa.push_back(s.area);
      for (const auto& s : b.shells) sb.push_back(s.area);
      std::sort(sa.begin(), sa.end());
      std::sort(sb.begin(), sb.end());
      for (std::size_t s = 0; s < sa.size(); ++s) EXPECT_NEAR(sb[s], sa[s], kExact * a.area) << "shell area";
    }
  }
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same_bits(const Vec3& a, const Vec3& b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }

void expect_identical(const SphereArrangement& a, const SphereArrangement& b, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_TRUE(same_bits(a.area, b.area));
  EXPECT_TRUE(same_bits(a.volume, b.volume));
  ASSERT_EQ(a.area_per_sphere.size(), b.area_per_sphere.size());
  for (std::size_t i = 0; i < a.area_per_sphere.size(); ++i)
    EXPECT_TRUE(same_bits(a.area_per_sphere[i], b.area_per_sphere[i])) << "sphere " << i;
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    EXPECT_EQ(a.vertices[i].spheres, b.vertices[i].spheres) << "vertex " << i;
    EXPECT_EQ(a.vertices[i].side, b.vertices[i].side) << "vertex " << i;
    EXPECT_TRUE(same_bits(a.vertices[i].point, b.vertices[i].point)) << "vertex " << i;
  }
  ASSERT_EQ(a.arcs.size(), b.arcs.size());
  for (std::size_t i = 0; i < a.arcs.size(); ++i) {
    const ArrangementArc &x = a.arcs[i], &y = b.arcs[i];
    EXPECT_TRUE(x.sphere == y.sphere && x.other == y.other && x.from == y.from && x.to == y.to &&
                x.patch == y.patch && same_bits(x.angle, y.angle))
        << "arc " << i;
  }
  ASSERT_EQ(a.patches.size(), b.patches.size());
  for (std::size_t i = 0; i < a.patches.size(); ++i) {
    const ArrangementPatch &x = a.patches[i], &y = b.patches[i];
    EXPECT_TRUE(x.sphere == y.sphere && x.shell == y.shell && same_bits(x.area, y.area) &&
                same_bits(x.vector_area, y.vector_area))
        << "patch " << i;
  }
  ASSERT_EQ(a.shells.size(), b.shells.size());
  for (std::size_t i = 0; i < a.shells.size(); ++i) {
    const ArrangementShell &x = a.shells[i], &y = b.shells[i];
    EXPECT_TRUE(same_bits(x.area, y.area) && same_bits(x.volume, y.volume) && same_bits(x.centroid, y.centroid) &&
                x.spheres == y.spheres)
        << "shell " << i;
  }
  // Counts that are facts about the input (exact_decisions is left out: a cache may change it).
  EXPECT_EQ(a.stats.spheres, b.stats.spheres);
  EXPECT_EQ(a.stats.buried, b.stats.buried);
  EXPECT_EQ(a.stats.duplicate, b.stats.duplicate);
  EXPECT_EQ(a.stats.circles, b.stats.circles);
  EXPECT_EQ(a.stats.degenerate_points, b.stats.degenerate_points);
}

TEST(ArrangementReference, ThreadCountGivesIdenticalBits) {
  auto with_threads = [](const std::vector<Vec3>& c, const std::vector<double>& r, int threads) {
    ArrangementOptions o;
    o.threads = threads;
    return arrange_spheres(c, r, o);
  };
  for (const Case& k : degenerate_cases())
    expect_identical(with_threads(k.centres, k.radii, 1), with_threads(k.centres, k.radii, 2), k.name);
  // A larger set, so both threads get work: a jittered 13^3 lattice (2197 atom-like balls,
  // spacing 2.25, radii 1.5 to 1.875, coordinates on multiples of 1/64: exact ties such as
  // tangencies occur), a tangent-lattice corner and exact duplicates mixed in. The
  // arrangement splits inputs this small today (measured: 1000 balls run 2x faster on two
  // threads than on one); were a minimum size for parallel loops added (as
  // kParallelMinItems = 16384 in src/common/parallel_threshold.hpp), this set would have to
  // grow past it for the comparison to mean anything.
  std::mt19937_64 rng(11);
  std::vector<Vec3> c;
  std::vector<double> r;
  for (int i = 0; i < 13; ++i)
    for (int j = 0; j < 13; ++j)
      for (int k = 0; k < 13; ++k) {
        auto jitter = [&] { return static_cast<double>(static_cast<int>(rng() % 65) - 32) / 64; };
        if (i < 4 && j < 4 && k < 4) {  // tangent corner: radius 1.125 at spacing 2.25
          c.push_back({2.25 * i, 2.25 * j, 2.25 * k});
          r.push_back(1.125);
        } else {
          c.push_back({2.25 * i + jitter(), 2.25 * j + jitter(), 2.25 * k + jitter()});
          r.push_back(1.5 + static_cast<double>(rng() % 4) / 8);
        }
      }
  for (int d = 0; d < 64; ++d) {  // exact duplicates of random earlier balls
    const std::size_t i = rng() % c.size();
    c.push_back(c[i]);
    r.push_back(r[i]);
  }
  const SphereArrangement one = with_threads(c, r, 1), two = with_threads(c, r, 2);
  expect_identical(one, two, "2261 balls");
  expect_consistent(two, r, "2261 balls");
}

// ---------------------------------------------------------------------------------------
// 5. A cavity: six balls of radius 1.75 at +-2 on the axes. Neighbours overlap (2 sqrt 2 =
// 2.83 < 3.5), the octahedron's faces are covered (circumradius 2 sqrt(2/3) = 1.63 < 1.75) and
// the origin is free (2 > 1.75): one cavity, lined by all six spheres (closed form above;
// checked by Monte Carlo while writing this file: cavity volume 0.14763 +- 0.00024 against
// 0.147862).

TEST(ArrangementReference, OctahedralCavity) {
  const std::vector<Vec3> c = octahedral_centres(2.0);
  const std::vector<double> r(6, 1.75);
  const OctahedralSix ref = octahedral_six(2.0, 1.75);
  ASSERT_GT(ref.cavity_area, 0);
  ASSERT_LT(ref.cavity_volume, 0);
  const SphereArrangement a = arrange_spheres(c, r);
  expect_consistent(a, r, "octahedral cavity");
  expect_per_sphere(a, r, std::vector<double>(6, ref.exposed_each), "octahedral cavity");
  expect_relative(a.area, 6 * ref.exposed_each, kExact, "area");
  expect_relative(a.volume, ref.volume, kExact, "volume");
  ASSERT_EQ(a.shells.size(), 2u);
  const ArrangementShell &outer = a.shells[0], &cavity = a.shells[1];
  EXPECT_FALSE(outer.cavity());
  EXPECT_GT(outer.volume, 0);
  EXPECT_TRUE(cavity.cavity());
  const std::vector<std::uint32_t> all{0, 1, 2, 3, 4, 5};
  EXPECT_EQ(cavity.spheres, all);
  EXPECT_EQ(outer.spheres, all);
  expect_relative(cavity.area, ref.cavity_area, kExact, "cavity area");
  expect_relative(cavity.volume, ref.cavity_volume, kExact, "cavity volume");
  expect_relative(outer.area, 6 * ref.exposed_each - ref.cavity_area, kExact, "outer area");
  expect_relative(outer.volume, ref.volume - ref.cavity_volume, kExact, "outer volume");
  EXPECT_NEAR(outer.area + cavity.area, a.area, kExact * a.area);
  EXPECT_NEAR(outer.volume + cavity.volume, a.volume, kExact * a.volume);
  // The cavity's centroid is the origin, by symmetry.
  EXPECT_NEAR(norm(cavity.centroid), 0, kExact * 2);
  // Two patches per sphere: the outside and the cavity wall.
  EXPECT_EQ(a.patches.size(), 12u);
  // The same holds translated far away and with the spheres in reverse order.
  std::vector<Vec3> moved;
  for (const Vec3& x : c) moved.push_back(x + Vec3{1000, -1000, 1000});
  const std::vector<Vec3> reversed(c.rbegin(), c.rend());
  for (const auto& placement : {moved, reversed}) {
    const SphereArrangement b = arrange_spheres(placement, r);
    ASSERT_EQ(b.shells.size(), 2u);
    EXPECT_TRUE(b.shells[1].cavity());
    expect_relative(b.shells[1].volume, ref.cavity_volume, kExact, "cavity volume, moved or reversed");
    expect_relative(b.volume, ref.volume, kExact, "volume, moved or reversed");
  }
}

// A sphere that two neighbours cut in the same circle (the lower index owns it). Sphere 0
// (radius 5 at the origin) meets sphere 1 (radius 5 at x = 6) and sphere 2 (radius 8.5 at
// x = 10.5) in the same plane x = 3 ((10.5^2 + 25 - 8.5^2) / 21 = 3): sphere 0 keeps
// 2 pi 5 (5 + 3) = 80 pi whatever owns the circle.
TEST(ArrangementReference, NeighboursCuttingTheSameCircle) {
  const std::vector<Vec3> c{{0, 0, 0}, {6, 0, 0}, {10.5, 0, 0}};
  const std::vector<double> r{5, 5, 8.5};
  for (const auto& order : {std::vector<std::size_t>{0, 1, 2}, std::vector<std::size_t>{2, 1, 0},
                            std::vector<std::size_t>{1, 0, 2}}) {
    std::vector<Vec3> cc;
    std::vector<double> rr;
    for (std::size_t i : order) {
      cc.push_back(c[i]);
      rr.push_back(r[i]);
    }
    const std::size_t zero = std::find(order.begin(), order.end(), 0) - order.begin();
    const SphereArrangement a = arrange_spheres(cc, rr);
    expect_consistent(a, rr, "same circle");
    EXPECT_NEAR(a.area_per_sphere[zero], 80 * kPi, kExact * sphere_area(5));
    expect_matches_slices(a, cc, rr, "same circle");
  }
}

// n equal spheres of radius R centred on a ring of radius a: every sphere has the same area
// by symmetry, and the slices reference gives it. Tilted and shifted copies keep the
// coordinates away from the axes.
void expect_ring_symmetric_and_as_the_slices(int n, double a, double radius, bool tilted) {
  std::vector<Vec3> c;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * kPi * k / n;
    Vec3 p{a * std::cos(angle), a * std::sin(angle), 0};
    if (tilted) {  // about the axis (1, 2, 2) / 3 by 0.7 rad, then shifted
      const Vec3 u{1.0 / 3, 2.0 / 3, 2.0 / 3};
      const double cs = std::cos(0.7), sn = std::sin(0.7);
      p = p * cs + cross(u, p) * sn + u * (dot(u, p) * (1 - cs)) + Vec3{10.3, -4.1, 7.7};
    }
    c.push_back(p);
  }
  const std::vector<double> r(static_cast<std::size_t>(n), radius);
  const std::string what = "ring of " + std::to_string(n) + ", a " + std::to_string(a) + ", R " +
                           std::to_string(radius) + (tilted ? ", tilted" : "");
  const SphereArrangement arrangement = arrange_spheres(c, r);
  expect_consistent(arrangement, r, what);
  for (int k = 1; k < n; ++k)
    EXPECT_NEAR(arrangement.area_per_sphere[static_cast<std::size_t>(k)], arrangement.area_per_sphere[0],
                kExact * sphere_area(radius))
        << what << ": sphere " << k;
  // The slices converge slowly on these (1e-5 between 4000 and 8000 slices); the failures
  // below cost percents.
  const BallUnionMeasure slices = measure_ball_union(c, r, kSlices);
  EXPECT_NEAR(arrangement.area, slices.area, 1e-4 * slices.area) << what;
  EXPECT_NEAR(arrangement.volume, slices.volume, 1e-4 * slices.volume) << what;
  for (std::size_t i = 0; i < r.size(); ++i)
    EXPECT_NEAR(arrangement.area_per_sphere[i], slices.area_per_ball[i], 1e-4 * sphere_area(r[i]))
        << what << ": sphere " << i;
}

// Each sphere through (nearly) the two points on the ring's axis at height sqrt(R^2 - a^2):
// coordinates rounded to doubles put all n spheres within rounding of one point at the top
// and one at the bottom, where the exact order of the circles' ends along each circle is
// below the angles' resolution. (A rounded order once ran an exposed arc round the far side
// of a circle: rings of 5 and 6 lost 5 and 8 % of their area.)
TEST(ArrangementReference, RingsOfSpheresNearlyThroughTwoPoints) {
  struct Ring {
    double a, radius;
  };
  for (int n : {4, 5, 6, 7, 8, 9, 12})
    for (const Ring ring : {Ring{3.05, 3.1}, Ring{3.2, 4.7}, Ring{2.6, 4.5}, Ring{1.0, 1.2}})
      for (const bool tilted : {false, true}) expect_ring_symmetric_and_as_the_slices(n, ring.a, ring.radius, tilted);
}

// a = R: every sphere through the ring's centre (the probe's exact threshold for passing a
// ring of atoms), where the two points above meet and the circles of neighbouring caps are
// tangent. Their crossings' two ends lie within rounding of each other, and a rounded order
// made a touching cap's interval a whole turn or a tangent circle's exposed arc a point:
// every circle was taken as covered and every sphere as whole (a ring of 8 at 2.6 times its
// area), or half the spheres (a ring of 5 at 1.35 and 1.70 times).
TEST(ArrangementReference, RingsOfSpheresThroughTheirCentre) {
  for (int n : {4, 5, 6, 7, 8, 9, 12})
    for (const double radius : {3.248448521940434, 3.1, 1.2})
      for (const bool tilted : {false, true}) expect_ring_symmetric_and_as_the_slices(n, radius, radius, tilted);
}

}  // namespace
}  // namespace molsurf
