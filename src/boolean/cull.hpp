#pragma once
// Step 1, cull (paper §2.2.1 i-iii): only faces inside the overlap of the two bounding
// boxes go further, and a BVH over b's remaining faces gives, for each face of a, the
// faces of b whose closed boxes overlap its own. Conservative: any two faces that share a
// point are a candidate pair.
#include <cstdint>
#include <utility>
#include <vector>

#include "boolean/operands.hpp"

namespace molsurf::boolean_engine {

// Candidate pairs (face of a, combined face of b), sorted.
std::vector<std::pair<std::uint32_t, std::uint32_t>> cull_face_pairs(const Operands& operands);

}  // namespace molsurf::boolean_engine
