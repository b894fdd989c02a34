#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "mesh/icosphere.hpp"

namespace molsurf {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Icosphere, CountsFollowTheFrequency) {
  for (int n = 1; n <= 12; ++n) {
    const Mesh m = make_icosphere({}, 1.0, {.frequency = n});
    EXPECT_EQ(m.face_count(), 20u * n * n) << n;
    EXPECT_EQ(m.vertex_count(), 10u * n * n + 2) << n;
    EXPECT_EQ(euler_characteristic(m), 2) << n;
    EXPECT_EQ(connected_components(m).count, 1u) << n;
  }
}

TEST(Icosphere, EveryEdgeHasTwoOppositelyOrientedFaces) {
  for (int n : {1, 2, 5, 9}) {
    const Mesh m = make_icosphere({1, 2, 3}, 2.5, {.frequency = n});
    std::map<std::pair<Index, Index>, int> directed;
    for (const Triangle& t : m.faces)
      for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
    for (const auto& [edge, count] : directed) {
      EXPECT_EQ(count, 1);
      EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
    }
  }
}

// Inscribed: the corners lie just inside the sphere (2^-30 of the radius and 2^-48 of the
// coordinates in), so that the polyhedra of tangent spheres do not touch.
TEST(Icosphere, VerticesLieJustInsideTheSphereAndFacesPointOutward) {
  const Vec3 centre{-4, 0.5, 10};
  const Mesh m = make_icosphere(centre, 3.2, {.frequency = 6});
  for (const Vec3& v : m.vertices) {
    EXPECT_LT(norm(v - centre), 3.2);
    EXPECT_NEAR(norm(v - centre), 3.2 * (1 - std::ldexp(1.0, -30)), 1e-12);
  }
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const Vec3 centroid = (m.vertices[m.faces[f][0]] + m.vertices[m.faces[f][1]] + m.vertices[m.faces[f][2]]) / 3.0;
    EXPECT_GT(dot(face_normal(m, f), centroid - centre), 0) << f;
  }
  EXPECT_GT(signed_volume(m), 0);
}

TEST(Icosphere, AreaAndVolumeConvergeToTheSphere) {
  double previous_area_error = 1;
  for (int n : {1, 2, 4, 8, 16, 32}) {
    const Mesh m = make_icosphere({}, 1.0, {.frequency = n});
    const double area_error = std::abs(surface_area(m) - 4 * kPi) / (4 * kPi);
    EXPECT_LT(area_error, previous_area_error) << n;
    previous_area_error = area_error;
  }
  EXPECT_LT(previous_area_error, 1e-3);
  const Mesh fine = make_icosphere({}, 2.0, {.frequency = 32});
  EXPECT_NEAR(signed_volume(fine), 4.0 / 3 * kPi * 8, 4.0 / 3 * kPi * 8 * 2e-3);
}

TEST(Icosphere, AreaCorrectionMatchesTheSphereArea) {
  for (int n : {1, 3, 5}) {
    const Mesh m = make_icosphere({}, 1.7, {.frequency = n, .area_corrected = true});
    EXPECT_NEAR(surface_area(m), 4 * kPi * 1.7 * 1.7, 1e-9) << n;
    const Mesh plain = make_icosphere({}, 1.7, {.frequency = n});
    EXPECT_LT(surface_area(plain), surface_area(m)) << n;
  }
}

TEST(Icosphere, TagsEveryFace) {
  const Mesh tagged = make_icosphere({}, 1.0, {.frequency = 2, .tag = 42});
  ASSERT_EQ(tagged.face_tags.size(), tagged.face_count());
  for (auto t : tagged.face_tags) EXPECT_EQ(t, 42);
  EXPECT_FALSE(make_icosphere({}, 1.0, {.frequency = 2}).has_tags());
}

TEST(Icosphere, FrequencyFromDensityIsNearestVertexCount) {
  // r = 3.28 (carbon 1.88 + probe 1.4), density 2/A^2: 4 pi r^2 * 2 = 270 vertices -> n = 5 (252).
  EXPECT_EQ(frequency_for_density(3.28, 2.0), 5);
  EXPECT_EQ(frequency_for_density(0.1, 1.0), 1);
  for (double r : {1.0, 2.5, 3.3, 10.0})
    for (double d : {0.5, 1.0, 2.0, 4.0, 10.0}) {
      const int n = frequency_for_density(r, d);
      const double target = d * 4 * kPi * r * r;
      const double here = std::abs(10.0 * n * n + 2 - target);
      EXPECT_LE(here, std::abs(10.0 * (n + 1) * (n + 1) + 2 - target));
      if (n > 1) EXPECT_LE(here, std::abs(10.0 * (n - 1) * (n - 1) + 2 - target));
    }
}

TEST(Icosphere, RejectsBadParameters) {
  EXPECT_THROW(make_icosphere({}, 1.0, {.frequency = 0}), std::invalid_argument);
  EXPECT_THROW(make_icosphere({}, 0.0, {.frequency = 1}), std::invalid_argument);
}

}  // namespace
}  // namespace molsurf
