// The solvent-excluded surface (--surface ses; src/ses/): valid, and its area and volume
// against references written apart from its construction (ses_reference.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/error.hpp"
#include "ses_reference.hpp"

namespace molsurf {
namespace {

Atom atom_at(Vec3 centre, double radius) {
  Atom a;
  a.centre = centre;
  a.radius = radius;
  a.element = "C";
  return a;
}

ComputedSurface ses_of(const std::vector<Atom>& atoms, double probe = 1.4, double density = 2) {
  ComputeSurfaceOptions options;
  options.surface = SurfaceKind::ses;
  options.spheres.probe = probe;
  options.spheres.density = density;
  return compute_surface(atoms, options);
}

double relative(double value, double reference) { return std::abs(value - reference) / reference; }

TEST(SolventExcludedSurface, OfOneAtomIsItsVanDerWaalsSphere) {
  const double r = 1.7;
  const ComputedSurface s = ses_of({atom_at({0.3, -1, 2}, r)});
  EXPECT_TRUE(s.check.valid());
  ASSERT_EQ(s.measures.components.size(), 1u);
  EXPECT_LT(relative(s.measures.area, 4 * std::numbers::pi * r * r), 0.005);
  EXPECT_LT(relative(s.measures.volume, 4.0 / 3 * std::numbers::pi * r * r * r), 0.005);
}

struct TwoAtoms {
  double r1, r2, d;
  std::size_t components;
};

TEST(SolventExcludedSurface, OfTwoAtomsMatchesTheClosedForm) {
  // A torus with a hole, two overlapping van der Waals spheres, and spindle tori whose
  // probe circle is smaller than the probe (the neck cut through: two components).
  for (const TwoAtoms& c : {TwoAtoms{1.7, 1.5, 3.5, 1}, TwoAtoms{1.8, 1.2, 2.0, 1}, TwoAtoms{1.5, 1.5, 5.4, 2},
                            TwoAtoms{1.9, 1.4, 5.6, 2}}) {
    SCOPED_TRACE(testing::Message() << "r1 " << c.r1 << " r2 " << c.r2 << " d " << c.d);
    const ComputedSurface s = ses_of({atom_at({0, 0, 0}, c.r1), atom_at({c.d, 0, 0}, c.r2)});
    const ses_reference::AreaVolume exact = ses_reference::two_atoms(c.r1, c.r2, c.d, 1.4);
    EXPECT_TRUE(s.check.valid());
    EXPECT_EQ(s.measures.components.size(), c.components);
    EXPECT_LT(relative(s.measures.area, exact.area), 0.005) << s.measures.area << " vs " << exact.area;
    EXPECT_LT(relative(s.measures.volume, exact.volume), 0.005) << s.measures.volume << " vs " << exact.volume;
  }
}

TEST(SolventExcludedSurface, AtomsTooFarApartForTheProbeToBridgeGiveTheirSpheres) {
  const double r = 1.6;
  const ComputedSurface s = ses_of({atom_at({0, 0, 0}, r), atom_at({7, 0, 0}, r)});
  ASSERT_EQ(s.measures.components.size(), 2u);
  EXPECT_LT(relative(s.measures.area, 8 * std::numbers::pi * r * r), 0.005);
}

TEST(SolventExcludedSurface, LiesBetweenTheVanDerWaalsAndTheAccessibleSurfaces) {
  const Structure crambin = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  const std::vector<Atom> atoms(crambin.atoms.begin(), crambin.atoms.begin() + 60);
  ComputeSurfaceOptions options;
  options.exact_areas = false;
  options.surface = SurfaceKind::vdw;
  const ComputedSurface vdw = compute_surface(atoms, options);
  options.surface = SurfaceKind::sas;
  options.spheres.probe = 0;
  const ComputedSurface probe0 = compute_surface(atoms, options);
  EXPECT_EQ(vdw.measures.area, probe0.measures.area);  // vdw is the SAS at probe 0
  options.spheres.probe = 1.4;
  const ComputedSurface sas = compute_surface(atoms, options);
  const ComputedSurface ses = ses_of(atoms);
  EXPECT_GT(ses.measures.volume, vdw.measures.volume);
  EXPECT_LT(ses.measures.volume, sas.measures.volume);
  EXPECT_LT(ses.measures.area, sas.measures.area);
}

TEST(SolventExcludedSurface, VolumeOfACrambinFragmentMatchesTheDistanceReference) {
  const Structure crambin = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  const std::vector<Atom> atoms(crambin.atoms.begin(), crambin.atoms.begin() + 40);
  const ComputedSurface s = ses_of(atoms);
  const double reference = ses_reference::ExcludedSolid(atoms, 1.4).grid_volume(0.2);
  EXPECT_LT(relative(s.measures.volume, reference), 0.005) << s.measures.volume << " vs " << reference;
  // Every face belongs to an atom, and the atoms' areas add up to the surface's.
  double sum = 0;
  for (double a : s.measures.atom_area) sum += a;
  EXPECT_NEAR(sum, s.measures.area, 1e-9 * s.measures.area);
  for (std::int32_t tag : s.mesh.face_tags) {
    ASSERT_GE(tag, 0);
    ASSERT_LT(tag, static_cast<std::int32_t>(atoms.size()));
  }
}

TEST(SolventExcludedSurface, RefusesAProbeOfZeroAndAtomsOfRadiusZero) {
  EXPECT_THROW(ses_of({atom_at({0, 0, 0}, 1.5)}, 0.0), Error);
  EXPECT_THROW(ses_of({atom_at({0, 0, 0}, 1.5), atom_at({2, 0, 0}, 0.0)}), Error);
}

}  // namespace
}  // namespace molsurf
