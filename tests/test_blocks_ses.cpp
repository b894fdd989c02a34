// The solvent-excluded surface in blocks (src/blocks/ses_piece.*, blocked_ses.*; --surface
// ses with --blocks or under mpirun). Each block draws the SES of its atoms and a halo and
// keeps its own atoms' faces: before cleanup those are the whole structure's SES faces, so
// the pieces glued by position are the single-process SES face for face, on the same exact
// coordinates, across the placements whose SES needs its ridges, retries and pinched
// patches, with atoms on the cutting planes and copies in two blocks. Cleaned (each piece
// with its seam band frozen, then the band with both sides in view): valid, the facets'
// area and volume within twice the cleanup's budget (1e-3) of one process's, the same
// components, no sliver where one process leaves none, and the patches' areas (the report's) the single process's
// exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <tuple>
#include <vector>

#include "atom_fixtures.hpp"
#include "blocks/block_partition.hpp"
#include "blocks/blocked_ses.hpp"
#include "blocks/blocked_surface.hpp"
#include "blocks/seam.hpp"
#include "blocks/ses_piece.hpp"
#include "cli_runner.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "ses/solvent_excluded_surface.hpp"
#include "ses_reference.hpp"

namespace molsurf::blocks {
namespace {

const std::string kData = MOLSURF_DATA_DIR;

struct Placement {
  std::string name;
  std::vector<Atom> atoms;
  double probe = 1.4;
};

std::vector<Placement> placements() {
  using ses_reference::ring;
  std::vector<Placement> p;
  p.push_back({"crambin", read_structure(kData + "/pdb/1crn.pdb").atoms});
  // Rings whose probes overlap above and below (ridges carved), whose hole the probe just
  // passes, and 1e-9 and 1e-3 wider than the probe's threshold (pinched patches; the SES's
  // later attempts, from the union cleaned).
  p.push_back({"ring whose probes above and below just overlap", ring(6, 2.79, 1.7)});
  p.push_back({"ring whose hole the probe just passes", ring(6, 3.15, 1.7)});
  p.push_back({"ring 1e-9 wider than the probe's threshold",
               ring(7, (1.7751079917106116 + 1.0420492930000027) * (1 + 1e-9), 1.7751079917106116),
               1.0420492930000027});
  p.push_back({"ring 1e-3 wider than the probe's threshold",
               ring(6, (1.6715019396236861 + 1.4837225921191997) * (1 + 1e-3), 1.6715019396236861),
               1.4837225921191997});
  // Whole layers of atoms on the cutting planes, faces of neighbours exactly coplanar.
  p.push_back({"lattice on the cutting planes", testing::lattice_4x4x3(3.0)});
  // A copy of an atom in another block, and an atom inside another's ball.
  p.push_back({"copies split across blocks", testing::row_with_copies()});
  return p;
}

// A face as its corners' exact coordinates, turned so the least comes first, and its atom.
using FaceKey = std::tuple<std::array<std::array<double, 3>, 3>, std::int32_t>;

std::vector<FaceKey> face_keys(const Mesh& mesh) {
  std::vector<FaceKey> keys;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    std::array<std::array<double, 3>, 3> corners;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.vertices[mesh.faces[f][k]];
      corners[k] = {p.x, p.y, p.z};
    }
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    keys.emplace_back(corners, mesh.tag(f));
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

TEST(BlockedSes, PiecesBeforeCleanupAreTheWholeSes) {
  for (const Placement& placement : placements()) {
    SphereOptions spheres;
    spheres.probe = placement.probe;
    const Mesh whole = ses_detail::solvent_excluded_surface(placement.atoms, spheres, 2).mesh;
    const std::vector<FaceKey> whole_faces = face_keys(whole);
    for (const std::size_t blocks : {std::size_t{2}, std::size_t{3}}) {
      SCOPED_TRACE(placement.name + ", " + std::to_string(blocks) + " blocks");
      const BlockPartition partition =
          partition_blocks(placement.atoms, spheres, blocks, ses_halo_reach(placement.atoms, spheres));
      std::vector<Mesh> pieces;
      for (std::size_t b = 0; b < blocks; ++b) {
        pieces.push_back(ses_piece_before_cleanup(block_atoms(placement.atoms, partition, b), spheres, 2));
        if (placement.atoms.size() > 100) EXPECT_FALSE(seam_edges(pieces.back()).empty());
      }
      const Mesh glued = glue_by_position(pieces);
      EXPECT_TRUE(seam_edges(glued).empty());
      EXPECT_EQ(glued.vertices.size(), whole.vertices.size());
      EXPECT_TRUE(face_keys(glued) == whole_faces);
      EXPECT_NEAR(surface_area(glued), surface_area(whole), 1e-12 * surface_area(whole));
    }
  }
}

TEST(BlockedSes, CleanedPiecesMatchTheSingleProcessSes) {
  for (const Placement& placement : placements()) {
    ComputeSurfaceOptions options;
    options.surface = SurfaceKind::ses;
    options.spheres.probe = placement.probe;
    options.threads = 2;
    const ComputedSurface whole = compute_surface(placement.atoms, options);
    // Crambin (the slowest) in 3 blocks, as the command test below has it.
    const std::vector<std::size_t> counts =
        placement.atoms.size() > 100 ? std::vector<std::size_t>{3} : std::vector<std::size_t>{2, 3};
    for (const std::size_t blocks : counts) {
      SCOPED_TRACE(placement.name + ", " + std::to_string(blocks) + " blocks");
      std::vector<std::size_t> faces_of(blocks, 0);
      BlockedSurfaceOptions blocked_options;
      blocked_options.blocks = blocks;
      // Asked to stream, the SES is still joined on the first process: the pieces come from it.
      blocked_options.streamed = blocks == 3;
      blocked_options.piece_done = [&](std::size_t b, const Mesh& piece) { faces_of.at(b) = piece.faces.size(); };
      const ComputedSurface blocked = compute_blocked_surface(placement.atoms, options, blocked_options).surface;
      for (const std::string& note : blocked.notes) EXPECT_EQ(note.find("did not join"), std::string::npos) << note;
      const MeshCheck check = check_mesh(blocked.mesh);
      EXPECT_TRUE(check.valid());
      EXPECT_EQ(blocked.check.valid(), check.valid());
      // Each within the cleanup's budgets (1e-3 of the area, of each component's volume) of
      // the same SES before cleanup, so within twice that of each other.
      EXPECT_NEAR(check.area, whole.check.area, 2e-3 * whole.check.area);
      EXPECT_NEAR(check.volume, whole.check.volume, 2e-3 * std::fabs(whole.check.volume));
      EXPECT_EQ(blocked.measures.components.size(), whole.measures.components.size());
      // Where one process leaves no sliver, neither do the blocks (the overlapping probes'
      // singular ridge keeps 22 in one process, 22 to 26 in blocks).
      if (whole.check.quality.below_1deg == 0) EXPECT_EQ(check.quality.below_1deg, 0u);
      ASSERT_TRUE(blocked.ses_patches && whole.ses_patches);
      EXPECT_EQ(blocked.ses_patches->area, whole.ses_patches->area);
      EXPECT_EQ(blocked.ses_patches->volume, whole.ses_patches->volume);
      EXPECT_EQ(blocked.ses_patches->area_per_atom, whole.ses_patches->area_per_atom);
      ASSERT_TRUE(blocked.true_points.has_value());
      std::size_t handed_out = 0;
      for (std::size_t n : faces_of) handed_out += n;
      EXPECT_EQ(handed_out, blocked.mesh.faces.size());
    }
  }
}

// One block freezes nothing: its SES is the single process's, face for face and bit for bit.
TEST(BlockedSes, OneBlockIsTheSingleProcessSes) {
  for (const Placement& placement : placements()) {
    if (placement.atoms.size() > 100) continue;
    SCOPED_TRACE(placement.name);
    ComputeSurfaceOptions options;
    options.surface = SurfaceKind::ses;
    options.spheres.probe = placement.probe;
    options.threads = 2;
    const ComputedSurface whole = compute_surface(placement.atoms, options);
    const ComputedSurface one = compute_blocked_surface(placement.atoms, options, {.blocks = 1}).surface;
    EXPECT_EQ(one.mesh.faces, whole.mesh.faces);
    EXPECT_EQ(one.mesh.face_tags, whole.mesh.face_tags);
    EXPECT_TRUE(one.mesh.vertices == whole.mesh.vertices);
  }
}

// Pieces that leave a seam open are refused with the reason, and the job then draws the
// SES whole (compute_blocked_surface's fallback).
TEST(BlockedSes, PiecesThatDoNotCloseAreRefused) {
  const std::vector<Atom> atoms = ses_reference::ring(6, 3.15, 1.7);
  SphereOptions spheres;
  const BlockPartition partition = partition_blocks(atoms, spheres, 2, ses_halo_reach(atoms, spheres));
  std::vector<Mesh> pieces;
  for (std::size_t b = 0; b < 2; ++b) pieces.push_back(ses_piece_before_cleanup(block_atoms(atoms, partition, b), spheres, 2));
  pieces[1].faces.pop_back();
  pieces[1].face_tags.pop_back();
  ComputeSurfaceOptions options;
  options.surface = SurfaceKind::ses;
  ComputedSurface result;
  std::string why;
  EXPECT_FALSE(finish_blocked_ses(atoms, options, pieces, 0, result, why));
  EXPECT_NE(why.find("found no neighbouring piece"), std::string::npos) << why;
}

// molsurf --surface ses --blocks N: the pieces beside the index, with no seams' piece (the
// seams are cleaned on the first process, and the pieces cut from the joined surface), glued
// back by their coordinates into a valid surface, the one --merge writes; the reports'
// patches' numbers and per-atom table the single process's, the facets' within 1e-3.
class BlockedSesCommand : public ::testing::TestWithParam<int> {};

TEST_P(BlockedSesCommand, WritesPiecesOfTheMergedSurface) {
  const std::string blocks = std::to_string(GetParam());
  testing::TempDir dir;
  const std::string input = "'" + kData + "/pdb/1crn.pdb' --surface ses";
  ASSERT_EQ(testing::run_molsurf(input + " -o one.off --json one.json --per-atom one.csv -q", dir.path()).exit_code, 0);
  const auto run =
      testing::run_molsurf(input + " --blocks " + blocks + " -o s.pvtp --json s.json --per-atom s.csv -q", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_EQ(testing::run_molsurf(input + " --blocks " + blocks + " --merge -o merged.off -q", dir.path()).exit_code, 0);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "s_seams.vtp"));
  const Mesh merged = read_mesh(dir.path() / "merged.off");
  const Mesh pieces = read_mesh(dir.path() / "s.pvtp");
  const MeshCheck check = check_mesh(pieces);
  EXPECT_TRUE(check.valid());
  EXPECT_EQ(pieces.faces.size(), merged.faces.size());
  EXPECT_EQ(pieces.vertices.size(), merged.vertices.size());
  EXPECT_NEAR(check.area, surface_area(merged), 1e-12 * check.area);
  const std::string one = testing::read_text(dir.path() / "one.json");
  const std::string blocked = testing::read_text(dir.path() / "s.json");
  for (const char* key : {"area", "volume", "contact_area", "toroidal_area", "reentrant_area"})
    EXPECT_EQ(testing::json_number(blocked, key), testing::json_number(one, key)) << key;
  for (const char* key : {"facet_area", "facet_volume"})
    EXPECT_NEAR(testing::json_number(blocked, key), testing::json_number(one, key),
                1e-3 * testing::json_number(one, key))
        << key;
  EXPECT_EQ(testing::read_text(dir.path() / "s.csv"), testing::read_text(dir.path() / "one.csv"));
}

INSTANTIATE_TEST_SUITE_P(Crambin, BlockedSesCommand, ::testing::Values(3));

}  // namespace
}  // namespace molsurf::blocks
