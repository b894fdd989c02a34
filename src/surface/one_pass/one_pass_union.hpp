#pragma once
// The union of all atoms' polyhedra in one pass (the default surface method). The boundary
// of a union of solids is the union, over the solids, of each one's boundary minus the
// interiors of all the others; the polyhedra are convex, so every face of every atom is
// settled on its own, against only the neighbours that can reach it. The steps, one file
// each in this folder (atom_trimmer.hpp runs the first four face by face, trim.cpp):
//   cull      (§2.2.1, cull.cpp) inside a neighbour: dropped; reached by none: kept whole;
//   intersect (§2.2.2, intersect.cpp) traces of the neighbours' faces on it, by exact
//                      signed volumes; points are implicit (edge x plane, or three planes
//                      where two neighbours' traces cross; point_definition.hpp) and
//                      compared by exact value;
//   split     (§2.3, split_classify.cpp) re-triangulated in its plane, constrained to the
//                      traces, each trace split at every point of the face on it (a
//                      neighbour's vertex that only touches the face splits it too: the face
//                      across the trace sees the same vertex on the same trace);
//   classify  (§2.4, split_classify.cpp) a piece is kept iff it lies outside every
//                      neighbour: by convexity, a piece is inside a neighbour iff its three
//                      corners are;
//   join      (join.cpp) pieces of all atoms meet at exactly equal points: one closed
//                      surface, cavities included, rounded only after every decision.
// Ties follow one rule: identical atoms keep the lowest index, and where a face of one
// atom lies in the plane of another's with the same orientation, the lower index keeps
// the shared part; with opposite orientations (solids face to face) both go.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"
#include "surface/one_pass/join.hpp"
#include "surface/solvent_accessible_surface.hpp"

namespace molsurf::surface_detail {

struct OnePassResult {
  Mesh mesh;  // face tags: atom index
  OnePassStats stats;
  std::vector<one_pass::VertexOrigin> origins;  // per vertex (one_pass_partial_union only)
};

// `progress` (may be empty) is called from one thread with (atoms done, atoms in all).
// `check_size` (may be empty) is called before the pass with the union's size estimated from
// a sample of atoms, when the spheres have more than `estimate_size_above` faces; it may
// throw to stop before the memory is spent. `cancel` (may be null) is read before each
// atom's trim: once set, the remaining atoms are skipped and the call throws Cancelled.
OnePassResult one_pass_union(std::span<const Atom> atoms, const SphereOptions& options, int threads,
                             const std::function<void(std::size_t, std::size_t)>& progress = {},
                             const std::function<void(const SurfaceSizeEstimate&)>& check_size = {},
                             std::uint64_t estimate_size_above = 0, const CancelFlag* cancel = nullptr);

// Part of a union: the faces of the atoms that `trimmed` marks (one flag per atom), each
// trimmed by its neighbours among all `atoms`, with containment given (one flag per atom,
// decided on a larger set: AtomPolyhedra's second constructor). The faces are those the
// whole union gives these atoms when `atoms` hold every neighbour of a marked atom; the
// mesh is open where the marked atoms meet unmarked ones (stats.open_edges counts those
// edges). Face tags index `atoms`; `origins` is filled.
OnePassResult one_pass_partial_union(std::span<const Atom> atoms, std::span<const std::uint8_t> contained,
                                     std::span<const std::uint8_t> trimmed, const SphereOptions& options, int threads);

// What a one-pass union with `open_edges` directed edges without their reverse is: a bug,
// said as such wherever a caller stops on it or falls back.
std::string open_union_message(std::size_t open_edges);

}  // namespace molsurf::surface_detail
