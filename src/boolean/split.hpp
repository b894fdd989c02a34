#pragma once
// Step 3 driver: every face becomes sub-faces, the cut ones re-triangulated by the
// advancing front (retriangulate.hpp), the others kept whole; and the pieces of the
// intersection curves (split at every point on them) are collected for classification.
#include <cstdint>
#include <utility>
#include <vector>

#include "boolean/arrangement.hpp"
#include "boolean/classify.hpp"

namespace molsurf::boolean_engine {

struct SplitResult {
  std::vector<SubFace> sub_faces;  // in order of source face
  std::vector<std::pair<std::uint32_t, std::uint32_t>> intersection_edges;  // (lower, higher) point ids
  std::size_t split_faces = 0;
};

SplitResult split_faces(const Operands& operands, const Arrangement& arrangement);

}  // namespace molsurf::boolean_engine
