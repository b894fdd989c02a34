#pragma once
// Step 3 driver: every face becomes sub-faces, the cut ones re-triangulated by the
// advancing front (ear_clipping.hpp, advancing_front.hpp), the others kept whole; and the pieces of the
// intersection curves (split at every point on them) are collected for classification.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "boolean/arrangement.hpp"
#include "boolean/operands.hpp"

namespace molsurf::boolean_engine {

// A piece of a face after the split: a triangle on the face's own points and the
// intersection points in it.
struct SubFace {
  std::array<std::uint32_t, 3> points;  // point ids, oriented as the source face
  std::uint32_t face;                   // combined source face
};

struct SplitResult {
  std::vector<SubFace> sub_faces;  // in order of source face
  // Sub-faces of face f: [first_sub_face[f], first_sub_face[f + 1]); cut[f]: re-triangulated.
  std::vector<std::uint32_t> first_sub_face;
  std::vector<std::uint8_t> cut;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> intersection_edges;  // (lower, higher) point ids
  // Sub-faces of one face on the two sides of a transversal crossing: one inside the other
  // solid, one outside (classification propagates across these without a ray).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> opposite_sides;
  std::size_t split_faces = 0;
};

SplitResult split_faces(const Operands& operands, const Arrangement& arrangement);

}  // namespace molsurf::boolean_engine
