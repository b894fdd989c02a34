#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "molsurf/mesh_check.hpp"
#include "support/shapes.hpp"

namespace molsurf {
namespace {

constexpr double kPi = std::numbers::pi;

void expect_valid(const Mesh& m, long euler) {
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.valid()) << ::testing::PrintToString(c.defects());
  EXPECT_EQ(c.euler_characteristic, euler);
  EXPECT_EQ(c.components, 1u);
}

TEST(Shapes, GridBox) {
  const Mesh box = make_box({0, 0, 0}, {2, 3, 4}, 4, 5, 6);
  EXPECT_EQ(box.face_count(), 2u * 2 * (4 * 5 + 5 * 6 + 4 * 6));
  EXPECT_NEAR(signed_volume(box), 24, 1e-12);
  EXPECT_NEAR(surface_area(box), 2 * (6 + 12 + 8), 1e-12);
  expect_valid(box, 2);
}

TEST(Shapes, UvSphereWithThePapersFaceCount) {
  const Mesh s = make_uv_sphere({1, 1, 1}, 2, 41, 38);
  EXPECT_EQ(s.face_count(), 3034u);
  EXPECT_NEAR(signed_volume(s), 4.0 / 3 * kPi * 8, 0.02 * 4.0 / 3 * kPi * 8);
  expect_valid(s, 2);
}

TEST(Shapes, CappedCylinderAlongAnyAxis) {
  const Mesh c = make_capped_cylinder({0, 0, 0}, {1, 2, 3}, 1.5, 6, 100, 40);
  EXPECT_EQ(c.face_count(), 8200u);
  const double exact = kPi * 1.5 * 1.5 * 6;
  EXPECT_NEAR(signed_volume(c), exact, 0.01 * exact);
  expect_valid(c, 2);
}

TEST(Shapes, ChannelIsAGenusOneSolid) {
  const Mesh ch = make_channel(4, 2, 10, 8, 3);
  EXPECT_NEAR(signed_volume(ch), (16 - 4) * 10, 1e-9);
  expect_valid(ch, 0);
}

TEST(Shapes, RigidTransformKeepsVolumeAndValidity) {
  const Mesh box = make_box({0, 0, 0}, {1, 2, 3}, 2, 2, 2);
  const Mesh moved = transformed(box, {.axis = {1, 1, 0}, .angle = 0.7, .translation = {5, -2, 1}});
  EXPECT_NEAR(signed_volume(moved), 6, 1e-12);
  expect_valid(moved, 2);
  const Vec3 p = RigidTransform{.axis = {0, 0, 1}, .angle = kPi / 2}.apply({1, 0, 0});
  EXPECT_NEAR(p.x, 0, 1e-15);
  EXPECT_NEAR(p.y, 1, 1e-15);
}

TEST(Shapes, RejectBadParameters) {
  EXPECT_THROW(make_box({0, 0, 0}, {1, 1, 1}, 0), std::invalid_argument);
  EXPECT_THROW(make_uv_sphere({}, 1, 2, 5), std::invalid_argument);
  EXPECT_THROW(make_channel(1, 2, 1, 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace molsurf
