#pragma once
// The trim of one atom (paper §2.2-§2.4 on convex polyhedra): each face of its polyhedron
// against the neighbours that can reach it, step by step, each step in its own file:
//   cull            (cull.cpp, §2.2.1)    inside a neighbour: dropped; reached by none: kept whole;
//   intersect       (intersect.cpp, §2.2.2) the traces of the neighbours' faces on it;
//   split, classify (split_classify.cpp, §2.3, §2.4) re-triangulated along the traces, only
//                   the pieces outside every neighbour kept.
// trim.cpp runs them face by face. One trimmer per thread: it keeps its buffers from atom
// to atom.
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "surface/atom_polyhedra.hpp"
#include "surface/one_pass/atom_pieces.hpp"
#include "surface/one_pass/face_work.hpp"
#include "surface/one_pass/neighbour.hpp"

namespace molsurf::surface_detail::one_pass {

// The atom's points by definition, numbered in order of first use.
class PointTable {
 public:
  std::uint32_t add(const PointDefinition& d, const geometry::ImplicitPoint& x, AtomPieces& out);

 private:
  std::unordered_map<PointDefinition, std::uint32_t, DefinitionHash> ids_;
};

class AtomTrimmer {
 public:
  AtomTrimmer(const AtomPolyhedra& polyhedra, const NeighbourList& neighbours)
      : polyhedra_(polyhedra), neighbours_(neighbours) {}

  AtomPieces trim(std::uint32_t atom);

 private:
  void load_neighbours(std::uint32_t atom);
  // Cull: per block of the icosahedron, the neighbours that hold it most deeply.
  void find_covering();
  // Cull of face f (block `block`), whose corners are f_: true when a neighbour's inscribed
  // ball holds it; otherwise the face is loaded and work_.near lists the neighbours that
  // can reach it.
  bool culled(std::uint32_t f, std::uint32_t block);
  // Intersect: the traces of every near neighbour on the face; false when the face lies
  // inside a neighbour none of whose faces meets it.
  bool intersect();
  void find_lens(Neighbour& n);
  // The trace of neighbour face g on face f: adds the points of f ∩ g and, when they span a
  // segment, the segment. Returns false if they do not meet.
  bool trace(std::uint32_t n, std::uint32_t g);
  void add_crossings();
  // Split and classify: the face cut along the traces, the pieces outside every neighbour emitted.
  void split_and_classify(AtomPieces& out, PointTable& table);
  void emit(const std::array<std::uint32_t, 3>& local, AtomPieces& out, PointTable& table);

  const AtomPolyhedra& polyhedra_;
  const NeighbourList& neighbours_;
  std::uint32_t atom_ = 0;
  Vec3 centre_;
  std::vector<Vec3> vertices_;
  // Per block of faces: the neighbours whose inscribed balls hold the block's centre most
  // deeply (~0 where fewer reach it), and whether the first holds the whole block.
  static constexpr int kCovering = 3;
  std::array<std::array<std::uint32_t, kCovering>, 20> covering_{};
  std::array<std::uint8_t, 20> buried_{};
  std::vector<std::uint32_t> corner_id_;  // per vertex: its id among the atom's points, or ~0
  std::vector<std::uint32_t> lens_candidates_;  // find_lens's buffer
  std::vector<std::uint32_t> reaching_;   // cull's buffer: the neighbours that can reach a face
  std::vector<std::uint32_t> lens_hits_;  // intersect's buffer: a lens group's faces whose boxes meet the face's
  std::vector<Neighbour> nbr_;
  std::size_t nbr_count_ = 0;
  // The face being trimmed.
  std::array<Vec3, 3> f_;
  std::array<Index, 3> f_index_{};
  std::uint32_t face_ = 0;
  BoundingBox f_box_;
  FaceWork work_;
  std::size_t crossings_ = 0;
};

}  // namespace molsurf::surface_detail::one_pass
