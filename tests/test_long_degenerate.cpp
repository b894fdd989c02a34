// The degenerate-placement battery of test_degenerate.cpp, every family, on many more
// seeds and frequencies (label `long`).
#include <gtest/gtest.h>

#include <string>

#include "arrangement_invariants.hpp"
#include "boolean_invariants.hpp"
#include "degenerate_placements.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/error.hpp"
#include "molsurf/surface.hpp"
#include "surface_methods.hpp"

namespace molsurf {
namespace {

class ManyDegeneratePlacements
    : public ::testing::TestWithParam<std::tuple<testing::PlacementFamily, std::uint32_t>> {};

TEST_P(ManyDegeneratePlacements, BothMethodsValidAndEqual) {
  const std::uint32_t seed = std::get<1>(GetParam());
  const testing::DegeneratePlacement p = testing::degenerate_placement(std::get<0>(GetParam()), seed);
  for (const int frequency : {1, 2, 3})
    for (const double probe : {0.0, 0.7, 1.4}) {
      SphereOptions o;
      o.frequency = frequency;
      o.probe = probe;
      const std::string what = "seed " + std::to_string(seed) + " (" + p.family + "), frequency " +
                               std::to_string(frequency) + ", probe " + std::to_string(probe);
      try {
        EXPECT_TRUE(testing::methods_agree(p.atoms, o, 1)) << what;
      } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).find("internal"), std::string::npos) << what << ": " << e.what();
      }
    }
}

// The true spheres' arrangement on the same placements (its tie rules: open balls, the
// lowest copy, circles shared by several spheres).
TEST_P(ManyDegeneratePlacements, ArrangementIsSound) {
  const std::uint32_t seed = std::get<1>(GetParam());
  const testing::DegeneratePlacement p = testing::degenerate_placement(std::get<0>(GetParam()), seed);
  for (const double probe : {0.0, 0.7, 1.4})
    testing::expect_arrangement_sound(p.atoms, probe,
                                      "seed " + std::to_string(seed) + " (" + p.family + "), probe " + std::to_string(probe));
}

INSTANTIATE_TEST_SUITE_P(Seeds, ManyDegeneratePlacements,
                         ::testing::Combine(::testing::ValuesIn(testing::kAllPlacementFamilies),
                                            ::testing::Range(1000u, 1100u)));

}  // namespace
}  // namespace molsurf
