// Vertices moved toward targets as far as validity allows (src/mesh/move_vertices.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "mesh/icosphere.hpp"
#include "mesh/move_vertices.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/mesh_check.hpp"

namespace molsurf {
namespace {

double smallest_angle(const Mesh& mesh) {
  double smallest = 180;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) smallest = std::min(smallest, min_angle_deg(mesh, f));
  return smallest;
}

TEST(MoveVertices, MovesThatKeepTheMeshValidAreMadeWhole) {
  Mesh mesh = make_icosphere({0, 0, 0}, 1, {.frequency = 4});
  const std::size_t n = mesh.vertices.size();
  std::vector<Vec3> target(n);
  std::vector<std::uint8_t> has(n, 1);
  for (std::size_t v = 0; v < n; ++v) target[v] = mesh.vertices[v] * 1.01;  // onto a slightly larger sphere
  const TruePointStats s = move_vertices_toward(mesh, target, has, 5);
  EXPECT_EQ(s.vertices, n);
  EXPECT_EQ(s.on_true_point, n);
  for (std::size_t v = 0; v < n; ++v) EXPECT_EQ(mesh.vertices[v], target[v]);
  EXPECT_TRUE(check_mesh(mesh).valid());
}

TEST(MoveVertices, AMoveThroughTheOtherSideOrIntoASliverIsRefused) {
  Mesh mesh = make_icosphere({0, 0, 0}, 1, {.frequency = 3});
  const std::size_t n = mesh.vertices.size();
  const double angle_before = smallest_angle(mesh);
  std::vector<Vec3> target(n);
  std::vector<std::uint8_t> has(n, 0);
  // Vertex 0 through the sphere to beyond the far side: its faces would turn over and
  // cross the far faces, even halfway (at the centre).
  target[0] = mesh.vertices[0] * -1.5;
  has[0] = 1;
  // Vertex 1 onto a neighbour but for a hair: its faces would become slivers.
  const Triangle* around = nullptr;
  for (const Triangle& t : mesh.faces)
    if (t[0] == 1 || t[1] == 1 || t[2] == 1) around = &t;
  ASSERT_NE(around, nullptr);
  const Index neighbour = (*around)[0] == 1 ? (*around)[1] : (*around)[0];
  ASSERT_NE(neighbour, Index{0});
  target[1] = mesh.vertices[neighbour] + (mesh.vertices[1] - mesh.vertices[neighbour]) * 1e-3;
  has[1] = 1;
  const Vec3 first = mesh.vertices[0];
  const TruePointStats s = move_vertices_toward(mesh, target, has, 5);
  EXPECT_EQ(s.on_true_point, 0u);
  EXPECT_EQ(s.partly + s.not_moved, n);  // the others had no target
  EXPECT_NE(mesh.vertices[0], target[0]);
  EXPECT_GT(dot(mesh.vertices[0], first), 0);  // not past the centre
  EXPECT_TRUE(check_mesh(mesh).valid());
  EXPECT_GE(smallest_angle(mesh), std::min(5.0, angle_before) - 1e-9);
}

}  // namespace
}  // namespace molsurf
