// A reduced random battery for every CI run; the full one is test_long_boolean_random.
#include <gtest/gtest.h>

#include "boolean_invariants.hpp"
#include "random_pairs.hpp"

namespace molsurf {
namespace {

class RandomPairs : public ::testing::TestWithParam<int> {};

TEST_P(RandomPairs, ValidResultsAndExactVolumes) {
  const int first = GetParam() * 10;
  for (int seed = first; seed < first + 10; ++seed) {
    const auto pair = testing::random_pair(static_cast<std::uint64_t>(seed));
    testing::expect_boolean_invariants(pair.a, pair.b, "seed " + std::to_string(seed) + ": " + pair.description);
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, RandomPairs, ::testing::Range(0, 6));

// Pairs from the full battery that once failed: sheets touching along a segment that
// ends where they join (1017 ... 1221), and a cavity touching the outer surface along an
// edge where the faces bounding material are one of each operand (1399, 1951), and such
// an edge whose two ends are where the sheets join (1099, 1161, 1781).
TEST(RandomPairsRegression, OnceFailingSeeds) {
  for (int seed : {1017, 1035, 1037, 1077, 1099, 1161, 1181, 1207, 1221, 1399, 1781, 1951}) {
    const auto pair = testing::random_pair(static_cast<std::uint64_t>(seed));
    testing::expect_boolean_invariants(pair.a, pair.b, "seed " + std::to_string(seed) + ": " + pair.description);
  }
}

}  // namespace
}  // namespace molsurf
