#include "blocks/coordinate_bisection.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace molsurf::blocks {

namespace {

int longest_axis(std::span<const Vec3> centres, std::span<const std::uint32_t> ids) {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi = lo * -1.0;
  for (std::uint32_t i : ids)
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = std::min(lo[axis], centres[i][axis]);
      hi[axis] = std::max(hi[axis], centres[i][axis]);
    }
  int best = 0;
  for (int axis = 1; axis < 3; ++axis)
    if (hi[axis] - lo[axis] > hi[best] - lo[best]) best = axis;
  return best;
}

void bisect(std::span<const Vec3> centres, std::span<std::uint32_t> ids, std::uint32_t first_block, std::size_t blocks,
            std::vector<std::uint32_t>& block_of) {
  if (blocks == 1 || ids.empty()) {
    for (std::uint32_t i : ids) block_of[i] = first_block;
    return;
  }
  const int axis = longest_axis(centres, ids);
  const std::size_t left_blocks = blocks / 2;
  const std::size_t left = (ids.size() * left_blocks + blocks / 2) / blocks;
  // A total order (coordinate, then index): the cut is the same whatever the input order.
  std::nth_element(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(left), ids.end(),
                   [&](std::uint32_t a, std::uint32_t b) {
                     return centres[a][axis] != centres[b][axis] ? centres[a][axis] < centres[b][axis] : a < b;
                   });
  bisect(centres, ids.first(left), first_block, left_blocks, block_of);
  bisect(centres, ids.subspan(left), first_block + static_cast<std::uint32_t>(left_blocks), blocks - left_blocks,
         block_of);
}

}  // namespace

std::vector<std::uint32_t> bisect_coordinates(std::span<const Vec3> centres, std::size_t blocks) {
  if (blocks == 0) throw std::invalid_argument("bisect_coordinates: at least one block");
  std::vector<std::uint32_t> block_of(centres.size(), 0);
  std::vector<std::uint32_t> ids(centres.size());
  for (std::uint32_t i = 0; i < ids.size(); ++i) ids[i] = i;
  bisect(centres, ids, 0, blocks, block_of);
  return block_of;
}

}  // namespace molsurf::blocks
