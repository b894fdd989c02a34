#pragma once
// One local change of a mesh, described before it is made so that every check can run on
// it first (src/mesh/mesh_editor.hpp makes and undoes it).
#include <cstdint>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf {

inline constexpr Index kNoVertex = ~Index{0};

struct MeshEdit {
  enum class Kind { collapse, flip, move };
  // The corners of a face the edit removes.
  static constexpr Triangle kRemoved{kNoVertex, kNoVertex, kNoVertex};

  Kind kind = Kind::collapse;
  // The faces that go or stay with new corners (or a corner that moves), each with its
  // corners afterwards (kRemoved: it goes) and a direction its normal must keep (unused
  // for a removed face). Faces keep their index and tag. The order matters beyond this
  // edit: an undo lists the faces back around their corners in it, and later edits read
  // the faces around a vertex in the order they are listed.
  std::vector<std::uint32_t> faces;
  std::vector<Triangle> after;
  std::vector<Vec3> reference;
  // Faces appended to the mesh, tagged like face `added_like`.
  std::vector<Triangle> added;
  std::uint32_t added_like = 0;
  // A vertex that moves to `target`.
  Index moved = kNoVertex;
  Vec3 target;

  bool empty() const { return faces.empty() && added.empty(); }
  // No face has a corner kNoVertex, so the first corner tells (cheaper than all three).
  bool removes(std::size_t k) const { return after[k][0] == kNoVertex; }
  void reserve(std::size_t n) {
    faces.reserve(n);
    after.reserve(n);
    reference.reserve(n);
  }
  void remove(std::uint32_t f) {
    faces.push_back(f);
    after.push_back(kRemoved);
    reference.emplace_back();
  }
  void change(std::uint32_t f, const Triangle& t, const Vec3& keep) {
    faces.push_back(f);
    after.push_back(t);
    reference.push_back(keep);
  }
  // Where corner w lies once the edit is made.
  const Vec3& position(const Mesh& m, Index w) const { return w == moved ? target : m.vertices[w]; }
};

}  // namespace molsurf
