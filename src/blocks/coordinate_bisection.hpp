#pragma once
// Spatial blocks of atoms balanced by count: recursive coordinate bisection. Each step cuts
// the atoms' box across its longest side so that the two halves hold atoms in proportion
// to the blocks each half will be cut into; atoms on the cutting plane are ordered by
// index, so the partition depends on nothing but the centres and the block count.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "molsurf/vec3.hpp"

namespace molsurf::blocks {

// Per point, its block in [0, blocks). Blocks hold floor or ceil of points / blocks points
// (up to one more per level of the bisection); with fewer points than blocks, some are empty.
std::vector<std::uint32_t> bisect_coordinates(std::span<const Vec3> centres, std::size_t blocks);

}  // namespace molsurf::blocks
