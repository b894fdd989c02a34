#pragma once
// Vertices whose star (the faces around them) is embedded, proved with a few exact 2-d
// orientations: seen along a coordinate axis, every face of the star turns strictly the
// same way around the vertex, and together they turn around it exactly once. The
// projected faces then tile a disk around the vertex without overlap, and since each face
// projects one to one, two faces of the star meet only at the vertex or along the edge
// they share: no pair of them needs an exact intersection test (the check's pairs that
// share a corner are four fifths of all it tests on a molecular surface).
//
// The proof needs each star to be one closed fan, consistently oriented: only meaningful
// for a mesh with no boundary or non-manifold edge, no misoriented edge and no
// non-manifold vertex. A star the proof does not settle (a fold, a face seen edge-on from
// every axis, a fan that winds twice) is simply not marked.
#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf {

// The faces around each vertex, in compressed rows.
struct VertexFaces {
  std::vector<std::uint32_t> start;  // per vertex, and one past the last
  std::vector<std::uint32_t> faces;
  std::span<const std::uint32_t> of(Index v) const { return {faces.data() + start[v], faces.data() + start[v + 1]}; }
};

// Per vertex: 1 when its star is proved embedded as above. In parallel.
std::vector<std::uint8_t> embedded_stars(const Mesh& mesh, const VertexFaces& around);

// Keys that settle pairs of faces around a vertex whose whole star is not provable (the
// corner of a polygon cap, where the cap's fan meets the sides at a right angle, so that no
// axis shows the star flat): a chain of consecutive faces around the vertex that, seen
// along one axis, all turn strictly the same way, each sharing its edge with the next, and
// turn less than once around in all (no face's wedge holds the direction the chain starts
// from). Such faces meet only at the vertex or along the edges they share, like an
// embedded star's. A cap of 100 000 corners fanned from one of them is one chain: without
// it, its 5e9 pairs would each be tested.
//
// Key of a face's corner at vertex v: v when v's star is embedded, else (vertex count +
// the chain's number) when the corner lies in a chain, else none. Two faces that share a
// key meet only where they share the vertex (and the edge between them).
class FanKeys {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  FanKeys() = default;
  // `embedded` from embedded_stars (empty: no star proved, no chain looked for either,
  // since the proofs need a closed, manifold, oriented mesh).
  FanKeys(const Mesh& mesh, const VertexFaces& around, std::span<const std::uint8_t> embedded);

  bool empty() const { return embedded_.empty(); }
  // The keys of face f's corners, sorted, kNone last.
  std::array<std::uint32_t, 3> of(const Mesh& mesh, std::uint32_t f) const;
  // Whether faces a and b share a key.
  bool share(const Mesh& mesh, std::uint32_t a, std::uint32_t b) const;

 private:
  std::uint32_t key(const Mesh& mesh, std::uint32_t f, int corner) const;

  std::span<const std::uint8_t> embedded_;
  std::uint32_t vertex_count_ = 0;
  std::unordered_map<std::uint64_t, std::uint32_t> chain_;  // (face, corner) -> chain number
};

}  // namespace molsurf
