#pragma once
// Rounding the implicit points to doubles (the last step) can make a piece that was tiny
// but valid in exact arithmetic degenerate: two points that differ by less than an ulp
// become one position (a zero-length edge), or a point lands exactly on the opposite edge
// of its piece. Both are repaired without moving any vertex, deciding by exact predicates
// on the rounded coordinates:
//  - a zero-length edge is collapsed (its two faces vanish) when the link condition holds,
//    so the mesh stays a 2-manifold;
//  - a face whose corner lies strictly inside the opposite edge is removed by flipping that
//    edge with the neighbouring face, whose plane both new faces then share;
//  - a sliver or tiny face with a rounded corner is folded when it crosses a face sharing
//    a corner with it (two points an ulp or so apart, joined by an edge, or a point a
//    rounding error from an edge of a nearly coplanar face). The fold is removed by the smallest change that leaves fewer exact crossings:
//    the rounded corner moved to a neighbouring double, else the longest edge flipped,
//    else the shortest edge that can be collapsed with the link condition, no face turned
//    over and no crossing left around the kept vertex (all exact).
#include <cstdint>
#include <utility>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf::boolean_engine {


// A face that rounding can have turned over: a sliver (smallest angle under 0.1 degree) or
// a face whose height is within a few dozen ulps of its coordinates. Selects faces for the
// exact crossing test; decides nothing.
bool may_turn_over(const Mesh& mesh, const Triangle& t);

struct RepairOutcome {
  std::size_t degenerate_left = 0;  // faces still degenerate afterwards (0 unless blocked)
  std::size_t refused_frozen = 0;   // repairs not done because they would touch a frozen vertex
  // (removed, kept) per collapse, in order: what was true of a removed vertex's place
  // (the sheets may touch there) is now true of the kept one's.
  std::vector<std::pair<Index, Index>> collapsed;
};

// What the Boolean's results need beyond that, as the operands of later merges of the
// pairwise surface method (whose own operands earlier roundings tilted by 1e-16); the
// one-pass union does without (repair_rounding.cpp):
struct RepairOptions {
  // any face with a rounded corner that crosses a neighbour, not only slivers and tiny
  // faces, has its rounded corners rounded again first (another rounding only);
  bool nudge_every_fold = false;
  // once the result is valid, edges a rounding error long at a rounded point are
  // collapsed where that leaves no exact crossing around them.
  bool collapse_tiny_edges = false;
  // two faces at a shared vertex that lie face to face (geometry::folded_flat) count as
  // a crossing, in the fold test and in the counts that decide every edit: another
  // rounding of a sliver's corner can land it exactly in the plane of the face across
  // their common vertex, where the crossing test sees only a contact, and the next merge
  // cuts both sheets along one line in overlapping segments that its split orders
  // differently on the two operands (an exact result open between points 1e-31 apart).
  bool flat_folds = false;
};

// `rounded[v]`: vertex v is a rounded intersection point (the only places rounding can
// fold). `frozen[v]` (empty: none): a vertex that faces outside this mesh share, which
// no repair may touch.
RepairOutcome repair_rounding(Mesh& mesh, std::vector<std::uint8_t>& face_operand,
                              std::vector<std::uint32_t>& face_source, const std::vector<std::uint8_t>& rounded,
                              const std::vector<std::uint8_t>& frozen, const RepairOptions& options = {});

}  // namespace molsurf::boolean_engine
