// Polygon faces of mesh files as triangles: convex ones fanned, concave ones ear-clipped,
// so that a valid solid with an L-shaped face reads as a valid mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "geometry/predicates.hpp"
#include "mesh/polygon_triangulation.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"

namespace molsurf {
namespace {

// An L-shaped prism: caps of six corners (concave at (1, 1)), six quads around.
std::string l_prism_off() {
  const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  std::string off = "OFF\n12 8 0\n";
  for (const double z : {0.0, 1.0})
    for (const auto& p : xy) off += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(z) + "\n";
  off += "6 5 4 3 2 1 0\n6 6 7 8 9 10 11\n";  // bottom seen from below, top from above
  for (int i = 0; i < 6; ++i) {
    const int j = (i + 1) % 6;
    off += "4 " + std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(j + 6) + " " +
           std::to_string(i + 6) + "\n";
  }
  return off;
}

// Issue 34: the bottom cap fanned from its first corner folded over the notch, and the
// check called a valid prism invalid.
TEST(PolygonTriangulation, AnLShapedPrismReadsAsAValidSolid) {
  testing::TempDir dir;
  const auto file = dir.path() / "l.off";
  std::ofstream(file) << l_prism_off();
  const Mesh mesh = read_mesh(file);
  EXPECT_EQ(mesh.face_count(), 2u * 4 + 6 * 2);
  const MeshCheck check = check_mesh(mesh);
  EXPECT_TRUE(check.valid()) << check.defects().front();
  EXPECT_DOUBLE_EQ(check.volume, 3.0);
  EXPECT_DOUBLE_EQ(check.area, 2 * 3.0 + 8.0);
}

// Seen along z, every triangle of a polygon turns as the polygon does and the triangles'
// areas add up to the polygon's (shoelace): no fold, no overlap.
void expect_tiles(const std::vector<Vec3>& vertices, const std::vector<Index>& corners, int turn) {
  const std::vector<Triangle> triangles = triangulate_polygon(vertices, corners);
  ASSERT_EQ(triangles.size(), corners.size() - 2);
  double polygon = 0, sum = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3 &p = vertices[corners[i]], &q = vertices[corners[(i + 1) % corners.size()]];
    polygon += p.x * q.y - q.x * p.y;
  }
  for (const Triangle& t : triangles) {
    const Vec3 &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
    EXPECT_EQ(geometry::orient2d(a.x, a.y, b.x, b.y, c.x, c.y), turn);
    sum += (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  }
  EXPECT_NEAR(sum, polygon, 1e-9 * std::fabs(polygon));
}

TEST(PolygonTriangulation, ConcaveCombsTileInEitherTurn) {
  // A comb: teeth along x, open upwards; its first corner sees none of the teeth's tips.
  std::vector<Vec3> vertices{{0, 0, 0}, {20, 0, 0}};
  for (int k = 9; k >= 0; --k) {
    vertices.push_back({2.0 * k + 2, 3, 0});
    vertices.push_back({2.0 * k + 1.5, 3, 0});
    vertices.push_back({2.0 * k + 1.5, 1, 0});
    vertices.push_back({2.0 * k + 0.5, 1, 0});
  }
  std::vector<Index> corners(vertices.size());
  for (std::size_t i = 0; i < corners.size(); ++i) corners[i] = static_cast<Index>(i);
  expect_tiles(vertices, corners, 1);
  std::vector<Index> reversed(corners.rbegin(), corners.rend());
  expect_tiles(vertices, reversed, -1);
}

// A convex polygon is cut by halving: n - 2 triangles that tile it, and none of them spans
// more than a third of the corners (a fan's would span all).
TEST(PolygonTriangulation, AConvexPolygonIsCutByHalving) {
  std::vector<Vec3> vertices;
  std::vector<Index> corners;
  for (int k = 0; k < 1000; ++k) {
    const double angle = 2 * std::numbers::pi * k / 1000;
    vertices.push_back({std::cos(angle), std::sin(angle), 0.5});
    corners.push_back(static_cast<Index>(k));
  }
  expect_tiles(vertices, corners, 1);
  std::size_t at_first_corner = 0;
  for (const Triangle& t : triangulate_polygon(vertices, corners))
    at_first_corner += t[0] == 0 || t[1] == 0 || t[2] == 0;
  EXPECT_LT(at_first_corner, 30u);
}

// Issue 34: a valid prism whose caps are 100 000-gons took minutes to check: fanned, every
// cap triangle shared the fan's first corner (so every pair had overlapping boxes) and
// reached across the cap (so every side face's box met half of them). Cut by halving, the
// exact tests made stay a small multiple of the faces (the old count: billions).
TEST(PolygonTriangulation, APrismWithAHugePolygonCapIsCheckedInNearLinearWork) {
  testing::TempDir dir;
  const int n = 100'000;
  std::string off = "OFF\n" + std::to_string(2 * n) + " " + std::to_string(n + 2) + " 0\n";
  char line[96];
  for (const double z : {0.0, 1.0})
    for (int k = 0; k < n; ++k) {
      const double angle = 2 * std::numbers::pi * k / n;
      std::snprintf(line, sizeof line, "%.17g %.17g %g\n", 10 * std::cos(angle), 10 * std::sin(angle), z);
      off += line;
    }
  off += std::to_string(n);
  for (int k = n - 1; k >= 0; --k) off += " " + std::to_string(k);
  off += "\n" + std::to_string(n);
  for (int k = 0; k < n; ++k) off += " " + std::to_string(n + k);
  off += "\n";
  for (int k = 0; k < n; ++k)
    off += "4 " + std::to_string(k) + " " + std::to_string((k + 1) % n) + " " + std::to_string((k + 1) % n + n) + " " +
           std::to_string(k + n) + "\n";
  const auto file = dir.path() / "prism.off";
  std::ofstream(file) << off;
  const Mesh mesh = read_mesh(file);
  ASSERT_EQ(mesh.face_count(), 2u * (n - 2) + 2u * n);
  const MeshCheck check = check_mesh(mesh);
  EXPECT_TRUE(check.valid());
  EXPECT_LT(check.pairs_tested, 40 * mesh.face_count()) << check.pairs_tested;
}

}  // namespace
}  // namespace molsurf
