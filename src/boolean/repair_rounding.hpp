#pragma once
// Rounding the implicit points to doubles (the last step) can make a piece that was tiny
// but valid in exact arithmetic degenerate: two points that differ by less than an ulp
// become one position (a zero-length edge), or a point lands exactly on the opposite edge
// of its piece. Both are repaired without moving any vertex, deciding by exact predicates
// on the rounded coordinates:
//  - a zero-length edge is collapsed (its two faces vanish) when the link condition holds,
//    so the mesh stays a 2-manifold;
//  - a face whose corner lies strictly inside the opposite edge is removed by flipping that
//    edge with the neighbouring face, whose plane both new faces then share.
#include <cstdint>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf::boolean_engine {


// Returns the number of faces still degenerate afterwards (0 unless a repair was blocked).
std::size_t repair_rounding(Mesh& mesh, std::vector<std::uint8_t>& face_operand, std::vector<std::uint32_t>& face_source);

}  // namespace molsurf::boolean_engine
