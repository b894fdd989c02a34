// The full random battery (label `long`): 1000 pairs, half of them grid-snapped.
#include <gtest/gtest.h>

#include "boolean_invariants.hpp"
#include "random_pairs.hpp"

namespace molsurf {
namespace {

class RandomPairsFull : public ::testing::TestWithParam<int> {};

TEST_P(RandomPairsFull, ValidResultsAndExactVolumes) {
  const int first = 1000 + GetParam() * 50;  // seeds 1000..1999, apart from the CI set
  for (int seed = first; seed < first + 50; ++seed) {
    const auto pair = testing::random_pair(static_cast<std::uint64_t>(seed));
    testing::expect_boolean_invariants(pair.a, pair.b, "seed " + std::to_string(seed) + ": " + pair.description);
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, RandomPairsFull, ::testing::Range(0, 20));

}  // namespace
}  // namespace molsurf
