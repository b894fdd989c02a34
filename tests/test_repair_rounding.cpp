// The rounding repair (the stitch's last part, repair_rounding.hpp) on its own: closed
// meshes made degenerate the way rounding makes them (two points at one position, a
// point on the opposite edge of its face), repaired without moving a vertex.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "boolean/repair_rounding.hpp"
#include "molsurf/mesh_check.hpp"
#include "support/shapes.hpp"

namespace molsurf::boolean_engine {
namespace {

struct Repairable {
  Mesh mesh;
  std::vector<std::uint8_t> rounded, frozen;
  std::vector<std::uint8_t> face_operand;
  std::vector<std::uint32_t> face_source;

  explicit Repairable(Mesh m) : mesh(std::move(m)) { fill(); }
  void fill() {
    rounded.resize(mesh.vertices.size(), 0);
    face_operand.resize(mesh.faces.size(), 0);
    face_source.resize(mesh.faces.size());
    for (std::uint32_t f = 0; f < face_source.size(); ++f) face_source[f] = f;
  }
  Index add_vertex(const Vec3& p) {
    mesh.vertices.push_back(p);
    rounded.push_back(1);  // a rounded intersection point
    return static_cast<Index>(mesh.vertices.size() - 1);
  }
  RepairOutcome repair() { return repair_rounding(mesh, face_operand, face_source, rounded, frozen); }
};

// The face across edge (a, b) of face f: the one that runs b -> a.
std::uint32_t across(const Mesh& m, Index a, Index b) {
  for (std::uint32_t g = 0; g < m.faces.size(); ++g)
    for (int i = 0; i < 3; ++i)
      if (m.faces[g][i] == b && m.faces[g][(i + 1) % 3] == a) return g;
  ADD_FAILURE() << "no face across " << a << "-" << b;
  return 0;
}

// Edge (a, b) of face 0 of a box, replaced by the path a - m - m2 - b where m and m2 are
// its midpoint rounded to one position: the two faces on m-m2 are degenerate.
Repairable box_with_a_zero_length_edge() {
  Repairable r(make_box({0, 0, 0}, {4, 4, 4}));
  const Triangle t = r.mesh.faces[0];
  const Index a = t[0], b = t[1], c = t[2];
  const std::uint32_t g = across(r.mesh, a, b);
  Index d = 0;
  for (Index v : r.mesh.faces[g])
    if (v != a && v != b) d = v;
  const Vec3 mid = 0.5 * (r.mesh.vertices[a] + r.mesh.vertices[b]);
  const Index m = r.add_vertex(mid), m2 = r.add_vertex(mid);
  r.mesh.faces[0] = {a, m, c};
  r.mesh.faces[g] = {b, m2, d};
  r.mesh.faces.push_back({m, m2, c});
  r.mesh.faces.push_back({m2, b, c});
  r.mesh.faces.push_back({m2, m, d});
  r.mesh.faces.push_back({m, a, d});
  r.fill();
  return r;
}

TEST(RepairRounding, ZeroLengthEdgeIsCollapsed) {
  Repairable r = box_with_a_zero_length_edge();
  ASSERT_EQ(check_mesh(r.mesh).degenerate_faces, 2u);
  const std::size_t faces_before = r.mesh.faces.size();
  const std::vector<Vec3> positions = r.mesh.vertices;
  const RepairOutcome out = r.repair();
  EXPECT_EQ(out.degenerate_left, 0u);
  EXPECT_EQ(out.refused_frozen, 0u);
  const MeshCheck c = check_mesh(r.mesh);
  EXPECT_TRUE(c.valid()) << c.defects().front();
  EXPECT_EQ(r.mesh.faces.size(), faces_before - 2);  // the edge's two faces vanish
  EXPECT_EQ(r.face_operand.size(), r.mesh.faces.size());
  EXPECT_EQ(r.face_source.size(), r.mesh.faces.size());
  EXPECT_NEAR(surface_area(r.mesh), 96.0, 1e-12);  // no vertex moved: the box is whole
  for (const Triangle& t : r.mesh.faces)
    for (Index v : t) EXPECT_TRUE(v < positions.size() && r.mesh.vertices[v] == positions[v]);
}

TEST(RepairRounding, NoRepairTouchesAFrozenVertex) {
  Repairable r = box_with_a_zero_length_edge();
  r.frozen.assign(r.mesh.vertices.size(), 0);
  r.frozen[r.mesh.vertices.size() - 1] = 1;
  r.frozen[r.mesh.vertices.size() - 2] = 1;
  const Mesh before = r.mesh;
  const RepairOutcome out = r.repair();
  EXPECT_GT(out.refused_frozen, 0u);
  EXPECT_EQ(r.mesh.faces, before.faces);  // refused, so the caller redoes the merge whole
}

// Face (a, b, c) of a box split at a point p exactly on its edge ab, keeping the face
// (a, b, p): a corner strictly inside the opposite edge. Flipping ab with the face across it
// removes it.
TEST(RepairRounding, CornerOnTheOppositeEdgeIsFlippedAway) {
  Repairable r(make_box({0, 0, 0}, {4, 4, 4}));
  const Triangle t = r.mesh.faces[0];
  const Index a = t[0], b = t[1], c = t[2];
  const Index p = r.add_vertex(0.25 * r.mesh.vertices[a] + 0.75 * r.mesh.vertices[b]);
  r.mesh.faces[0] = {a, p, c};
  r.mesh.faces.push_back({p, b, c});
  r.mesh.faces.push_back({a, b, p});
  r.fill();
  ASSERT_EQ(check_mesh(r.mesh).degenerate_faces, 1u);
  const RepairOutcome out = r.repair();
  EXPECT_EQ(out.degenerate_left, 0u);
  const MeshCheck check = check_mesh(r.mesh);
  EXPECT_TRUE(check.valid()) << check.defects().front();
  EXPECT_NEAR(surface_area(r.mesh), 96.0, 1e-12);
  EXPECT_NEAR(signed_volume(r.mesh), 64.0, 1e-12);
}

TEST(RepairRounding, AValidMeshIsLeftAsItIs) {
  Repairable r(make_box({0, 0, 0}, {4, 4, 4}, 3, 2, 2));
  std::fill(r.rounded.begin(), r.rounded.end(), 1);  // even with every vertex rounded
  const Mesh before = r.mesh;
  const RepairOutcome out = r.repair();
  EXPECT_EQ(out.degenerate_left, 0u);
  EXPECT_EQ(r.mesh.faces, before.faces);
  EXPECT_EQ(r.mesh.vertices, before.vertices);
}

TEST(RepairRounding, SliversAndTinyFacesAreTheFacesRoundingCanTurnOver) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 1e-5, 0}};
  EXPECT_FALSE(may_turn_over(m, {0, 1, 2}));  // a right triangle
  EXPECT_TRUE(may_turn_over(m, {0, 1, 3}));   // a sliver: 0.001 degrees
}

}  // namespace
}  // namespace molsurf::boolean_engine
