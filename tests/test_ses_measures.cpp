// The SES's area and volume from the arrangement's patches (ses_measures.hpp), against
// references written apart from it (ses_reference.hpp): the closed forms of one and two atoms,
// spindle tori included, and the volume of the points whose distance to the probe-accessible
// region is at least the probe radius, counted on a grid, where probes overlap.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include "molsurf/compute_areas.hpp"
#include "molsurf/io.hpp"
#include "molsurf/ses_measures.hpp"
#include "ses_reference.hpp"

namespace molsurf {
namespace {

using ses_reference::atom_at;

SesMeasures measured(const std::vector<Atom>& atoms, double probe, double cell = 0.35) {
  SphereOptions spheres;
  spheres.probe = probe;
  return measure_ses(atoms, probe, compute_areas(atoms, spheres).arrangement, false, cell);
}

void expect_parts_add_up(const SesMeasures& m) {
  EXPECT_NEAR(m.area, m.contact_area + m.toroidal_area + m.reentrant_area, 1e-9 * m.area);
  EXPECT_NEAR(std::accumulate(m.area_per_atom.begin(), m.area_per_atom.end(), 0.0), m.area, 1e-9 * m.area);
}

TEST(SesMeasures, OneAtomIsItsVanDerWaalsSphere) {
  const double r = 1.8;
  const SesMeasures m = measured({atom_at({0.3, -1, 2}, r)}, 1.4);
  EXPECT_NEAR(m.area, 4 * std::numbers::pi * r * r, 1e-10);
  EXPECT_NEAR(m.volume, 4.0 / 3 * std::numbers::pi * r * r * r, 1e-10);
  EXPECT_EQ(m.toroidal_area, 0.0);
  EXPECT_EQ(m.reentrant_area, 0.0);
}

struct TwoAtoms {
  double r1, r2, d, probe;
};

class SesMeasuresTwoAtoms : public ::testing::TestWithParam<TwoAtoms> {};

// The saddle of two atoms is cut by nothing but, for a spindle torus, its own axis: the
// quadrature's cells along the axis are halved there, and the rest is smooth.
TEST_P(SesMeasuresTwoAtoms, MatchTheClosedFormOfTheSolidOfRevolution) {
  const TwoAtoms c = GetParam();
  const std::vector<Atom> atoms{atom_at({0, 0, 0}, c.r1), atom_at({c.d * 0.6, c.d * 0.8, 0}, c.r2)};
  const SesMeasures m = measured(atoms, c.probe);
  const ses_reference::AreaVolume exact = ses_reference::two_atoms(c.r1, c.r2, c.d, c.probe);
  EXPECT_NEAR(m.area / exact.area, 1.0, 2e-5) << m.area << " vs " << exact.area;
  EXPECT_NEAR(m.volume / exact.volume, 1.0, 2e-5) << m.volume << " vs " << exact.volume;
  EXPECT_GT(m.toroidal_area, 0.0);
  EXPECT_EQ(m.reentrant_area, 0.0);
  expect_parts_add_up(m);
}

INSTANTIATE_TEST_SUITE_P(Placements, SesMeasuresTwoAtoms,
                         ::testing::Values(TwoAtoms{1.7, 1.5, 3.5, 1.4},   // a ring torus
                                           TwoAtoms{1.5, 1.5, 5.4, 1.4},   // spindle: two components
                                           TwoAtoms{1.8, 1.2, 4.6, 1.4},   // spindle, unequal
                                           TwoAtoms{1.6, 1.6, 1.0, 1.4},   // nearly one sphere
                                           TwoAtoms{1.52, 1.7, 3.1, 3.0}));  // a large probe

// Where probes overlap, the reentrant and toroidal patches are cut by other probes: the
// volume against the distance reference counted on a grid of 0.05 A (its own error up to about
// a tenth of a percent on these; a patch left out or counted twice costs percents).
struct Placement {
  const char* name;
  std::vector<Atom> atoms;
  double probe;
};

std::vector<Placement> overlapping_probes() {
  const double s3 = std::sqrt(3.0);
  return {
      {"triangle of side 5, probes above and below overlap",
       {atom_at({0, 0, 0}, 1.7), atom_at({5, 0, 0}, 1.7), atom_at({2.5, 2.5 * s3, 0}, 1.7)},
       1.4},
      {"tetrahedron of side 5",
       {atom_at({0, 0, 0}, 1.6), atom_at({5, 0, 0}, 1.6), atom_at({2.5, 2.5 * s3, 0}, 1.6),
        atom_at({2.5, 2.5 / s3, 5 * std::sqrt(2.0 / 3)}, 1.6)},
       1.4},
      // Five and six atoms whose spheres (nearly: rounded coordinates) meet at one probe
      // position above and one below the ring.
      {"ring of 5, probe 3", ses_reference::ring(5, 3.2, 1.7), 3.0},
      {"ring of 6, the probe just fails to pass", ses_reference::ring(6, 3.05, 1.7), 1.4},
  };
}

TEST(SesMeasures, WhereProbesOverlapTheVolumeIsTheDistanceReferences) {
  for (const Placement& p : overlapping_probes()) {
    const SesMeasures m = measured(p.atoms, p.probe);
    const double reference = ses_reference::ExcludedSolid(p.atoms, p.probe).grid_volume(0.05);
    EXPECT_NEAR(m.volume / reference, 1.0, 2e-3) << p.name << ": " << m.volume << " vs " << reference;
    EXPECT_GT(m.reentrant_area, 0.0) << p.name;
    expect_parts_add_up(m);
    // Halving the cells moves the numbers by far less than the mesh's errors (tenths of a percent).
    const SesMeasures finer = measured(p.atoms, p.probe, 0.175);
    EXPECT_NEAR(finer.area / m.area, 1.0, 1e-4) << p.name;
    EXPECT_NEAR(finer.volume / m.volume, 1.0, 1e-4) << p.name;
  }
}

TEST(SesMeasures, CrambinsVolumeIsTheGridReferencesAndItsAreaConverges) {
  const std::vector<Atom> atoms = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb").atoms;
  const SesMeasures m = measured(atoms, 1.4);
  // The grid reference's count at 0.1 A (docs/ses.md): 4 890.28 A^3, its error a few hundredths.
  EXPECT_NEAR(m.volume / 4890.28, 1.0, 5e-4) << m.volume;
  // The contact area is the arrangement's exposed patches scaled onto the atoms.
  EXPECT_NEAR(m.contact_area, 918.53, 0.01);
  expect_parts_add_up(m);
  const SesMeasures finer = measured(atoms, 1.4, 0.175);
  EXPECT_NEAR(finer.area / m.area, 1.0, 1e-4) << finer.area << " vs " << m.area;
  EXPECT_NEAR(finer.volume / m.volume, 1.0, 1e-4) << finer.volume << " vs " << m.volume;
}

}  // namespace
}  // namespace molsurf
