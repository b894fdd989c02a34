#include <gtest/gtest.h>

#include <numeric>
#include <string>
#include <vector>

#include "atom_fixtures.hpp"
#include "degenerate_placements.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/surface.hpp"
#include "molsurf/surface_report.hpp"
#include "surface/cleanup.hpp"
#include "surface/solvent_accessible_surface.hpp"

namespace molsurf {
namespace {

const std::string kData = MOLSURF_DATA_DIR;

using testing::atom_at;

const Structure& crambin() {
  static const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  return s;
}

bool same_mesh(const Mesh& a, const Mesh& b) {
  if (a.faces != b.faces || a.face_tags != b.face_tags || a.vertices.size() != b.vertices.size()) return false;
  for (std::size_t v = 0; v < a.vertices.size(); ++v)
    if (a.vertices[v].x != b.vertices[v].x || a.vertices[v].y != b.vertices[v].y || a.vertices[v].z != b.vertices[v].z)
      return false;
  return true;
}

// The stages as the command line ran them before compute_surface existed: union, cleanup,
// check, measures. The one call must give exactly this surface and these numbers.
TEST(ComputeSurface, EqualsTheStagesRunOneByOneOnCrambin) {
  const std::vector<Atom>& atoms = crambin().atoms;
  SphereUnionOptions surface_options;
  Mesh expected = solvent_accessible_surface(atoms, surface_options).mesh;
  const CleanupStats cleanup = improve_surface(expected);
  const MeshCheck check = check_mesh(expected);
  ASSERT_TRUE(check.valid());
  const SurfaceReport report = make_surface_report(expected, check);
  const std::vector<double> atom_area = area_per_atom(expected, atoms.size());

  const ComputedSurface r = compute_surface(atoms);
  EXPECT_TRUE(same_mesh(r.mesh, expected));
  EXPECT_EQ(r.method, SurfaceMethod::one_pass);
  EXPECT_TRUE(r.notes.empty());
  EXPECT_TRUE(r.check.valid());
  EXPECT_TRUE(r.check.self_intersections_checked);
  EXPECT_EQ(r.measures.faces, report.faces);
  EXPECT_EQ(r.measures.vertices, report.vertices);
  EXPECT_EQ(r.measures.area, report.area);
  EXPECT_EQ(r.measures.volume, report.volume);
  ASSERT_EQ(r.measures.components.size(), report.components.size());
  for (std::size_t c = 0; c < report.components.size(); ++c) {
    EXPECT_EQ(r.measures.components[c].faces, report.components[c].faces);
    EXPECT_EQ(r.measures.components[c].volume, report.components[c].volume);
  }
  EXPECT_EQ(r.measures.atom_area, atom_area);
  ASSERT_TRUE(r.cleanup.has_value());
  EXPECT_EQ(r.cleanup->collapses, cleanup.collapses);
  EXPECT_EQ(r.cleanup->flips, cleanup.flips);
  // The cleanup's own measure of the cleaned surface is the check's (measured once).
  EXPECT_EQ(r.cleanup->after.faces, cleanup.after.faces);
  EXPECT_EQ(r.cleanup->after.min_angle_deg, cleanup.after.min_angle_deg);
  EXPECT_EQ(r.cleanup->after.mean_min_angle_deg, cleanup.after.mean_min_angle_deg);
  EXPECT_EQ(r.cleanup->after.below_5deg, cleanup.after.below_5deg);
  EXPECT_EQ(r.quality_before.below_5deg, cleanup.before.below_5deg);
  EXPECT_EQ(r.quality_after.min_angle_deg, check.quality.min_angle_deg);
  EXPECT_EQ(r.quality_after.below_5deg, check.quality.below_5deg);
  EXPECT_LT(r.quality_after.below_5deg, r.quality_before.below_5deg);  // the cleanup did something
  // Crambin at the defaults: one outer surface and its cavities, area ~ 3000 A^2.
  EXPECT_GT(r.measures.area, 2500);
  EXPECT_LT(r.measures.area, 3500);
  EXPECT_NEAR(std::accumulate(r.measures.atom_area.begin(), r.measures.atom_area.end(), 0.0), r.measures.area,
              1e-9 * r.measures.area);
}

TEST(ComputeSurface, PairwiseMethodGivesTheSameAreaAndVolume) {
  ComputeSurfaceOptions options;
  options.method = SurfaceMethod::pairwise;
  options.cleanup = false;
  const ComputedSurface pairwise = compute_surface(crambin().atoms, options);
  options.method = SurfaceMethod::one_pass;
  const ComputedSurface one_pass = compute_surface(crambin().atoms, options);
  EXPECT_EQ(pairwise.method, SurfaceMethod::pairwise);
  EXPECT_NEAR(pairwise.measures.area, one_pass.measures.area, 1e-12 * one_pass.measures.area);
  EXPECT_NEAR(pairwise.measures.volume, one_pass.measures.volume, 1e-12 * one_pass.measures.volume);
}

// Two atoms 1e17 A from the origin: there a double's spacing (16 A) exceeds the spheres,
// so every method's surface is degenerate. The one-pass surface fails, the pairwise
// fallback fails too, and the call returns nothing.
// At coordinates of 1e17 A a 1.7 A sphere's icosphere rounds to a few points (once a
// surface that failed its check, returned as SurfaceCheckFailed): refused plainly first.
TEST(ComputeSurface, SpheresTooSmallForTheirCoordinatesAreAPlainError) {
  const std::vector<Atom> atoms{atom_at({1e17, 0, 0}, 1.7), atom_at({1e17 + 2, 0, 0}, 1.7)};
  try {
    compute_surface(atoms);
    ADD_FAILURE() << "no error";
  } catch (const SurfaceCheckFailed& failed) {
    ADD_FAILURE() << "a failed check instead of a plain error: " << failed.what();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("atom 0: its sphere's radius 3.1 A is too small for its position"),
              std::string::npos)
        << e.what();
  }
}

// Icosahedral shells of frequency-1 spheres on which the pairwise union used to stop
// (the advancing front found no valid triangle: an operand touching itself along runs of
// vertices a rounding error apart, crossed there by a face of the other operand) or give
// invalid surfaces. compute_surface reported the stops as a plain molsurf::Error naming
// the method; each merge now collapses such runs and rounds again what rounding folded,
// and every one of these gives a valid surface.
TEST(ComputeSurface, PairwiseJoinsIcosahedralShellsThatUsedToStop) {
  for (const std::uint32_t seed : {1003u, 1035u, 1059u, 1082u, 1084u, 1086u, 1091u, 1099u}) {
    const auto placement = testing::degenerate_placement(testing::PlacementFamily::icosahedral_shell, seed);
    for (const double probe : {0.7, 1.4}) {
      ComputeSurfaceOptions o;
      o.spheres.frequency = 1;
      o.spheres.probe = probe;
      o.method = SurfaceMethod::pairwise;
      EXPECT_TRUE(compute_surface(placement.atoms, o).check.valid()) << "seed " << seed << ", probe " << probe;
      o.method = SurfaceMethod::one_pass;
      EXPECT_TRUE(compute_surface(placement.atoms, o).check.valid()) << "seed " << seed << ", probe " << probe;
    }
  }
}

TEST(ComputeSurface, TimingsAndProgressCoverEveryStage) {
  std::vector<SurfaceStage> started;
  std::size_t union_reports = 0;
  ComputeSurfaceOptions options;
  options.progress = [&](SurfaceStage stage, std::size_t done, std::size_t total) {
    EXPECT_LE(done, total);
    if (done == 0) started.push_back(stage);
    if (stage == SurfaceStage::union_) ++union_reports;
  };
  const ComputedSurface r = compute_surface(crambin().atoms, options);
  const std::vector<SurfaceStage> order{SurfaceStage::union_, SurfaceStage::cleanup, SurfaceStage::check,
                                        SurfaceStage::measures};
  EXPECT_EQ(started, order);
  EXPECT_GT(union_reports, 2u);  // start, the union's own (done, total), end
  const ComputeSurfaceTimings& t = r.seconds;
  EXPECT_GT(t.union_, 0);
  EXPECT_GT(t.cleanup, 0);
  EXPECT_GT(t.check, 0);
  EXPECT_GT(t.measures, 0);
  EXPECT_GE(t.total, t.union_ + t.cleanup + t.check + t.measures);
  EXPECT_EQ(std::string(surface_stage_name(SurfaceStage::union_)), "union");
  EXPECT_EQ(std::string(surface_stage_name(SurfaceStage::measures)), "measures");
}

TEST(ComputeSurface, CleanupOff) {
  ComputeSurfaceOptions options;
  options.cleanup = false;
  const ComputedSurface r = compute_surface(crambin().atoms, options);
  EXPECT_FALSE(r.cleanup.has_value());
  EXPECT_TRUE(r.check.valid());
  EXPECT_EQ(r.seconds.cleanup, 0);
  EXPECT_EQ(r.quality_before.below_5deg, r.quality_after.below_5deg);
  EXPECT_EQ(r.quality_before.min_angle_deg, r.quality_after.min_angle_deg);
  const Mesh union_only = solvent_accessible_surface(crambin().atoms, SphereUnionOptions{}).mesh;
  EXPECT_TRUE(same_mesh(r.mesh, union_only));
  const ComputedSurface cleaned = compute_surface(crambin().atoms);
  EXPECT_NEAR(cleaned.measures.area, r.measures.area, 1e-3 * r.measures.area);  // the cleanup's area budget
}

TEST(ComputeSurface, OuterOnlyDropsTheCavities) {
  const ComputedSurface all = compute_surface(crambin().atoms);
  std::size_t cavities = 0;
  for (const ComponentMeasure& c : all.measures.components) cavities += c.cavity();
  ASSERT_GT(cavities, 0u);  // crambin at probe 1.4 has cavities; otherwise this test shows nothing
  ComputeSurfaceOptions options;
  options.outer_only = true;
  const ComputedSurface outer = compute_surface(crambin().atoms, options);
  for (const ComponentMeasure& c : outer.measures.components) EXPECT_FALSE(c.cavity());
  EXPECT_GT(outer.measures.volume, all.measures.volume);  // cavities no longer subtracted
}

TEST(ComputeSurface, ThreadCountDoesNotChangeTheSurface) {
  ComputeSurfaceOptions options;
  options.threads = 1;
  const ComputedSurface one = compute_surface(crambin().atoms, options);
  options.threads = 2;
  const ComputedSurface two = compute_surface(crambin().atoms, options);
  EXPECT_EQ(one.threads, 1);
  EXPECT_EQ(two.threads, 2);
  EXPECT_TRUE(same_mesh(one.mesh, two.mesh));
}

TEST(ComputeSurface, NoAtomsGiveAnEmptySurface) {
  const ComputedSurface r = compute_surface({});
  EXPECT_EQ(r.mesh.face_count(), 0u);
  EXPECT_EQ(r.measures.area, 0);
  EXPECT_TRUE(r.measures.components.empty());
}

TEST(ComputeSurface, TooManySphereFacesAreRefusedBeforeAnySphereIsBuilt) {
  ComputeSurfaceOptions options;
  options.max_sphere_faces = 1000;
  options.source = "crambin.pdb";
  try {
    compute_surface(crambin().atoms, options);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("crambin.pdb: ", 0), 0u) << message;
    EXPECT_NE(message.find("faces"), std::string::npos) << message;
  }
}

// The estimate trims a sample of atoms as the pass does: on structures of different sizes
// and at both probes it must land near the union's real face count.
TEST(SurfaceSizeEstimate, IsNearTheUnionsFaceCount) {
  const Structure haemoglobin = read_structure(kData + "/pdb/2hhb.pdb");
  for (const Structure* s : {&crambin(), &haemoglobin})
    for (double probe : {0.0, 1.4}) {
      SphereUnionOptions options;
      options.spheres.probe = probe;
      std::vector<SurfaceSizeEstimate> seen;
      options.check_size = [&seen](const SurfaceSizeEstimate& e) { seen.push_back(e); };
      const Mesh mesh = solvent_accessible_surface(s->atoms, options).mesh;
      ASSERT_EQ(seen.size(), 1u);
      const SurfaceSizeEstimate& e = seen.front();
      EXPECT_EQ(e.atoms, s->atoms.size());
      EXPECT_EQ(e.sampled_atoms, std::min<std::size_t>(s->atoms.size(), 256));
      const double faces = static_cast<double>(mesh.face_count());
      EXPECT_NEAR(static_cast<double>(e.faces), faces, 0.15 * faces) << s->atoms.size() << " atoms, probe " << probe;
      EXPECT_EQ(e.bytes, e.faces * kBytesPerSurfaceFace);
    }
}

TEST(SurfaceSizeEstimate, IsSkippedWhenTheSpheresAreFew) {
  SphereUnionOptions options;
  bool called = false;
  options.check_size = [&called](const SurfaceSizeEstimate&) { called = true; };
  options.estimate_size_above = 1'000'000'000;
  solvent_accessible_surface(crambin().atoms, options);
  EXPECT_FALSE(called);
  options.estimate_size_above = 1000;
  solvent_accessible_surface(crambin().atoms, options);
  EXPECT_TRUE(called);
}

TEST(ComputeSurface, ASurfaceTooLargeForTheMemoryLimitIsRefusedBeforeThePass) {
  ComputeSurfaceOptions options;
  options.max_memory = 1'000'000;  // crambin's 24 000 faces need about 9 MB
  options.source = "crambin.pdb";
  bool union_ran = false;
  options.progress = [&union_ran](SurfaceStage stage, std::size_t done, std::size_t) {
    if (stage == SurfaceStage::union_ && done > 0) union_ran = true;
  };
  try {
    compute_surface(crambin().atoms, options);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("crambin.pdb: ", 0), 0u) << message;
    EXPECT_NE(message.find("--max-memory"), std::string::npos) << message;
    EXPECT_NE(message.find("of 327 atoms"), std::string::npos) << message;
  }
  EXPECT_FALSE(union_ran);
  options.max_memory = 100'000'000;
  EXPECT_NO_THROW(compute_surface(crambin().atoms, options));
}

TEST(AvailableMemory, IsPositiveAndAtMostThePhysicalMemory) {
  const std::uint64_t bytes = available_memory_bytes();
  EXPECT_GT(bytes, 100'000'000u);
}

}  // namespace
}  // namespace molsurf
