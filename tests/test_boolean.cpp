#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "boolean_invariants.hpp"
#include "mesh/icosphere.hpp"
#include "mesh_fixtures.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "support/shapes.hpp"

namespace molsurf {
namespace {

::testing::AssertionResult valid(const Mesh& m) { return testing::valid_surface(m); }

struct Volumes {
  double a, b, uni, inter, diff;
};

// Runs the three operations, checks each result, and returns their volumes.
Volumes run_all(const Mesh& a, const Mesh& b) {
  Volumes v{signed_volume(a), signed_volume(b), 0, 0, 0};
  const BooleanResult u = boolean(a, b, BooleanOp::union_);
  const BooleanResult i = boolean(a, b, BooleanOp::intersection);
  const BooleanResult d = boolean(a, b, BooleanOp::difference);
  EXPECT_TRUE(testing::valid_or_only_touching(u.mesh)) << "union";
  EXPECT_TRUE(testing::valid_or_only_touching(i.mesh)) << "intersection";
  EXPECT_TRUE(testing::valid_or_only_touching(d.mesh)) << "difference";
  v.uni = signed_volume(u.mesh);
  v.inter = signed_volume(i.mesh);
  v.diff = signed_volume(d.mesh);
  return v;
}

void expect_volume_identities(const Volumes& v) {
  const double scale = std::max(v.a, v.b);
  EXPECT_NEAR(v.uni + v.inter, v.a + v.b, 1e-9 * scale);
  EXPECT_NEAR(v.diff, v.a - v.inter, 1e-9 * scale);
}

TEST(Boolean, OverlappingSpheres) {
  const Mesh a = make_icosphere({0, 0, 0}, 1.0, {.frequency = 6, .tag = 1});
  const Mesh b = make_icosphere({0.9, 0.31, 0.17}, 0.8, {.frequency = 5, .tag = 2});
  const Volumes v = run_all(a, b);
  expect_volume_identities(v);
  EXPECT_GT(v.inter, 0);
  EXPECT_LT(v.uni, v.a + v.b);
  const BooleanResult u = boolean(a, b, BooleanOp::union_);
  EXPECT_GT(u.stats.intersection_points, 0u);
  ASSERT_EQ(u.mesh.face_tags.size(), u.mesh.face_count());
  ASSERT_EQ(u.face_operand.size(), u.mesh.face_count());
  for (std::size_t f = 0; f < u.mesh.face_count(); ++f) EXPECT_EQ(u.mesh.face_tags[f], u.face_operand[f] + 1);
}

// Coordinates of wildly different magnitudes: every exact coordinate 0 of two crossing
// icospheres becomes +-1e-200 (a shift far below any rounding). Exact predicates on
// those points need integers of thousands of bits: the double expansions' range guard
// and the inline integers' capacity both refuse them, and GMP must take over.
TEST(Boolean, TinyCoordinatesTakeTheGmpPaths) {
  auto with_tiny_zeros = [](Mesh m) {
    int changed = 0;
    for (Vec3& v : m.vertices)
      for (int axis = 0; axis < 3; ++axis) {
        double& c = axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
        if (c == 0) {
          c = (changed++ % 2 == 0) ? 1e-200 : -1e-200;
        }
      }
    EXPECT_GT(changed, 0);
    return m;
  };
  const Mesh a = with_tiny_zeros(make_icosphere({0, 0, 0}, 1.0, {.frequency = 4}));
  const Mesh b = with_tiny_zeros(make_icosphere({0, 0, 0}, 0.9, {.frequency = 3}));
  // Shift b by a dyadic amount so that its exact zeros stay tiny but the spheres cross.
  Mesh shifted = b;
  for (Vec3& v : shifted.vertices) v.x += 0.5;
  ASSERT_TRUE(valid(a));
  ASSERT_TRUE(valid(shifted));
  const Volumes v = run_all(a, shifted);
  expect_volume_identities(v);
  EXPECT_GT(v.inter, 0);
}

TEST(Boolean, DisjointSolids) {
  const Mesh a = make_icosphere({0, 0, 0}, 1.0, {.frequency = 3});
  const Mesh b = make_icosphere({5, 0, 0}, 1.0, {.frequency = 3});
  const BooleanResult u = boolean(a, b, BooleanOp::union_);
  EXPECT_EQ(u.mesh.face_count(), a.face_count() + b.face_count());
  EXPECT_TRUE(valid(u.mesh));
  const BooleanResult i = boolean(a, b, BooleanOp::intersection);
  EXPECT_EQ(i.mesh.face_count(), 0u);
  EXPECT_TRUE(valid(i.mesh));
  const BooleanResult d = boolean(a, b, BooleanOp::difference);
  EXPECT_EQ(d.mesh.face_count(), a.face_count());
}

TEST(Boolean, OneInsideTheOther) {
  const Mesh outer = make_icosphere({0, 0, 0}, 2.0, {.frequency = 4});
  const Mesh inner = make_icosphere({0.1, 0.2, 0.05}, 0.5, {.frequency = 3});
  EXPECT_EQ(boolean(outer, inner, BooleanOp::union_).mesh.face_count(), outer.face_count());
  EXPECT_EQ(boolean(outer, inner, BooleanOp::intersection).mesh.face_count(), inner.face_count());
  const BooleanResult cavity = boolean(outer, inner, BooleanOp::difference);
  EXPECT_EQ(cavity.mesh.face_count(), outer.face_count() + inner.face_count());
  EXPECT_TRUE(valid(cavity.mesh));
  EXPECT_NEAR(signed_volume(cavity.mesh), signed_volume(outer) - signed_volume(inner), 1e-12);
}

TEST(Boolean, IdenticalMeshes) {
  const Mesh a = make_icosphere({0.5, 0, 0}, 1.0, {.frequency = 4});
  const Volumes v = run_all(a, a);
  EXPECT_NEAR(v.uni, v.a, 1e-12);
  EXPECT_NEAR(v.inter, v.a, 1e-12);
  EXPECT_NEAR(v.diff, 0, 1e-12);
}

TEST(Boolean, CubesSharingPartOfAFace) {
  const Mesh a = make_box({0, 0, 0}, {2, 2, 2});
  const Mesh b = make_box({1, 1, 2}, {3, 3, 4});  // sits on a's top face, overlapping a quarter of it
  const Volumes v = run_all(a, b);
  EXPECT_NEAR(v.uni, 16, 1e-12);
  EXPECT_NEAR(v.inter, 0, 1e-12);
  EXPECT_NEAR(v.diff, 8, 1e-12);
}

TEST(Boolean, OverlappingCubesWithCoplanarFaces) {
  const Mesh a = make_box({0, 0, 0}, {2, 2, 2}, 2, 2, 2);
  const Mesh b = make_box({1, 1, 0}, {3, 3, 2}, 3, 3, 1);  // same bottom and top planes
  const Volumes v = run_all(a, b);
  EXPECT_NEAR(v.uni, 14, 1e-12);
  EXPECT_NEAR(v.inter, 2, 1e-12);
  EXPECT_NEAR(v.diff, 6, 1e-12);
}

TEST(Boolean, SphereAgainstARotatedCopy) {
  const Mesh a = make_icosphere({0, 0, 0}, 1.0, {.frequency = 5});
  const Mesh b = transformed(a, {.axis = {0.3, 0.5, 0.8}, .angle = 1e-12});
  const Volumes v = run_all(a, b);
  expect_volume_identities(v);
}

TEST(Boolean, TouchingAtOneVertex) {
  const Mesh a = make_box({0, 0, 0}, {1, 1, 1});
  const Mesh b = make_box({1, 1, 1}, {2, 2, 2});
  const BooleanResult u = boolean(a, b, BooleanOp::union_);
  // The sheets kept apart, touching at the corner: a contact, so the result is refused.
  EXPECT_TRUE(testing::valid_or_only_touching(u.mesh));
  EXPECT_GT(check_mesh(u.mesh).contact_pairs, 0u);
  EXPECT_EQ(u.mesh.face_count(), 24u);
  EXPECT_EQ(u.stats.split_vertices, 1u);
  EXPECT_NEAR(signed_volume(u.mesh), 2, 1e-12);
}

TEST(Boolean, TouchingAlongAnEdge) {
  const Mesh a = make_box({0, 0, 0}, {1, 1, 1});
  const Mesh b = make_box({1, 1, 0}, {2, 2, 1});
  const BooleanResult u = boolean(a, b, BooleanOp::union_);
  EXPECT_TRUE(testing::valid_or_only_touching(u.mesh));
  EXPECT_GT(check_mesh(u.mesh).contact_pairs, 0u);
  EXPECT_NEAR(signed_volume(u.mesh), 2, 1e-12);
}

TEST(Boolean, TunnelTouchingTheOuterFaceAlongAnEdge) {
  // A diamond prism through a cube, its top edge lying on the cube's top face: carving it
  // out leaves a tunnel whose ridge touches the top face from inside. Along the ridge four
  // faces meet, and at its ends (on the cube's sides) the sheets join, so the pairs that
  // bound material (one face of each operand) must be found by their order around the edge.
  const Mesh cube = make_box({0, 0, 0}, {4, 4, 4});
  Mesh prism = make_box({0, 0, 0}, {1, 1, 1});
  for (Vec3& v : prism.vertices) v = Vec3{-1, 2, 2} + v.x * Vec3{6, 0, 0} + v.y * Vec3{0, 1, 1} + v.z * Vec3{0, -1, 1};
  ASSERT_NEAR(signed_volume(prism), 12, 1e-12);
  const BooleanResult carved = boolean(cube, prism, BooleanOp::difference);
  EXPECT_TRUE(testing::valid_or_only_touching(carved.mesh));
  EXPECT_GT(check_mesh(carved.mesh).contact_pairs, 0u);  // the ridge touches the top face
  EXPECT_NEAR(signed_volume(carved.mesh), 64 - 8, 1e-12);
  EXPECT_GT(carved.stats.split_vertices, 0u);
  const Volumes v = run_all(cube, prism);
  EXPECT_NEAR(v.uni, 64 + 4, 1e-12);
  EXPECT_NEAR(v.inter, 8, 1e-12);
}

TEST(Boolean, RoundingFoldAtANearTripleJunction) {
  // Two partial surfaces from 7cth's merge tree (level 5) whose union has four intersection
  // points within 1e-7 A of each other: rounding folded slivers there until the repair
  // learned to clear such clusters.
  const std::string dir = std::string(MOLSURF_DATA_DIR) + "/../tests/data/boolean/";
  const Mesh a = read_mesh(dir + "7cth_level5_a.ply"), b = read_mesh(dir + "7cth_level5_b.ply");
  ASSERT_TRUE(valid(a));
  ASSERT_TRUE(valid(b));
  EXPECT_TRUE(valid(boolean(a, b, BooleanOp::union_).mesh));
}

TEST(Boolean, AnEngineErrorInAParallelStepIsAnExceptionNotAnAbort) {
  // Two convex cells from an experiment that clipped spheres with rounded plane cuts; b
  // intersects itself, so no Boolean is defined (the CLI refuses it), and the advancing
  // front gave up on it inside split's parallel loop. That used to call std::terminate;
  // the library must report it as an exception (or cope), never abort.
  const std::string dir = std::string(MOLSURF_DATA_DIR) + "/../tests/data/boolean/";
  const Mesh a = read_mesh(dir + "clipped_cells_a.ply"), b = read_mesh(dir + "clipped_cells_b.ply");
  ASSERT_TRUE(valid(a));
  ASSERT_FALSE(valid(b));
  try {
    boolean(a, b, BooleanOp::union_);
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()), "");
  }
}

}  // namespace
}  // namespace molsurf
