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

using ses_reference::atom_at;
using ses_reference::cage;
using ses_reference::ring;

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

TEST(SolventExcludedSurface, OfASmallAtomSplitsTheFacetsErrorBetweenAreaAndVolume) {
  // Its SAS sphere (r + probe 2.6 A) has frequency 4 at density 2, whose area-corrected
  // facets hold 0.58 % less volume than the sphere: the contact patch is drawn where the
  // area is as much too large as the volume too small. The cleanup then coarsens it to the
  // density asked (edges under 0.57 A), within its 0.1 % budgets of area and volume.
  const double r = 1.37;
  const std::vector<Atom> atom = {atom_at({0.5, 0.25, -1}, r)};
  ComputeSurfaceOptions drawn_options;
  drawn_options.surface = SurfaceKind::ses;
  drawn_options.spheres.probe = 1.23;
  drawn_options.cleanup = false;
  const ComputedSurface s = compute_surface(atom, drawn_options);
  const double area = 4 * std::numbers::pi * r * r, volume = 4.0 / 3 * std::numbers::pi * r * r * r;
  const ComputedSurface cleaned = ses_of(atom, 1.23);
  EXPECT_LT(relative(cleaned.measures.area, area), 0.005);
  EXPECT_LT(relative(cleaned.measures.volume, volume), 0.005);
  EXPECT_GT(s.measures.area, area);
  EXPECT_LT(s.measures.volume, volume);
  EXPECT_LT(relative(s.measures.area, area), 0.003);
  EXPECT_LT(relative(s.measures.volume, volume), 0.003);
  EXPECT_NEAR(relative(s.measures.area, area), relative(s.measures.volume, volume), 1e-3);
}

TEST(SolventExcludedSurface, OfASmallSpindlePairMatchesTheClosedFormAndTheDistanceReference) {
  // The degenerate battery's Spindle_7: both SAS spheres at frequency 4, the probe's circle
  // 0.4 probe radii; its volume was 0.65 % low against the closed form.
  const double r1 = 1.3728084383501855, r2 = 1.3384615093444743, d = 5.0764517354610614, probe = 1.2313435505917587;
  const std::vector<Atom> atoms = {atom_at({0, 0, 0}, r1), atom_at({d, 0, 0}, r2)};
  const ComputedSurface s = ses_of(atoms, probe);
  EXPECT_TRUE(s.check.valid());
  EXPECT_EQ(s.measures.components.size(), 2u);
  const ses_reference::AreaVolume exact = ses_reference::two_atoms(r1, r2, d, probe);
  EXPECT_LT(relative(s.measures.area, exact.area), 0.005) << s.measures.area << " vs " << exact.area;
  EXPECT_LT(relative(s.measures.volume, exact.volume), 0.005) << s.measures.volume << " vs " << exact.volume;
  const double reference = ses_reference::ExcludedSolid(atoms, probe).grid_volume(0.1);
  EXPECT_LT(relative(s.measures.volume, reference), 0.005) << s.measures.volume << " vs " << reference;
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

// The rolled surface's every defect makes the ridges (not the first ones the threads
// reach), and the cleanup's sweeps are by cells: the same surface on one and two threads.
TEST(SolventExcludedSurface, IsTheSameOnOneAndTwoThreads) {
  const Structure crambin = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  const std::vector<Atom> atoms(crambin.atoms.begin(), crambin.atoms.begin() + 120);
  std::vector<ComputedSurface> surfaces;
  for (int threads : {1, 2}) {
    ComputeSurfaceOptions options;
    options.surface = SurfaceKind::ses;
    options.threads = threads;
    surfaces.push_back(compute_surface(atoms, options));
  }
  EXPECT_TRUE(surfaces[0].check.valid());
  EXPECT_TRUE(surfaces[0].mesh.faces == surfaces[1].mesh.faces);
  EXPECT_TRUE(surfaces[0].mesh.vertices == surfaces[1].mesh.vertices);
  EXPECT_TRUE(surfaces[0].mesh.face_tags == surfaces[1].mesh.face_tags);
}

struct Placement {
  const char* name;
  std::vector<Atom> atoms;
  double probe = 1.4;
  long euler = 2;  // of the whole surface: 2 per sphere-like shell, 0 per torus-like one
};

std::vector<Placement> degenerate_placements() {
  const double s = 5.0 / std::sqrt(3.0);  // a triangle of side 5: the probes above and below overlap
  std::vector<Placement> p;
  p.push_back({"probes above and below a triangle overlap (exactly symmetric)",
               {atom_at({s, 0, 0}, 1.7), atom_at({-s / 2, s * std::sqrt(3.0) / 2, 0}, 1.7),
                atom_at({-s / 2, -s * std::sqrt(3.0) / 2, 0}, 1.7)},
               1.4,
               0});
  // Six atoms in a ring: a probe at its centre touches all six at ring radius 3.1 (it passes
  // above that); below, the probes touching all six from above and below overlap (a tunnel
  // in the SES, through a point where six spheres meet) down to ring radius 2.77, and the
  // hole closes under it.
  p.push_back({"ring whose hole the probe just passes", ring(6, 3.15, 1.7), 1.4, 0});
  p.push_back({"ring whose hole the probe just fails to pass", ring(6, 3.05, 1.7), 1.4, 0});
  p.push_back({"ring whose probes above and below just overlap", ring(6, 2.79, 1.7), 1.4, 0});
  p.push_back({"ring whose probes above and below just miss", ring(6, 2.75, 1.7), 1.4, 2});
  // A regular tetrahedron of side 5: the probe cannot pass a face, but its positions inside
  // (0.2 A from the centre, all four overlapping) and outside each face (1.64 A apart)
  // overlap, so the excluded solid has a tunnel through each face into the middle: genus 3.
  const double t = 5 / (2 * std::sqrt(2.0));
  p.push_back({"four atoms whose reentrant patches overlap",
               {atom_at({t, t, t}, 1.6), atom_at({t, -t, -t}, 1.6), atom_at({-t, t, -t}, 1.6), atom_at({-t, -t, t}, 1.6)},
               1.4,
               -4});
  p.push_back({"a probe larger than the gaps between atoms", ring(5, 2.6, 1.5), 3.0, 2});
  // A cage whose atoms leave no gap for the probe: a cavity inside (an outer shell and a
  // cavity shell, 2 each).
  p.push_back({"cage with a cavity", cage(48, 6.5, 1.8), 1.4, 4});
  return p;
}

TEST(SolventExcludedSurface, DegeneratePlacementsAreValidAndMatchTheDistanceReference) {
  for (const Placement& p : degenerate_placements()) {
    SCOPED_TRACE(p.name);
    const ComputedSurface s = ses_of(p.atoms, p.probe);
    EXPECT_TRUE(s.check.valid());
    EXPECT_EQ(s.check.euler_characteristic, p.euler);
    EXPECT_EQ(s.check.contact_pairs, 0u);
    const double reference = ses_reference::ExcludedSolid(p.atoms, p.probe).grid_volume(0.1);
    EXPECT_LT(relative(s.measures.volume, reference), 0.005) << s.measures.volume << " vs " << reference;
  }
}

TEST(SolventExcludedSurface, RingsJustWiderThanTheProbesThresholdKeepTheirTunnelAndTheirVolume) {
  // The probe passes the hole with 3 mA (the degenerate battery's Ring_4) or 3e-9 A (Ring_8)
  // to spare. Each atom's SAS patch narrows to a neck at the hole, which the mesh pinches to
  // a point: the atom's faces form two fans around one SAS vertex, whose contact vertices
  // scaled from that vertex coincided and touched (Ring_8 ended with an error, Ring_4 came
  // from the coarsened SAS 0.76 % high); each is drawn from inside its own fan.
  struct Ring {
    int atoms;
    double r, probe, offset;
  };
  for (const Ring& c : {Ring{6, 1.6715019396236861, 1.4837225921191997, 1e-3},
                        Ring{7, 1.7751079917106116, 1.0420492930000027, 1e-9}}) {
    SCOPED_TRACE(testing::Message() << c.atoms << " atoms, offset " << c.offset);
    const std::vector<Atom> atoms = ring(c.atoms, (c.r + c.probe) * (1 + c.offset), c.r);
    const ComputedSurface s = ses_of(atoms, c.probe);
    EXPECT_TRUE(s.check.valid());
    EXPECT_EQ(s.check.contact_pairs, 0u);
    EXPECT_EQ(s.check.euler_characteristic, 0);  // a torus: the tunnel through the ring stays open
    const double reference = ses_reference::ExcludedSolid(atoms, c.probe).grid_volume(0.1);
    EXPECT_LT(relative(s.measures.volume, reference), 0.005) << s.measures.volume << " vs " << reference;
  }
}

TEST(SolventExcludedSurface, FourAtomsWhoseReentrantPatchesOverlapKeepTheirVolumeThroughTheCleanup) {
  // The degenerate battery's Tetrahedron_0: the cleanup's collapses of short edges across
  // the ridges where the overlapping probes meet took 0.7 % of the volume off (-0.61 % from
  // the reference); the SES's cleanup keeps each component's volume within 0.1 %.
  const double r = 1.5374127753616338, probe = 1.3495338196329048;
  const std::vector<Atom> atoms = {atom_at({2.7202484815907821, 0.90296599676048062, -0.93243669737378698}, r),
                                   atom_at({0.30361716949412909, -2.3667985217199687, 1.8413633426036489}, r),
                                   atom_at({-1.668297556596305, -0.78864796159353401, -2.3831397866766233}, r),
                                   atom_at({-1.3555680944886062, 2.2524804865530221, 1.4742131414467614}, r)};
  const ComputedSurface s = ses_of(atoms, probe);
  EXPECT_TRUE(s.check.valid());
  const double reference = ses_reference::ExcludedSolid(atoms, probe).grid_volume(0.1);
  EXPECT_LT(relative(s.measures.volume, reference), 0.005) << s.measures.volume << " vs " << reference;
}

TEST(SolventExcludedSurface, ACageKeepsItsCavityAsAnInwardComponentAndOuterOnlyDropsIt) {
  const std::vector<Atom> atoms = cage(48, 6.5, 1.8);
  const ComputedSurface all = ses_of(atoms);
  std::size_t cavities = 0;
  for (const auto& c : all.measures.components) cavities += c.cavity();
  EXPECT_EQ(cavities, 1u);
  ComputeSurfaceOptions options;
  options.surface = SurfaceKind::ses;
  options.outer_only = true;
  const ComputedSurface outer = compute_surface(atoms, options);
  ASSERT_EQ(outer.measures.components.size(), 1u);
  EXPECT_FALSE(outer.measures.components[0].cavity());
  EXPECT_GT(outer.measures.volume, all.measures.volume);  // the cavity's void is no longer taken out
}

TEST(SolventExcludedSurface, HasAboutTheVerticesPerSquareAngstromTheDensityAsks) {
  // Drawn from the SAS mesh, the SES inherits its short seam edges and its contact patches
  // are the SAS's faces scaled down: 4 times the vertices asked. The cleanup collapses edges
  // under 0.8 / sqrt(density) A (an even mesh's edge at density D is 1.07 / sqrt(D)).
  const Structure crambin = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  const std::vector<Atom> atoms(crambin.atoms.begin(), crambin.atoms.begin() + 40);
  for (const double density : {0.5, 1.0, 2.0, 4.0}) {
    SCOPED_TRACE(density);
    const ComputedSurface s = ses_of(atoms, 1.4, density);
    const double per_square_angstrom = static_cast<double>(s.measures.vertices) / s.measures.area;
    EXPECT_GT(per_square_angstrom, 0.7 * density);
    EXPECT_LT(per_square_angstrom, 1.6 * density);
    EXPECT_GE(s.quality_after.min_angle_deg, 1.0);
  }
}

TEST(SolventExcludedSurface, RefusesAProbeOfZeroAndAtomsOfRadiusZero) {
  EXPECT_THROW(ses_of({atom_at({0, 0, 0}, 1.5)}, 0.0), Error);
  EXPECT_THROW(ses_of({atom_at({0, 0, 0}, 1.5), atom_at({2, 0, 0}, 0.0)}), Error);
}

}  // namespace
}  // namespace molsurf
