#pragma once
// Step 4, classify (paper §2.4): every piece of a face (sub-face) is outside the other
// solid, inside it, or coincident with one of its faces (coplanar overlap), with the same
// or the opposite orientation. Pieces are grouped into patches bounded by the
// intersection curves; a patch takes one exact ray-parity verdict, from an input vertex of
// the patch that is not on the other surface when there is one (fast path), otherwise
// from the exact centroid of one of its pieces.
#include <array>
#include <cstdint>
#include <vector>

#include "boolean/arrangement.hpp"
#include "boolean/operands.hpp"
#include "boolean/split.hpp"
#include "molsurf/boolean.hpp"

namespace molsurf::boolean_engine {

enum class Side : std::uint8_t { outside, inside, coincident_same, coincident_opposite };

struct Classification {
  std::vector<Side> side;  // per sub-face
  std::size_t ray_casts = 0;        // patches decided by a ray (the rest: by seeds and crossings)
  std::size_t exact_ray_casts = 0;  // of those, rays from an exact rational point
};

// A sub-face lies in the coplanar face g of the other operand (all corners in the closed
// triangle g, exactly).
bool inside_partner(const Operands& operands, const Arrangement& arrangement, const SubFace& sub_face, std::uint32_t g);

Classification classify_sub_faces(const Operands& operands, const Arrangement& arrangement, const SplitResult& split);

// Which sub-faces the operation keeps, and whether each is flipped (b's part of a difference).
enum class Keep : std::uint8_t { drop, keep, keep_flipped };
Keep select_sub_face(BooleanOp op, int operand, Side side);

}  // namespace molsurf::boolean_engine
