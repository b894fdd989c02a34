#pragma once
// The union of all atoms' polyhedra in one pass (the default surface method). The boundary
// of a union of solids is the union, over the solids, of each one's boundary minus the
// interiors of all the others; the polyhedra are convex, so every face of every atom is
// settled on its own, against only the neighbours that can reach it:
//   cull      (§2.2.1) inside a neighbour: dropped; reached by none: kept whole;
//   intersect (§2.2.2) traces of the neighbours' faces on it, by exact signed volumes;
//                      points are implicit (edge x plane, or three planes where two
//                      neighbours' traces cross) and compared by exact value;
//   split     (§2.3)   re-triangulated in its plane, constrained to the traces;
//   classify  (§2.4)   a piece is kept iff it lies outside every neighbour: by convexity, a
//                      piece is inside a neighbour iff its three corners are;
//   join               pieces of all atoms meet at exactly equal points: one closed
//                      surface, cavities included, rounded only after every decision.
// Ties follow one rule: identical atoms keep the lowest index, and where a face of one
// atom lies in the plane of another's with the same orientation, the lower index keeps
// the shared part; with opposite orientations (solids face to face) both go.
#include <cstddef>
#include <span>
#include <string>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"

namespace molsurf::surface_detail {

struct OnePassStats {
  std::size_t atoms = 0, duplicate_atoms = 0, neighbour_pairs = 0;
  std::size_t faces_in = 0;       // all polyhedra's faces
  std::size_t faces_inside = 0;   // dropped whole (inside a neighbour)
  std::size_t faces_whole = 0;    // kept whole (reached by no neighbour)
  std::size_t faces_cut = 0;      // re-triangulated
  std::size_t crossings = 0;      // three-plane points (two traces crossing inside a face)
  std::size_t open_edges = 0;     // directed edges without a reverse after the join (0: closed)
  double seconds_trim = 0, seconds_join = 0;
};

struct OnePassResult {
  Mesh mesh;  // face tags: atom index
  OnePassStats stats;
};

OnePassResult one_pass_union(std::span<const Atom> atoms, const SphereOptions& options, int threads);

}  // namespace molsurf::surface_detail
