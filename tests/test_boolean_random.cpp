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

}  // namespace
}  // namespace molsurf
