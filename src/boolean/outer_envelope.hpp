#pragma once
// The outer envelope (paper §2.4, "visibility"): of all the pieces of both operands, keep
// those seen from outside, i.e. on the boundary of the unbounded region that the two
// surfaces leave free. It needs no inside/outside classification, so it also joins open
// surfaces (a plane patch through a sphere), and for two closed solids it is the union
// without its cavities.
//
// Flood fill over oriented pieces ("this piece, seen from this side"):
//  - seed: the lexicographically largest point v (x, then y, then z) is on the envelope.
//    Around v, the edge whose direction is closest to +x (perturbed to (1, e, e^2)) is on
//    it, and around that edge the piece whose half-plane is closest to that direction is on
//    it, seen from the side its normal shares with (1, e, e^2). All compared exactly.
//  - growth: from an oriented piece, across each of its edges, the next piece counter-
//    clockwise around the edge from its outer side (exact angular order, as the stitch
//    step sorts faces around an edge) is the next envelope piece, seen from the side that
//    faces the swept sector. Across an edge with two pieces that is the neighbour; across
//    a free boundary edge it is the same piece seen from its other side.
//  - several components (edge-connected sets of pieces): each floods from its own seed,
//    in order of decreasing extreme point, and is kept unless one of its points that no
//    other component shares is inside a kept component's envelope (exact ray parity
//    with a symbolically perturbed ray; a piece seen from both sides does not count).
// Coincident pieces (coplanar overlaps) are one sheet: b's copy is dropped, a's floods.
#include <cstdint>
#include <vector>

#include "boolean/arrangement.hpp"
#include "boolean/split.hpp"
#include "boolean/classify.hpp"

namespace molsurf::boolean_engine {

struct EnvelopeSelection {
  std::vector<Keep> keep;             // per sub-face: drop, keep (outside is the normal side), or flipped
  std::size_t components = 0;         // edge-connected sets of pieces
  std::size_t components_kept = 0;    // those on the envelope (not enclosed)
  std::size_t two_sided_faces = 0;    // kept, seen from both sides (parts of open sheets)
};

EnvelopeSelection select_outer_envelope(const Operands& operands, const Arrangement& arrangement,
                                        const SplitResult& split);

}  // namespace molsurf::boolean_engine
