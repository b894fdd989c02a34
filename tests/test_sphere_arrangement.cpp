// The arrangement's structure: vertices, arcs, patches and shells, and their consistency
// (the values against independent references: test_sphere_arrangement_reference.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "arrangement/sphere_arrangement.hpp"
#include "arrangement_invariants.hpp"
#include "degenerate_placements.hpp"
#include "support/ball_union.hpp"

namespace molsurf {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SphereArrangement, TwoSpheresShareOneWholeCircle) {
  const std::vector<Vec3> c{{0, 0, 0}, {1.5, 0.25, -0.5}};
  const std::vector<double> r{1.3, 1.1};
  const SphereArrangement a = arrange_spheres(c, r);
  ASSERT_EQ(a.arcs.size(), 2u);
  EXPECT_TRUE(a.vertices.empty());
  for (const ArrangementArc& arc : a.arcs) {
    EXPECT_EQ(arc.from, -1);
    EXPECT_NEAR(arc.angle, 2 * kPi, 1e-15);
  }
  EXPECT_EQ(a.arcs[0].other, 1u);
  EXPECT_EQ(a.arcs[1].other, 0u);
  ASSERT_EQ(a.patches.size(), 2u);
  ASSERT_EQ(a.shells.size(), 1u);
  EXPECT_EQ(a.shells[0].spheres, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_NEAR(a.shells[0].area, a.area, 1e-12 * a.area);
  EXPECT_NEAR(a.shells[0].volume, a.volume, 1e-12 * a.volume);
}

TEST(SphereArrangement, ThreeSpheresMeetAtTwoVertices) {
  const std::vector<Vec3> c{{0, 0, 0}, {1.6, 0, 0}, {0.8, 1.3, 0.1}};
  const std::vector<double> r{1.2, 1.1, 1.25};
  const SphereArrangement a = arrange_spheres(c, r);
  ASSERT_EQ(a.vertices.size(), 2u);
  EXPECT_EQ(a.vertices[0].spheres, (std::array<std::uint32_t, 3>{0, 1, 2}));
  EXPECT_NE(a.vertices[0].side, a.vertices[1].side);
  for (const ArrangementVertex& v : a.vertices)
    for (int s = 0; s < 3; ++s) EXPECT_NEAR(norm(v.point - c[s]), r[s], 1e-12);
  // Each sphere: two arcs from vertex to vertex; every vertex ends one arc and starts one
  // on each of its three spheres.
  ASSERT_EQ(a.arcs.size(), 6u);
  std::vector<int> starts(2, 0), ends(2, 0);
  for (const ArrangementArc& arc : a.arcs) {
    ASSERT_GE(arc.from, 0);
    ASSERT_GE(arc.to, 0);
    ++starts[arc.from];
    ++ends[arc.to];
  }
  EXPECT_EQ(starts, (std::vector<int>{3, 3}));
  EXPECT_EQ(ends, (std::vector<int>{3, 3}));
  EXPECT_EQ(a.shells.size(), 1u);
}

// Spheres on the six axes around an empty centre enclose a cavity.
std::vector<Vec3> octahedron(double d) {
  return {{d, 0, 0}, {-d, 0, 0}, {0, d, 0}, {0, -d, 0}, {0, 0, d}, {0, 0, -d}};
}

TEST(SphereArrangement, SixSpheresEncloseOneCavity) {
  const std::vector<Vec3> c = octahedron(2);
  const std::vector<double> r(6, 1.8);  // neighbours 2.83 apart overlap; the centre is 2 from each
  const SphereArrangement a = arrange_spheres(c, r);
  ASSERT_EQ(a.shells.size(), 2u);
  EXPECT_FALSE(a.shells[0].cavity());
  EXPECT_TRUE(a.shells[1].cavity());
  EXPECT_EQ(a.shells[1].spheres.size(), 6u);
  EXPECT_NEAR(norm(a.shells[1].centroid), 0, 1e-9);
  // Each sphere has two patches: one outside, one lining the cavity.
  EXPECT_EQ(a.patches.size(), 12u);
  double shells_area = 0, shells_volume = 0;
  for (const ArrangementShell& s : a.shells) {
    shells_area += s.area;
    shells_volume += s.volume;
  }
  EXPECT_NEAR(shells_area, a.area, 1e-12 * a.area);
  EXPECT_NEAR(shells_volume, a.volume, 1e-12 * a.volume);
  const BallUnionMeasure slices = measure_ball_union(c, r, 8000);
  EXPECT_NEAR(a.area, slices.area, 2e-5 * a.area);
}

TEST(SphereArrangement, PatchesSumToTheSphereArea) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pos(0, 6), rad(1.0, 2.2);
  std::vector<Vec3> c;
  std::vector<double> r;
  for (int k = 0; k < 60; ++k) {
    c.push_back({pos(rng), pos(rng), pos(rng)});
    r.push_back(rad(rng));
  }
  const SphereArrangement a = arrange_spheres(c, r);
  std::vector<double> by_patch(c.size(), 0);
  for (const ArrangementPatch& p : a.patches) by_patch[p.sphere] += p.area;
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_NEAR(by_patch[i], a.area_per_sphere[i], 1e-9 * r[i] * r[i]);
  const BallUnionMeasure slices = measure_ball_union(c, r, 4000);
  EXPECT_NEAR(a.area, slices.area, 1e-4 * a.area);
  EXPECT_NEAR(a.volume, slices.volume, 1e-4 * a.volume);
}

TEST(SphereArrangement, SameBitsOnAnyThreadCount) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(0, 12), rad(1.0, 2.2);
  std::vector<Vec3> c;
  std::vector<double> r;
  for (int k = 0; k < 400; ++k) {
    c.push_back({pos(rng), pos(rng), pos(rng)});
    r.push_back(rad(rng));
  }
  const SphereArrangement one = arrange_spheres(c, r, {.threads = 1});
  const SphereArrangement two = arrange_spheres(c, r, {.threads = 2});
  EXPECT_EQ(one.area, two.area);
  EXPECT_EQ(one.volume, two.volume);
  EXPECT_EQ(one.area_per_sphere, two.area_per_sphere);
  EXPECT_EQ(one.vertices.size(), two.vertices.size());
  EXPECT_EQ(one.shells.size(), two.shells.size());
}

// A few seeds of each degenerate family here; the long battery runs a hundred each.
TEST(SphereArrangement, DegeneratePlacementsAreSound) {
  for (const testing::PlacementFamily family : testing::kAllPlacementFamilies)
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
      const testing::DegeneratePlacement p = testing::degenerate_placement(family, seed);
      for (const double probe : {0.0, 1.4})
        testing::expect_arrangement_sound(p.atoms, probe,
                                          p.family + " seed " + std::to_string(seed) + ", probe " + std::to_string(probe));
    }
}

TEST(SphereArrangement, RefusesBadSpheres) {
  const std::vector<Vec3> c{{0, 0, 0}};
  EXPECT_THROW(arrange_spheres(c, std::vector<double>{-1}), std::invalid_argument);
  EXPECT_THROW(arrange_spheres(c, std::vector<double>{NAN}), std::invalid_argument);
  EXPECT_THROW(arrange_spheres(c, std::vector<double>{}), std::invalid_argument);
}

}  // namespace
}  // namespace molsurf
