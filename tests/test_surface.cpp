#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>

#include "atom_fixtures.hpp"
#include "boolean_invariants.hpp"
#include "mesh/icosphere.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/resource_limits.hpp"
#include "molsurf/surface.hpp"
#include "molsurf/surface_report.hpp"
#include "support/ball_union.hpp"
#include "surface/solvent_accessible_surface.hpp"

namespace molsurf {
namespace {

const std::string kData = MOLSURF_DATA_DIR;

using testing::atom_at;

using testing::valid_surface;
::testing::AssertionResult valid(const Mesh& m) { return valid_surface(m); }

TEST(Surface, OneAtomIsItsSphere) {
  const std::vector<Atom> atoms{atom_at({1, 2, 3}, 1.7)};
  SphereUnionOptions o;
  const SphereUnion r = solvent_accessible_surface(atoms, o);
  const Mesh sphere = atom_sphere(atoms[0], 0, o.spheres);
  EXPECT_EQ(r.mesh.face_count(), sphere.face_count());
  EXPECT_DOUBLE_EQ(surface_area(r.mesh), surface_area(sphere));
  EXPECT_EQ(r.merges, 0u);
}

TEST(Surface, TwoOverlappingAtoms) {
  const std::vector<Atom> atoms{atom_at({0, 0, 0}, 1.7), atom_at({2.1, 0.3, 0.2}, 1.5)};
  SphereUnionOptions o;
  const SphereUnion r = solvent_accessible_surface(atoms, o);
  EXPECT_TRUE(valid(r.mesh));
  const double a0 = surface_area(atom_sphere(atoms[0], 0, o.spheres));
  const double a1 = surface_area(atom_sphere(atoms[1], 1, o.spheres));
  const double area = surface_area(r.mesh);
  EXPECT_LT(area, a0 + a1);
  EXPECT_GT(area, std::max(a0, a1));
  const auto per_atom = area_per_atom(r.mesh, 2);
  EXPECT_NEAR(per_atom[0] + per_atom[1], area, 1e-9 * area);
  EXPECT_GT(per_atom[0], 0);
  EXPECT_GT(per_atom[1], 0);
}

TEST(Surface, DuplicateAtomsAndABuriedAtom) {
  const std::vector<Atom> atoms{atom_at({0, 0, 0}, 1.7), atom_at({0, 0, 0}, 1.7), atom_at({0.1, 0, 0}, 0.2),
                                atom_at({2, 0, 0}, 1.5)};
  const SphereUnion r = solvent_accessible_surface(atoms, {});
  EXPECT_TRUE(valid(r.mesh));
  const auto per_atom = area_per_atom(r.mesh, atoms.size());
  EXPECT_EQ(per_atom[2], 0);                    // buried
  EXPECT_EQ(per_atom[0] * per_atom[1], 0);      // the duplicate's faces come from one copy only
  EXPECT_GT(per_atom[0] + per_atom[1], 0);
}

TEST(Surface, TouchingSpheresStayApart) {
  // r + probe = 1.5 + 1.4 each, centres 5.8 apart: the probe-inflated spheres touch.
  const std::vector<Atom> atoms{atom_at({0, 0, 0}, 1.5), atom_at({5.8, 0, 0}, 1.5)};
  SphereUnionOptions o;
  o.spheres.frequency = 3;
  const SphereUnion r = solvent_accessible_surface(atoms, o);
  EXPECT_TRUE(valid(r.mesh));
  EXPECT_EQ(connected_components(r.mesh).count, 2u);
}

class Crambin : public ::testing::TestWithParam<std::tuple<double, double>> {};

TEST_P(Crambin, ValidSurfaceAtEachDensityAndProbe) {
  const auto [density, probe] = GetParam();
  const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  SphereUnionOptions o;
  o.spheres.density = density;
  o.spheres.probe = probe;
  const SphereUnion r = solvent_accessible_surface(s.atoms, o);
  EXPECT_TRUE(valid(r.mesh)) << "density " << density << " probe " << probe;
  EXPECT_GT(signed_volume(r.mesh), 0);
  const auto per_atom = area_per_atom(r.mesh, s.atoms.size());
  EXPECT_NEAR(std::accumulate(per_atom.begin(), per_atom.end(), 0.0), surface_area(r.mesh), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(DensitiesAndProbes, Crambin,
                         ::testing::Combine(::testing::Values(1.0, 2.0, 4.0), ::testing::Values(0.0, 1.4)));

TEST(Surface, SpheresBelowTheMinimumDensityRadiusGetItsFrequency) {
  SphereOptions o;  // density 2, min_density_radius 2.5
  o.probe = 0;
  for (double r : {0.5, 1.2, 1.52, 1.88, 2.4})
    EXPECT_EQ(sphere_frequency(atom_at({}, r), o), frequency_for_density(2.5, 2.0)) << r;
  EXPECT_EQ(frequency_for_density(2.5, 2.0), 4);
  EXPECT_EQ(sphere_frequency(atom_at({}, 1.88), o), 4);  // the density alone: 3
  EXPECT_EQ(sphere_frequency(atom_at({}, 1.52), o), 4);  // the density alone: 2
  o.probe = 1.4;  // larger spheres: the density alone decides
  for (double r : {1.1, 1.52, 1.88, 2.5})
    EXPECT_EQ(sphere_frequency(atom_at({}, r), o), frequency_for_density(r + 1.4, 2.0)) << r;
  o.probe = 0;
  o.min_density_radius = 0;
  EXPECT_EQ(sphere_frequency(atom_at({}, 1.88), o), 3);
  EXPECT_EQ(sphere_frequency(atom_at({}, 1.52), o), 2);
  o.min_density_radius = 2.5;
  o.frequency = 2;  // a fixed frequency still overrides everything
  EXPECT_EQ(sphere_frequency(atom_at({}, 1.52), o), 2);
  o.frequency = 0;
  const std::vector<Atom> atoms{atom_at({}, 1.52)};
  EXPECT_EQ(estimate_resources(atoms, o).sphere_faces, 320u);
  EXPECT_EQ(plan_spheres(atoms, o).faces, 320u);
}

// The accuracy target at the defaults: total area and volume within 0.5 % of the exact
// union of balls, for the van der Waals (probe 0) and the solvent-accessible (1.4) surface.
class CrambinAccuracy : public ::testing::TestWithParam<double> {};

TEST_P(CrambinAccuracy, WithinHalfAPercentOfTheExactUnionOfBalls) {
  const double probe = GetParam();
  const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  std::vector<Vec3> centres;
  std::vector<double> radii;
  for (const Atom& a : s.atoms) {
    centres.push_back(a.centre);
    radii.push_back(a.radius + probe);
  }
  const BallUnionMeasure exact = measure_ball_union(centres, radii, 1000);
  SphereUnionOptions o;
  o.spheres.probe = probe;
  const SphereUnion r = solvent_accessible_surface(s.atoms, o);
  EXPECT_NEAR(surface_area(r.mesh), exact.area, 0.005 * exact.area) << "probe " << probe;
  EXPECT_NEAR(signed_volume(r.mesh), exact.volume, 0.005 * exact.volume) << "probe " << probe;
}

INSTANTIATE_TEST_SUITE_P(BothProbes, CrambinAccuracy, ::testing::Values(0.0, 1.4));

TEST(Surface, CrambinAreaAgreesWithLeeRichards) {
  // FreeSASA 2.1.2 (Lee-Richards, ProtOr radii, probe 1.4) gives 2999.32 A^2 for 1crn.pdb.
  const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  const SphereUnion r = solvent_accessible_surface(s.atoms, {});
  EXPECT_NEAR(surface_area(r.mesh), 2999.32, 0.005 * 2999.32);
}

TEST(Surface, SameResultWithOneOrTwoThreads) {
  const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  SphereUnionOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const SphereUnion a = solvent_accessible_surface(s.atoms, one);
  const SphereUnion b = solvent_accessible_surface(s.atoms, two);
  ASSERT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size());
  EXPECT_TRUE(a.mesh.vertices == b.mesh.vertices);
  EXPECT_TRUE(a.mesh.faces == b.mesh.faces);
  EXPECT_TRUE(a.mesh.face_tags == b.mesh.face_tags);
}

TEST(Surface, OuterOnlyDropsCavities) {
  const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  const SphereUnion r = solvent_accessible_surface(s.atoms, {});
  const auto components = measure_components(r.mesh);
  ASSERT_GE(components.size(), 2u);  // crambin has a small cavity at this resolution
  EXPECT_FALSE(components.front().cavity());
  const Mesh outer = outer_surface_only(r.mesh);
  EXPECT_TRUE(valid(outer));
  EXPECT_EQ(measure_components(outer).size(), 1u);
  EXPECT_GT(signed_volume(outer), signed_volume(r.mesh));  // cavities no longer subtracted
}

}  // namespace
}  // namespace molsurf
