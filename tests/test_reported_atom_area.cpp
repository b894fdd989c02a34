// Which per-atom area the reports give (reported_atom_area.hpp): the true spheres' for the SAS,
// the patches' for the SES, the facets' only where no exact area was computed.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "atom_fixtures.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/reported_atom_area.hpp"

namespace molsurf {
namespace {

using testing::atom_at;

// Three atoms around a probe position: contact, toroidal and reentrant patches on each.
std::vector<Atom> triangle() {
  return {atom_at({0, 0, 0}, 1.6), atom_at({3.6, 0, 0}, 1.6), atom_at({1.8, 3.6 * std::sqrt(3.0) / 2, 0}, 1.6)};
}

ComputedSurface computed(SurfaceKind kind, bool exact_areas) {
  ComputeSurfaceOptions options;
  options.surface = kind;
  options.exact_areas = exact_areas;
  return compute_surface(triangle(), options);
}

double sum(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s;
}

TEST(ReportedAtomArea, OfTheSesIsItsPatchesNotItsFacets) {
  const ComputedSurface ses = computed(SurfaceKind::ses, true);
  ASSERT_TRUE(ses.ses_patches);
  const std::vector<double> area = reported_atom_area(ses, false);
  EXPECT_EQ(area, ses.ses_patches->area_per_atom);
  EXPECT_NE(area, ses.measures.atom_area);
  EXPECT_NEAR(sum(area), ses.ses_patches->area, 1e-12 * ses.ses_patches->area);
  // Whatever facets are given (a rounded file's), the patches' areas stay.
  SurfaceMeasures rounded = ses.measures;
  for (double& a : rounded.atom_area) a *= 2;
  EXPECT_EQ(reported_atom_area(ses, false, rounded), ses.ses_patches->area_per_atom);
}

TEST(ReportedAtomArea, WithoutExactAreasIsTheFacetsGiven) {
  const ComputedSurface ses = computed(SurfaceKind::ses, false);
  ASSERT_FALSE(ses.ses_patches);
  EXPECT_EQ(reported_atom_area(ses, false), ses.measures.atom_area);
  SurfaceMeasures rounded = ses.measures;
  for (double& a : rounded.atom_area) a *= 2;
  EXPECT_EQ(reported_atom_area(ses, false, rounded), rounded.atom_area);
  const ComputedSurface sas = computed(SurfaceKind::sas, false);
  EXPECT_EQ(reported_atom_area(sas, false), sas.measures.atom_area);
}

TEST(ReportedAtomArea, OfTheSasIsTheTrueSpheres) {
  const ComputedSurface sas = computed(SurfaceKind::sas, true);
  ASSERT_FALSE(sas.exact.area_per_sphere.empty());
  for (const bool outer_only : {false, true}) {
    const std::vector<double> area = reported_atom_area(sas, outer_only);
    EXPECT_EQ(area, exact_atom_area(sas.exact, outer_only));
    EXPECT_NE(area, sas.measures.atom_area);
  }
}

}  // namespace
}  // namespace molsurf
