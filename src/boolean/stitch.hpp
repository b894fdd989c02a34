#pragma once
// Step 5, stitch: the kept sub-faces, which share their intersection points, become one
// mesh. Points are rounded to doubles only here, after every decision. Where the two
// solids only touch (at a point or along an edge), the sheets are kept apart: the
// touching vertex is duplicated once per fan of faces around it, so the result stays a
// 2-manifold (see docs/boolean.md).
#include <cstdint>
#include <vector>

#include "boolean/arrangement.hpp"
#include "boolean/classify.hpp"
#include "boolean/repair_rounding.hpp"
#include "molsurf/boolean.hpp"

namespace molsurf::boolean_engine {

struct StitchResult {
  Mesh mesh;
  std::vector<std::uint8_t> face_operand;
  std::vector<std::uint32_t> face_source;
  std::size_t split_vertices = 0;
  // Per output vertex: the arrangement point it rounds, or ~0 for a vertex added by the
  // stitch (copies where sheets touch, midpoints).
  std::vector<std::uint32_t> vertex_point;
  RepairOutcome repair;
};

StitchResult stitch_sub_faces(const Operands& operands, const Arrangement& arrangement,
                              const std::vector<SubFace>& sub_faces, const std::vector<Side>& sides, BooleanOp op);
// The same with the choice made per sub-face by the caller (the outer envelope keeps
// what is visible from outside, outer_envelope.hpp). Without `keep_sheets_apart`, touching
// vertices are not duplicated (an open sheet seen from both sides makes three faces meet
// at an edge: no 2-manifold exists there, and the material sectors are not defined).
StitchResult stitch_sub_faces(const Operands& operands, const Arrangement& arrangement,
                              const std::vector<SubFace>& sub_faces, const std::vector<Keep>& keep,
                              bool keep_sheets_apart = true);

}  // namespace molsurf::boolean_engine
