// The degenerate-placement battery of test_degenerate.cpp, every family, on many more
// seeds and frequencies (label `long`).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "arrangement_invariants.hpp"
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

// The true spheres' arrangement on the same placements (its tie rules: open balls, the
// lowest copy, circles shared by several spheres).
TEST_P(ManyDegeneratePlacements, ArrangementIsSound) {
  const std::uint32_t seed = std::get<1>(GetParam());
  const testing::DegeneratePlacement p = testing::degenerate_placement(std::get<0>(GetParam()), seed);
  for (const double probe : {0.0, 0.7, 1.4})
    testing::expect_arrangement_sound(p.atoms, probe,
                                      "seed " + std::to_string(seed) + " (" + p.family + "), probe " + std::to_string(probe));
}

// Exactly tangent spheres at probe 0: chains along an axis with radii whose sums are exact,
// close packings written with three decimals, a large sphere with small ones touching it.
// Inscribed or area-corrected, one-pass or pairwise: valid, and no two shells touch.
std::vector<Atom> tangent_family(std::uint32_t seed) {
  std::mt19937 random(seed);
  auto pick = [&](int n) { return static_cast<int>(random() % static_cast<std::uint32_t>(n)); };
  const double radii[] = {0.0625, 0.5, 0.75, 1.25, 1.5, 2.0};
  std::vector<Atom> atoms;
  switch (seed % 3) {
    case 0: {  // a chain along x, y or z
      const int axis = pick(3), n = 3 + pick(6);
      double at = 0, previous = 0;
      for (int i = 0; i < n; ++i) {
        const double r = radii[pick(6)];
        at += i == 0 ? 0 : previous + r;
        Vec3 c{0, 0, 0};
        (axis == 0 ? c.x : axis == 1 ? c.y : c.z) = at;
        atoms.push_back(testing::atom_at(c, r));
        previous = r;
      }
      break;
    }
    case 1: {  // a hexagonal close packing, three decimals
      const double r = radii[1 + pick(5)];
      const auto three_decimals = [](double x) { return std::round(x * 1000) / 1000; };
      for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 3; ++j)
          for (int i = 0; i < 3; ++i)
            atoms.push_back(testing::atom_at({three_decimals(2 * r * (i + 0.5 * ((j + k) % 2))),
                                              three_decimals(r * std::sqrt(3.0) * (j + (k % 2) / 3.0)),
                                              three_decimals(2 * r * std::sqrt(2.0 / 3.0) * k)},
                                             r));
      break;
    }
    default: {  // contrast: radius 20 with small spheres touching it along the axes
      const double small = radii[pick(3)];
      atoms.push_back(testing::atom_at({0, 0, 0}, 20));
      for (const Vec3 d : {Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, -1, 0}, Vec3{0, 0, 1}})
        if (pick(2)) atoms.push_back(testing::atom_at((20 + small) * d, small));
      break;
    }
  }
  return atoms;
}

class TangentSpheres : public ::testing::TestWithParam<std::uint32_t> {};

TEST_P(TangentSpheres, ValidWithoutTouchingShells) {
  const std::uint32_t seed = GetParam();
  const std::vector<Atom> atoms = tangent_family(seed);
  for (const bool inscribed : {true, false})
    for (const int frequency : {1, 2, 4}) {
      SphereOptions o;
      o.frequency = frequency;
      o.probe = 0;
      o.area_corrected = !inscribed;
      EXPECT_TRUE(testing::methods_agree(atoms, o, 1))
          << "seed " << seed << (inscribed ? " inscribed" : " area-corrected") << ", frequency " << frequency;
    }
}

INSTANTIATE_TEST_SUITE_P(Seeds, TangentSpheres, ::testing::Range(0u, 60u));

INSTANTIATE_TEST_SUITE_P(Seeds, ManyDegeneratePlacements,
                         ::testing::Combine(::testing::ValuesIn(testing::kAllPlacementFamilies),
                                            ::testing::Range(1000u, 1100u)));

}  // namespace
}  // namespace molsurf
