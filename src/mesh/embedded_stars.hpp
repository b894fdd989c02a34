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
#include <cstdint>
#include <span>
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

// Whether faces a and b share a corner whose star is proved embedded.
inline bool share_embedded_star(const Mesh& mesh, std::span<const std::uint8_t> embedded, std::uint32_t a,
                                std::uint32_t b) {
  const Triangle &ta = mesh.faces[a], &tb = mesh.faces[b];
  bool shared = false;
  for (const Index v : ta) shared |= embedded[v] && (v == tb[0] || v == tb[1] || v == tb[2]);
  return shared;
}

}  // namespace molsurf
