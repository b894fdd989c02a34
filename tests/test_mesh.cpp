#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh/icosphere.hpp"
#include "mesh_fixtures.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf {
namespace {

TEST(Mesh, CubeMeasures) {
  const Mesh cube = fixtures::box({1, 2, 3}, {3, 5, 7});
  EXPECT_DOUBLE_EQ(surface_area(cube), 2 * (2 * 3 + 3 * 4 + 2 * 4));
  EXPECT_NEAR(signed_volume(cube), 24, 1e-12);
  const BoundingBox box = bounding_box(cube);
  EXPECT_EQ(box.min, (Vec3{1, 2, 3}));
  EXPECT_EQ(box.max, (Vec3{3, 5, 7}));
  EXPECT_EQ(euler_characteristic(cube), 2);
}

TEST(Mesh, FlippedMeshHasNegativeVolume) {
  Mesh cube = fixtures::unit_cube();
  for (Triangle& t : cube.faces) std::swap(t[1], t[2]);
  EXPECT_NEAR(signed_volume(cube), -1, 1e-12);
}

TEST(Mesh, VolumeIsAccurateFarFromTheOrigin) {
  const Mesh cube = fixtures::box({1e6, 1e6, 1e6}, {1e6 + 1, 1e6 + 1, 1e6 + 1});
  EXPECT_NEAR(signed_volume(cube), 1, 1e-9);
}

TEST(Mesh, FaceNormalsPointOutOfTheCube) {
  const Mesh cube = fixtures::unit_cube();
  for (std::size_t f = 0; f < cube.face_count(); ++f) {
    const Vec3 n = face_normal(cube, f);
    const Vec3 centroid = (cube.vertices[cube.faces[f][0]] + cube.vertices[cube.faces[f][1]] +
                           cube.vertices[cube.faces[f][2]]) / 3.0;
    EXPECT_GT(dot(n, centroid - Vec3{0.5, 0.5, 0.5}), 0);
    EXPECT_NEAR(norm(n), 1, 1e-15);
  }
}

TEST(Mesh, VertexNormalsAreUnitAndOutward) {
  const Mesh sphere = make_icosphere({}, 2, {.frequency = 3});
  const auto normals = vertex_normals(sphere);
  ASSERT_EQ(normals.size(), sphere.vertex_count());
  for (std::size_t v = 0; v < normals.size(); ++v) {
    EXPECT_NEAR(norm(normals[v]), 1, 1e-12);
    EXPECT_GT(dot(normals[v], sphere.vertices[v]), 0.99 * 2);
  }
}

TEST(Mesh, AppendOffsetsIndicesAndKeepsTags) {
  Mesh a = fixtures::tetrahedron();
  const Mesh b = make_icosphere({5, 0, 0}, 1, {.frequency = 1, .tag = 7});
  a.append(b);
  EXPECT_EQ(a.vertex_count(), 4u + 12u);
  EXPECT_EQ(a.face_count(), 4u + 20u);
  ASSERT_TRUE(a.has_tags());
  EXPECT_EQ(a.tag(0), kNoTag);
  EXPECT_EQ(a.tag(4), 7);
  EXPECT_EQ(a.faces[4][0], b.faces[0][0] + 4);
  const Components c = connected_components(a);
  EXPECT_EQ(c.count, 2u);
  EXPECT_EQ(c.face_component[0], 0u);
  EXPECT_EQ(c.face_component[10], 1u);
  EXPECT_EQ(euler_characteristic(a), 4);  // two spheres
}

TEST(Mesh, ComponentsJoinThroughASharedVertexOnly) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {5, 5, 5}, {6, 5, 5}, {5, 6, 5}};
  m.faces = {{0, 1, 2}, {0, 3, 4}, {5, 6, 7}};
  const Components c = connected_components(m);
  EXPECT_EQ(c.count, 2u);
  EXPECT_EQ(c.face_component[1], 0u);
  EXPECT_EQ(c.face_component[2], 1u);
}

TEST(Mesh, QualityOfEquilateralAndSliverTriangles) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}, {2, 0, 0}, {3, 0, 0}, {2.5, 0.001, 0}};
  m.faces = {{0, 1, 2}, {3, 4, 5}};
  EXPECT_NEAR(min_angle_deg(m, 0), 60, 1e-12);
  EXPECT_NEAR(aspect_ratio(m, 0), 1, 1e-12);
  EXPECT_NEAR(min_angle_deg(m, 1), std::atan(0.001 / 0.5) * 180 / std::numbers::pi, 1e-9);
  const Quality q = mesh_quality(m);
  EXPECT_EQ(q.faces, 2u);
  EXPECT_EQ(q.below_1deg, 1u);
  EXPECT_EQ(q.below_5deg, 1u);
  EXPECT_GT(q.max_aspect_ratio, 100);
  EXPECT_NEAR(q.min_angle_deg, min_angle_deg(m, 1), 1e-12);
}

TEST(Mesh, DegenerateFaceHasInfiniteAspectRatio) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  m.faces = {{0, 1, 2}};
  EXPECT_TRUE(std::isinf(aspect_ratio(m, 0)));
  EXPECT_EQ(face_normal(m, 0), (Vec3{}));
}

}  // namespace
}  // namespace molsurf
