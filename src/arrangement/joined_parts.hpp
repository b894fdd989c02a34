#pragma once
// The whole arrangement's report numbers from its blocks' parts (arrangement_part.hpp): the
// per-sphere areas and stats summed, vertices on block boundaries counted once, and the
// shells joined from the blocks' shell parts through the open keys they share, their sums
// moved to one origin. Equal to arrange_spheres on the whole structure but for rounding
// (sums in another order) and for what the summary does not keep: the vertex and arc lists,
// one patch per sphere and shell (the area of its patches there; no vector area).
#include <cstddef>
#include <functional>
#include <span>

#include "arrangement/arrangement_part.hpp"
#include "arrangement/shell_moments.hpp"
#include "molsurf/sphere_arrangement.hpp"

namespace molsurf::arrangement {

// parts: every block's, each owned sphere in exactly one; spheres: their total count.
// ball_of(i): sphere i (for shells too small for their volume's sign). Throws
// std::invalid_argument for a sphere outside [0, spheres) or parts that do not add up.
SphereArrangement join_parts(std::span<const ArrangementPart> parts, std::size_t spheres,
                             const std::function<Ball(std::uint32_t)>& ball_of);

}  // namespace molsurf::arrangement
