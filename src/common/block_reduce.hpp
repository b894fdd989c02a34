#pragma once
// A reduction over [0, n) in parallel whose result does not depend on the thread count:
// the items are folded in fixed blocks, each in order, and the blocks' results are then
// combined in order. Floating-point sums thus come out the same bits on any number of
// threads (unlike an OpenMP reduction), without an array of per-item values.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "common/parallel_threshold.hpp"

namespace molsurf {

// fold(value, i) adds item i to a block's value (which starts as `empty`);
// combine(total, block) adds a block's value to the total, block by block in order.
template <class T, class Fold, class Combine>
T block_reduce(std::int64_t n, const T& empty, Fold&& fold, Combine&& combine) {
  constexpr std::int64_t kBlock = 4096;
  const std::int64_t blocks = std::max<std::int64_t>(0, (n + kBlock - 1) / kBlock);
  std::vector<T> partial(static_cast<std::size_t>(blocks), empty);
#pragma omp parallel for schedule(static) if (n >= kParallelMinItems)
  for (std::int64_t b = 0; b < blocks; ++b) {
    T& value = partial[static_cast<std::size_t>(b)];
    for (std::int64_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) fold(value, i);
  }
  T total = empty;
  for (const T& value : partial) combine(total, value);
  return total;
}

}  // namespace molsurf
