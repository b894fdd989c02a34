// The mesh editors' shared reading of a mesh: the vertex-face index and, on it, the faces
// on an edge and the vertices that block an edge's collapse (mesh/topology.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "mesh/topology.hpp"
#include "mesh/vertex_face_index.hpp"
#include "support/shapes.hpp"

namespace molsurf {
namespace {

std::vector<std::uint32_t> as_vector(std::span<const std::uint32_t> s) { return {s.begin(), s.end()}; }

// A triangular bipyramid: triangle a b c (0 1 2), apex t (3) above, s (4) below.
Mesh bipyramid() {
  Mesh m;
  m.vertices = {{1, 0, 0}, {-0.5, 0.866, 0}, {-0.5, -0.866, 0}, {0, 0, 1}, {0, 0, -1}};
  m.faces = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}};
  return m;
}

VertexFaceIndex index_of(const Mesh& m) {
  VertexFaceIndex index(m.vertices.size());
  for (std::uint32_t f = 0; f < m.faces.size(); ++f) index.add(f, m.faces[f]);
  return index;
}

TEST(VertexFaceIndex, AddAllListsAsAddingOneByOne) {
  Mesh m = bipyramid();
  m.vertices.push_back({5, 5, 5});  // a vertex without a face
  m.faces.push_back({0, 0, 1});     // a repeated corner: listed twice around it
  const VertexFaceIndex one_by_one = index_of(m);
  VertexFaceIndex all(m.vertices.size());
  all.add_all(m.faces);
  for (Index v = 0; v < m.vertices.size(); ++v) EXPECT_EQ(as_vector(all.of(v)), as_vector(one_by_one.of(v))) << v;
  EXPECT_EQ(as_vector(all.of(0)), (std::vector<std::uint32_t>{0, 2, 3, 5, 6, 6}));
  EXPECT_TRUE(all.of(5).empty());
  all.add(7, {5, 1, 0});  // grows past the allocated size
  EXPECT_EQ(as_vector(all.of(0)), (std::vector<std::uint32_t>{0, 2, 3, 5, 6, 6, 7}));
}

TEST(VertexFaceIndex, ListsFacesInTheOrderAddedAndForgetsRemovedOnes) {
  const Mesh m = bipyramid();
  VertexFaceIndex index = index_of(m);
  EXPECT_EQ(as_vector(index.of(0)), (std::vector<std::uint32_t>{0, 2, 3, 5}));
  EXPECT_EQ(as_vector(index.of(3)), (std::vector<std::uint32_t>{0, 1, 2}));
  index.remove(2, m.faces[2]);
  EXPECT_EQ(as_vector(index.of(0)), (std::vector<std::uint32_t>{0, 3, 5}));
  EXPECT_EQ(as_vector(index.of(3)), (std::vector<std::uint32_t>{0, 1}));
  index.add(2, m.faces[2]);
  EXPECT_EQ(as_vector(index.of(3)), (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(as_vector(index.of(0)), (std::vector<std::uint32_t>{0, 3, 5, 2}));  // at the end again
}

TEST(VertexFaceIndex, AVertexNeverGivenAFaceHasNone) {
  VertexFaceIndex index(10);
  index.add(0, {1, 2, 3});
  EXPECT_TRUE(index.of(7).empty());
  EXPECT_EQ(index.of(2).size(), 1u);
}

TEST(VertexFaceIndex, AFaceWithARepeatedCornerIsListedTwiceAndHasTwoEdgesThere) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}};
  m.faces = {{0, 1, 0}};
  const VertexFaceIndex index = index_of(m);
  EXPECT_EQ(index.of(0).size(), 2u);
  EXPECT_EQ(faces_on_edge(m, index.of(0), 0, 1).size(), 2u);  // edges 0-1 and 1-0, once each
}

// Lists short enough to sit in place and long ones in an array of their own (a vertex of
// 40 faces), growing, shrinking and moving as the index grows: always the faces added and
// not removed, in the order added, as plain lists would hold them.
TEST(VertexFaceIndex, AgreesWithPlainListsThroughRandomEdits) {
  constexpr std::uint32_t kVertices = 60;
  std::mt19937 random(7);
  VertexFaceIndex index(kVertices);
  std::vector<std::vector<std::uint32_t>> plain(kVertices);
  std::vector<Triangle> faces;
  std::vector<std::uint8_t> listed;
  for (int step = 0; step < 20000; ++step) {
    if (faces.empty() || random() % 3 != 0) {
      // Vertex 0 is a corner of every fourth face, so its list grows long.
      Triangle t{static_cast<Index>(random() % 4 == 0 ? 0 : random() % kVertices),
                 static_cast<Index>(random() % kVertices), static_cast<Index>(random() % kVertices)};
      if (random() % 2 == 0 || faces.empty()) {
        faces.push_back(t);
        listed.push_back(0);
      }
      const auto f = static_cast<std::uint32_t>(random() % faces.size());
      if (listed[f]) continue;
      index.add(f, faces[f]);
      for (Index v : faces[f]) plain[v].push_back(f);
      listed[f] = 1;
    } else {
      const auto f = static_cast<std::uint32_t>(random() % faces.size());
      if (!listed[f]) continue;
      index.remove(f, faces[f]);
      for (Index v : faces[f]) std::erase(plain[v], f);
      listed[f] = 0;
    }
    if (step % 97 == 0)
      for (Index v = 0; v < kVertices; ++v) ASSERT_EQ(as_vector(index.of(v)), plain[v]) << step << " " << v;
  }
  std::size_t longest = 0;
  for (Index v = 0; v < kVertices; ++v) {
    EXPECT_EQ(as_vector(index.of(v)), plain[v]) << v;
    longest = std::max(longest, plain[v].size());
  }
  EXPECT_GT(longest, 40u);
}

TEST(MeshTopology, FacesOnAnEdgeOfAClosedMeshAreTwo) {
  const Mesh m = make_box({0, 0, 0}, {1, 1, 1}, 2, 2, 2);
  const VertexFaceIndex index = index_of(m);
  for (std::uint32_t f = 0; f < m.faces.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      const Index a = m.faces[f][i], b = m.faces[f][(i + 1) % 3];
      const auto on = faces_on_edge(m, index.of(a), a, b);
      ASSERT_EQ(on.size(), 2u);
      EXPECT_TRUE(on[0] == f || on[1] == f);
    }
}

TEST(MeshTopology, BlockingVerticesAreTheCommonNeighboursBeyondTheEdge) {
  const Mesh m = bipyramid();
  const VertexFaceIndex index = index_of(m);
  // Edge a-b: its faces' opposite corners are t and s; c is joined to both a and b too, so
  // collapsing a-b would pinch the surface at c.
  EXPECT_EQ(blocking_vertices(m, index.of(0), index.of(1), 0, 1), (std::vector<Index>{2}));
  const auto on = faces_on_edge(m, index.of(0), 0, 1);
  EXPECT_FALSE(link_condition(m, index.of(0), index.of(1), on, 0, 1));
  // Edge a-t: its opposite corners b and c are a and t's only common neighbours.
  EXPECT_TRUE(blocking_vertices(m, index.of(0), index.of(3), 0, 3).empty());
  // A box's grid: no edge is blocked.
  const Mesh box = make_box({0, 0, 0}, {1, 1, 1}, 3, 3, 3);
  const VertexFaceIndex box_index = index_of(box);
  for (const Triangle& t : box.faces)
    EXPECT_TRUE(blocking_vertices(box, box_index.of(t[0]), box_index.of(t[1]), t[0], t[1]).empty());
}

}  // namespace
}  // namespace molsurf
