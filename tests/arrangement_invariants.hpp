#pragma once
// What every arrangement must satisfy, on any input: per-sphere areas sum to the total,
// patches to their sphere, shells to the totals; the same bits on one and two threads; and
// the values of the slice reference (measure_ball_union) within its own error.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "arrangement/sphere_arrangement.hpp"
#include "molsurf/atoms.hpp"
#include "support/ball_union.hpp"

namespace molsurf::testing {

inline void expect_arrangement_sound(const std::vector<Vec3>& centres, const std::vector<double>& radii,
                                     const std::string& what) {
  const SphereArrangement a = arrange_spheres(centres, radii, {.threads = 1});
  const SphereArrangement b = arrange_spheres(centres, radii, {.threads = 2});
  EXPECT_EQ(a.area, b.area) << what;
  EXPECT_EQ(a.volume, b.volume) << what;
  EXPECT_EQ(a.area_per_sphere, b.area_per_sphere) << what;
  EXPECT_EQ(a.shells.size(), b.shells.size()) << what;
  double scale = 0, sum = 0;
  std::vector<double> by_patch(centres.size(), 0);
  for (std::size_t i = 0; i < centres.size(); ++i) {
    scale += radii[i] * radii[i];
    sum += a.area_per_sphere[i];
  }
  for (const ArrangementPatch& p : a.patches) by_patch[p.sphere] += p.area;
  EXPECT_NEAR(sum, a.area, 1e-12 * scale) << what;
  for (std::size_t i = 0; i < centres.size(); ++i)
    EXPECT_NEAR(by_patch[i], a.area_per_sphere[i], 1e-9 * radii[i] * radii[i]) << what << ", sphere " << i;
  double shell_area = 0, shell_volume = 0;
  for (const ArrangementShell& s : a.shells) {
    shell_area += s.area;
    shell_volume += s.volume;
  }
  EXPECT_NEAR(shell_area, a.area, 1e-9 * scale) << what;
  EXPECT_NEAR(shell_volume, a.volume, 1e-9 * scale * 4) << what;
  if (!a.shells.empty()) EXPECT_FALSE(a.shells.front().cavity()) << what;
  // The slice reference at 8000 slices per ball: where circles lie flat in its slicing
  // direction (lattices) its error falls only as 1/slices, measured at 4e-5 of a sphere's
  // area here (2000 slices: 1.3e-4; 32000: 4e-6); 1e-4 of the spheres' area is twice that.
  const BallUnionMeasure slices = measure_ball_union(centres, radii, 8000);
  EXPECT_NEAR(a.area, slices.area, 1e-4 * 4 * M_PI * scale) << what;
  for (std::size_t i = 0; i < centres.size(); ++i)
    EXPECT_NEAR(a.area_per_sphere[i], slices.area_per_ball[i], 1e-4 * 4 * M_PI * radii[i] * radii[i])
        << what << ", sphere " << i;
}

inline void expect_arrangement_sound(const std::vector<Atom>& atoms, double probe, const std::string& what) {
  std::vector<Vec3> centres;
  std::vector<double> radii;
  for (const Atom& atom : atoms) {
    centres.push_back(atom.centre);
    radii.push_back(atom.radius + probe);
  }
  expect_arrangement_sound(centres, radii, what);
}

}  // namespace molsurf::testing
