#pragma once
// The one editing layer of molsurf's mesh editors (the cleanup, src/surface/cleanup*.cpp,
// and the repair of rounding, src/boolean/repair_rounding.cpp): the faces around each
// vertex, the faces by place, collapses, flips and moves described before they are made,
// the link condition, the no-turnover test, the exact crossing tests, frozen vertices,
// and a journal that undoes what it recorded.
#include <array>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <span>
#include <vector>

#include "geometry/predicates.hpp"
#include "mesh/face_grid.hpp"
#include "mesh/mesh_edit.hpp"
#include "mesh/vertex_face_index.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf {

// What every editor of one mesh shares: the mesh, which faces are alive, the faces around
// each vertex, the faces by place (only for the crossing test against the whole mesh) and
// the vertices no edit may move or remove. Editors that run at the same time must change
// places far apart (the cleanup's sweep sees to it); nothing here is locked.
class EditableMesh {
 public:
  // `frozen[v]` (empty: none): vertex v joins faces outside the mesh.
  explicit EditableMesh(Mesh& mesh, std::span<const std::uint8_t> frozen = {})
      : mesh_(mesh), alive_(mesh.faces.size(), 1), faces_of_(mesh.vertices.size()), frozen_(frozen),
        first_added_(static_cast<std::uint32_t>(mesh.faces.size())) {}

  // Face f listed around its corners; an editor sees only the faces listed (a repair
  // lists those near what it repairs).
  void index(std::uint32_t f) { faces_of_.add(f, mesh_.faces[f]); }
  // Every face listed around its corners and kept by place in cells of side `cell` (see
  // FaceGrid): what the crossing test of an edit against the whole mesh needs.
  void index_all(double cell);

  const Mesh& mesh() const { return mesh_; }
  bool alive(std::uint32_t f) const { return alive_[f] != 0; }
  // Per face: still in the mesh (faces removed by edits keep their slot until the end).
  const std::vector<std::uint8_t>& alive_faces() const { return alive_; }
  const FaceGrid* grid() const { return grid_.get(); }
  // Faces from here on were added by edits, each tagged like face added_like(f).
  std::uint32_t first_added() const { return first_added_; }
  std::uint32_t added_like(std::uint32_t f) const { return added_like_[f - first_added_]; }

 private:
  friend class MeshEditor;
  Mesh& mesh_;
  std::vector<std::uint8_t> alive_;
  VertexFaceIndex faces_of_;
  std::unique_ptr<FaceGrid> grid_;
  std::span<const std::uint8_t> frozen_;
  std::uint32_t first_added_;
  std::vector<std::uint32_t> added_like_;
};

// One editor: builds edits, tests them, makes them and, while its journal is open, undoes
// them. Each worker of a parallel cleanup has its own (its journal and the marks of its
// crossing tests).
class MeshEditor {
 public:
  explicit MeshEditor(EditableMesh& shared) : s_(shared) {}

  const Mesh& mesh() const { return s_.mesh_; }
  bool alive(std::uint32_t f) const { return s_.alive_[f] != 0; }
  // The listed faces around v, in the order they were listed.
  std::span<const std::uint32_t> faces_of(Index v) const { return s_.faces_of_.of(v); }
  // The faces on edge ab (a closed 2-manifold has exactly two), in the order around a.
  std::vector<std::uint32_t> faces_on_edge(Index a, Index b) const;
  // The vertices joined to v by its faces (sorted).
  std::vector<Index> neighbours(Index v) const;
  // Whether some face around c has corner d.
  bool joined(Index c, Index d) const;
  // The common neighbours of a and b beyond the two faces on edge ab: what makes its
  // collapse fail the link condition.
  std::vector<Index> blocking_vertices(Index a, Index b) const;
  // The link condition for collapsing edge uv (its faces `on_edge`): the collapse keeps a
  // 2-manifold.
  bool link_condition(Index u, Index v, std::span<const std::uint32_t> on_edge) const;
  Vec3 normal(const Triangle& t) const {
    const Vec3 &a = mesh().vertices[t[0]], &b = mesh().vertices[t[1]], &c = mesh().vertices[t[2]];
    return cross(b - a, c - a);
  }

  // Edits, described and not made. Each changed face's reference is its present normal
  // unless said otherwise.
  //
  // Collapse of edge uv (faces `on_edge`): v merges into u, which moves to `target`. The
  // faces on the edge are listed first, then those around v, then those around u when u
  // moves.
  MeshEdit collapse(Index u, Index v, std::span<const std::uint32_t> on_edge, const Vec3& target) const;
  // Collapse of edge uv with u staying, the faces listed as they are around v.
  MeshEdit merge(Index u, Index v, std::span<const std::uint32_t> on_edge) const;
  // Removal of a vertex w with three faces: they become one face on its three neighbours,
  // whose reference is the surface around the fan (the faces across its three edges).
  // Empty when w's faces do not form such a fan.
  MeshEdit remove_valence_three(Index w) const;
  // Flip of the edge shared by faces f (corner c off the edge) and g (corner d): the two
  // faces on edge cd replace them, f and g changed in place (both with `reference`).
  MeshEdit flip(std::uint32_t f, std::uint32_t g, Index c, Index d, const Vec3& reference) const;
  // The same flip, with f and g removed and the two faces appended, tagged like g.
  MeshEdit flip_appending(std::uint32_t f, std::uint32_t g, Index c, Index d) const;
  // v moves to `target`.
  MeshEdit move(Index v, const Vec3& target) const;

  // The no-turnover test of a new face abc: not degenerate (exact) and its normal within
  // the angle whose cosine is `min_cos` of `reference` (0: any angle under 90 degrees).
  static bool keeps_facing(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& reference, double min_cos) {
    if (geometry::collinear3d(a, b, c)) return false;
    const Vec3 n = cross(b - a, c - a);
    return dot(n, reference) > min_cos * norm(n) * norm(reference);
  }
  // Exactly: no face of the edit meets a face near it (the faces by place) or another face
  // of the edit beyond the corners and edges they share. Needs index_all.
  bool crosses_nothing(const MeshEdit& e);
  // Exactly: the crossing pairs among the listed faces around the given vertices and
  // around their neighbours (a count for edits that must leave fewer than there were).
  std::size_t crossings_around(std::initializer_list<Index> centres) const;
  // Whether crossings_around also counts pairs that fold flat at a shared vertex
  // (geometry::folded_flat): the rounding repair of a Boolean's result, whose folds a
  // later Boolean on it would meet (off: the cleanup and the one-pass union).
  void count_flat_folds(bool on) { count_flat_folds_ = on; }
  // Exactly: faces a and b cross, or (count_flat_folds) fold flat at a shared vertex: the
  // pairs crossings_around counts.
  bool folds(const Triangle& a, const Triangle& b) const;

  bool frozen(Index v) const { return !s_.frozen_.empty() && s_.frozen_[v]; }
  // Whether any of `vertices` is frozen; each time one is, a refusal is counted.
  bool touches_frozen(std::initializer_list<Index> vertices);
  std::size_t refused_frozen() const { return refused_frozen_; }
  // Whether the edit neither moves a frozen vertex nor merges one away.
  bool spares_frozen(const MeshEdit& e) const;
  // Whether every edge between two frozen vertices in the faces the edit makes is an edge
  // already: frozen vertices join faces beyond the mesh, which may join them by an edge of
  // their own that this mesh cannot see (a spatial block's seam).
  bool keeps_frozen_edges(const MeshEdit& e) const;

  // Makes the edit (one that spares the frozen vertices; std::invalid_argument otherwise),
  // recording it while the journal is open.
  void commit(const MeshEdit& e);
  // v moves to p with its faces listed as they were: positions tried one after another
  // where no faces are kept by place (their cells would go stale).
  void reposition(Index v, const Vec3& p);

  // The journal: open_journal() starts recording commits, undo_last() undoes the last one
  // recorded (and returns it), close_journal() keeps what is left and stops recording.
  void open_journal() {
    journal_.clear();
    journaling_ = true;
  }
  bool journaling() const { return journaling_; }
  bool journal_empty() const { return journal_.empty(); }
  MeshEdit undo_last();
  void close_journal() {
    journal_.clear();
    journaling_ = false;
  }

 private:
  struct Step {
    MeshEdit edit;
    std::vector<Triangle> before;  // per face of the edit
    Vec3 old_position;
    std::uint32_t first_added = 0;
  };
  // The two faces on edge cd that replace f (corner c) and the face across from it (d).
  std::array<Triangle, 2> flipped(std::uint32_t f, Index c, Index d) const;
  bool crosses_nothing_near(const MeshEdit& e, const Triangle& t);

  EditableMesh& s_;
  std::vector<Step> journal_;
  bool journaling_ = false;
  std::size_t refused_frozen_ = 0;
  bool count_flat_folds_ = false;
  // Per face: the query of the crossing test that last saw it (each face is tested once).
  std::vector<std::uint32_t> seen_;
  std::uint32_t query_ = 0;
  std::vector<const Triangle*> made_;  // the new faces of the edit under test
};

}  // namespace molsurf
