// The editing layer (src/mesh/mesh_editor.hpp): what every edit it makes keeps, on
// generated meshes. An undone edit leaves the mesh as it was; a collapse that would pinch
// the surface fails the link condition; a flip that would turn a face over and a move
// that would cross the surface are refused; frozen vertices are neither moved nor merged
// away; committed edits keep a closed 2-manifold.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <vector>

#include "mesh/icosphere.hpp"
#include "mesh/mesh_editor.hpp"
#include "mesh/topology.hpp"
#include "molsurf/mesh_check.hpp"
#include "support/shapes.hpp"

namespace molsurf {
namespace {

Mesh icosphere(int frequency) {
  IcosphereOptions options;
  options.frequency = frequency;
  return make_icosphere({0.5, -0.25, 0.125}, 2.0, options);
}

double mean_edge(const Mesh& m) {
  double total = 0;
  for (const Triangle& t : m.faces) total += norm(m.vertices[t[1]] - m.vertices[t[0]]);
  return total / static_cast<double>(m.faces.size());
}

std::set<std::uint32_t> as_set(std::span<const std::uint32_t> s) { return {s.begin(), s.end()}; }

// The new faces of the edit pass the no-turnover test (60 degrees, as the cleanup asks).
bool keeps_facing(const MeshEditor& editor, const MeshEdit& e) {
  for (std::size_t k = 0; k < e.faces.size(); ++k) {
    if (e.removes(k)) continue;
    const Triangle& t = e.after[k];
    const Mesh& m = editor.mesh();
    if (!MeshEditor::keeps_facing(e.position(m, t[0]), e.position(m, t[1]), e.position(m, t[2]), e.reference[k], 0.5))
      return false;
  }
  return true;
}

// A closed pyramid whose top is a dart: v a w b in the plane z = 0, non-convex at a, as
// faces (v a b) and (b a w); below, an apex inside the dart's kernel.
Mesh dart_pyramid() {
  Mesh m;
  m.vertices = {{0, 1, 0}, {0.5, 0, 0}, {0, -1, 0}, {1, 0, 0}, {0.75, 0, -1}};  // v a w b s
  m.faces = {{0, 1, 3}, {3, 1, 2}, {1, 0, 4}, {2, 1, 4}, {3, 2, 4}, {0, 3, 4}};
  return m;
}

TEST(MeshEditor, CollapseThenUndoRestoresTheMeshExactly) {
  Mesh m = icosphere(3);
  const Mesh original = m;
  EditableMesh editable(m);
  editable.index_all(2 * mean_edge(m));
  MeshEditor editor(editable);
  std::vector<std::set<std::uint32_t>> around(m.vertices.size());
  for (Index v = 0; v < m.vertices.size(); ++v) around[v] = as_set(editor.faces_of(v));

  const Index u = original.faces[7][0], v = original.faces[7][1];
  const std::vector<std::uint32_t> on_edge = editor.faces_on_edge(u, v);
  ASSERT_EQ(on_edge.size(), 2u);
  ASSERT_TRUE(editor.link_condition(u, v, on_edge));
  const MeshEdit e = editor.collapse(u, v, on_edge, 0.5 * (m.vertices[u] + m.vertices[v]));
  ASSERT_TRUE(editor.crosses_nothing(e));
  editor.open_journal();
  editor.commit(e);
  EXPECT_FALSE(editor.alive(on_edge[0]));
  EXPECT_TRUE(editor.faces_of(v).empty());
  EXPECT_NE(m.vertices[u], original.vertices[u]);
  editor.undo_last();
  editor.close_journal();

  EXPECT_EQ(m.vertices, original.vertices);
  EXPECT_EQ(m.faces, original.faces);
  for (std::uint32_t f = 0; f < m.faces.size(); ++f) EXPECT_TRUE(editor.alive(f));
  for (Index w = 0; w < m.vertices.size(); ++w) EXPECT_EQ(as_set(editor.faces_of(w)), around[w]) << "vertex " << w;
}

TEST(MeshEditor, UndoOfAnAppendingFlipLeavesItsFacesDead) {
  Mesh m = icosphere(2);
  const Mesh original = m;
  EditableMesh editable(m);
  for (std::uint32_t f = 0; f < m.faces.size(); ++f) editable.index(f);
  MeshEditor editor(editable);
  const Triangle t = m.faces[3];
  const std::vector<std::uint32_t> on = editor.faces_on_edge(t[0], t[1]);
  ASSERT_EQ(on.size(), 2u);
  const std::uint32_t g = on[0] == 3 ? on[1] : on[0];
  Index d = t[0];
  for (Index w : m.faces[g])
    if (w != t[0] && w != t[1]) d = w;
  editor.open_journal();
  editor.commit(editor.flip_appending(3, g, t[2], d));
  EXPECT_EQ(m.faces.size(), original.faces.size() + 2);
  EXPECT_EQ(editable.added_like(static_cast<std::uint32_t>(original.faces.size())), g);
  editor.undo_last();
  editor.close_journal();
  std::vector<std::uint8_t> alive = editable.alive_faces();
  keep_alive_faces(m, alive);
  EXPECT_EQ(m.faces, original.faces);
}

TEST(MeshEditor, ACollapseThatWouldPinchTheSurfaceFailsTheLinkCondition) {
  // A triangular bipyramid: collapsing an edge of the equator would leave the third
  // equator vertex joined to the merged one by two edges.
  Mesh m;
  m.vertices = {{1, 0, 0}, {-0.5, 0.866, 0}, {-0.5, -0.866, 0}, {0, 0, 1}, {0, 0, -1}};
  m.faces = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}};
  EditableMesh editable(m);
  editable.index_all(1);
  MeshEditor editor(editable);
  const std::vector<std::uint32_t> on_edge = editor.faces_on_edge(0, 1);
  ASSERT_EQ(on_edge.size(), 2u);
  EXPECT_FALSE(editor.link_condition(0, 1, on_edge));
  EXPECT_EQ(editor.blocking_vertices(0, 1), std::vector<Index>{2});
  // An edge to an apex can go: the apex's other neighbours are the edge's opposite corners.
  EXPECT_TRUE(editor.link_condition(0, 3, editor.faces_on_edge(0, 3)));
}

TEST(MeshEditor, AFlipThatWouldTurnAFaceOverIsRefused) {
  Mesh m = dart_pyramid();
  ASSERT_TRUE(check_mesh(m).valid());
  EditableMesh editable(m);
  editable.index_all(0.5);
  MeshEditor editor(editable);
  // Edge a b of the dart's two top faces: the other diagonal, v w, runs outside the dart.
  ASSERT_FALSE(editor.joined(0, 2));
  const MeshEdit flip = editor.flip(0, 1, 0, 2, {0, 0, 1});
  EXPECT_FALSE(keeps_facing(editor, flip));
  // The same flip on a convex quad (the icosphere) keeps every face's side.
  Mesh sphere = icosphere(2);
  EditableMesh sphere_editable(sphere);
  sphere_editable.index_all(2 * mean_edge(sphere));
  MeshEditor sphere_editor(sphere_editable);
  const Triangle t = sphere.faces[0];
  const std::vector<std::uint32_t> on = sphere_editor.faces_on_edge(t[0], t[1]);
  const std::uint32_t g = on[0] == 0 ? on[1] : on[0];
  Index d = t[0];
  for (Index w : sphere.faces[g])
    if (w != t[0] && w != t[1]) d = w;
  const MeshEdit fine = sphere_editor.flip(0, g, t[2], d, sphere_editor.normal(t));
  EXPECT_TRUE(keeps_facing(sphere_editor, fine));
  EXPECT_TRUE(sphere_editor.crosses_nothing(fine));
}

TEST(MeshEditor, AnEditThatWouldCrossTheSurfaceIsRefused) {
  Mesh m = make_box({0, 0, 0}, {1, 1, 1}, 3, 3, 3);
  EditableMesh editable(m);
  editable.index_all(2 * mean_edge(m));
  MeshEditor editor(editable);
  // A vertex of the top face pushed below the bottom: its faces cross the bottom's (off
  // the lattice's lines, where they would only touch the bottom's edges).
  Index top = kNoVertex;
  for (Index v = 0; v < m.vertices.size() && top == kNoVertex; ++v)
    if (m.vertices[v].z == 1 && m.vertices[v].x > 0 && m.vertices[v].x < 1 && m.vertices[v].y > 0 && m.vertices[v].y < 1)
      top = v;
  ASSERT_NE(top, kNoVertex);
  const Vec3 p = m.vertices[top];
  EXPECT_FALSE(editor.crosses_nothing(editor.move(top, {p.x + 0.05, p.y + 0.03, -0.5})));
  EXPECT_EQ(m.vertices[top], p);  // the test leaves the mesh as it was
  EXPECT_TRUE(editor.crosses_nothing(editor.move(top, {p.x, p.y, 0.9})));
}

TEST(MeshEditor, FrozenVerticesAreNeverMovedOrMergedAway) {
  Mesh m = icosphere(2);
  const Index frozen_vertex = m.faces[5][0], other = m.faces[5][1];
  std::vector<std::uint8_t> frozen(m.vertices.size(), 0);
  frozen[frozen_vertex] = 1;
  EditableMesh editable(m, frozen);
  for (std::uint32_t f = 0; f < m.faces.size(); ++f) editable.index(f);
  MeshEditor editor(editable);
  const std::vector<std::uint32_t> on_edge = editor.faces_on_edge(frozen_vertex, other);
  const MeshEdit merged_away = editor.merge(other, frozen_vertex, on_edge);
  EXPECT_FALSE(editor.spares_frozen(merged_away));
  EXPECT_THROW(editor.commit(merged_away), std::invalid_argument);
  const MeshEdit moved = editor.move(frozen_vertex, 1.01 * m.vertices[frozen_vertex]);
  EXPECT_FALSE(editor.spares_frozen(moved));
  EXPECT_THROW(editor.commit(moved), std::invalid_argument);
  EXPECT_THROW(editor.reposition(frozen_vertex, {0, 0, 0}), std::invalid_argument);
  EXPECT_TRUE(editor.touches_frozen({other, frozen_vertex}));
  EXPECT_EQ(editor.refused_frozen(), 1u);
  // The other way round the frozen vertex stays where it is.
  const MeshEdit kept = editor.merge(frozen_vertex, other, on_edge);
  EXPECT_TRUE(editor.spares_frozen(kept));
  editor.commit(kept);
  EXPECT_FALSE(editor.faces_of(frozen_vertex).empty());
}

TEST(MeshEditor, CommittedEditsKeepAClosedTwoManifold) {
  Mesh m = icosphere(4);
  const double edge = mean_edge(m);
  EditableMesh editable(m);
  editable.index_all(2 * edge);
  MeshEditor editor(editable);
  std::size_t collapses = 0, flips = 0, moves = 0;
  for (std::uint32_t f = 0; f < m.faces.size(); f += 7) {
    if (!editor.alive(f)) continue;
    const Triangle t = m.faces[f];
    const std::vector<std::uint32_t> on = editor.faces_on_edge(t[0], t[1]);
    if (on.size() != 2) continue;
    if (f % 3 == 0) {
      if (!editor.link_condition(t[0], t[1], on)) continue;
      const MeshEdit e = editor.collapse(t[0], t[1], on, 0.5 * (m.vertices[t[0]] + m.vertices[t[1]]));
      if (keeps_facing(editor, e) && editor.crosses_nothing(e)) {
        editor.commit(e);
        ++collapses;
      }
    } else if (f % 3 == 1) {
      const std::uint32_t g = on[0] == f ? on[1] : on[0];
      Index d = t[0];
      for (Index w : m.faces[g])
        if (w != t[0] && w != t[1]) d = w;
      if (d == t[0] || editor.joined(t[2], d)) continue;
      const MeshEdit e = editor.flip(f, g, t[2], d, editor.normal(t));
      if (keeps_facing(editor, e) && editor.crosses_nothing(e)) {
        editor.commit(e);
        ++flips;
      }
    } else {
      const MeshEdit e = editor.move(t[2], 0.9 * m.vertices[t[2]] + 0.1 * m.vertices[t[0]]);
      if (keeps_facing(editor, e) && editor.crosses_nothing(e)) {
        editor.commit(e);
        ++moves;
      }
    }
  }
  EXPECT_GT(collapses, 10u);
  EXPECT_GT(flips, 10u);
  EXPECT_GT(moves, 10u);
  std::vector<std::uint8_t> alive = editable.alive_faces();
  keep_alive_faces(m, alive);
  drop_unused_vertices(m);
  const MeshCheck check = check_mesh(m);
  EXPECT_TRUE(check.closed());
  EXPECT_TRUE(check.manifold());
  EXPECT_TRUE(check.valid()) << ::testing::PrintToString(check.defects());
  EXPECT_EQ(check.euler_characteristic, 2);
}

}  // namespace
}  // namespace molsurf
