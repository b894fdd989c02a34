// The degenerate-placement battery of test_degenerate.cpp, every family, on many more
// seeds and frequencies (label `long`).
#include <gtest/gtest.h>

#include <string>

#include "atom_fixtures.hpp"
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

INSTANTIATE_TEST_SUITE_P(Seeds, ManyDegeneratePlacements,
                         ::testing::Combine(::testing::ValuesIn(testing::kAllPlacementFamilies),
                                            ::testing::Range(1000u, 1100u)));

// The smallest case of the coplanar-face defect (docs/boolean.md): the union of three
// icospheres must not depend on the order of the pairwise unions. The volume is the one
// every other order, the one-pass union and a Monte Carlo estimate agree on.
TEST(CoplanarFaces, UnionOrderDoesNotChangeTheVolume) {
  SphereOptions o;
  o.frequency = 1;
  o.probe = 1.4;
  const Mesh m0 = atom_sphere(testing::atom_at({3.4, 0, 3.4}, 1.7), 0, o);
  const Mesh m1 = atom_sphere(testing::atom_at({6.8, 0, 0}, 1.7), 1, o);
  const Mesh m2 = atom_sphere(testing::atom_at({6.8, 0, 3.4}, 1.7), 2, o);
  const double reference = signed_volume(boolean(boolean(m0, m2, BooleanOp::union_).mesh, m1, BooleanOp::union_).mesh);
  const Mesh a = boolean(m1, m2, BooleanOp::union_).mesh;
  const double volume = signed_volume(boolean(a, m0, BooleanOp::union_).mesh);
  EXPECT_NEAR(volume, reference, 1e-9 * reference);
  testing::expect_boolean_invariants(a, m0, "(m1 u m2) and m0");
}

}  // namespace
}  // namespace molsurf
