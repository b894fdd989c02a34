// The solvent-excluded surface in blocks (src/blocks/, --surface ses with --blocks or under
// mpirun): the union's pieces glued as they leave the union, put in the union's own order,
// and the SES drawn from them as one process draws it from its own union. So it must be the
// single-process SES itself: the same faces, tags and vertices in the same order, cleaned or
// not, and the same patches' areas; across the placements whose SES needs its ridges,
// retries and speck removal, with atoms on the cutting planes and copies in two blocks.
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "atom_fixtures.hpp"
#include "blocks/blocked_surface.hpp"
#include "cli_runner.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
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

void expect_same_surface(const ComputedSurface& blocked, const ComputedSurface& whole) {
  EXPECT_TRUE(blocked.check.valid());
  EXPECT_EQ(blocked.mesh.faces, whole.mesh.faces);
  EXPECT_EQ(blocked.mesh.face_tags, whole.mesh.face_tags);
  EXPECT_TRUE(blocked.mesh.vertices == whole.mesh.vertices);
  ASSERT_TRUE(blocked.ses_patches && whole.ses_patches);
  EXPECT_EQ(blocked.ses_patches->area, whole.ses_patches->area);
  EXPECT_EQ(blocked.ses_patches->volume, whole.ses_patches->volume);
  EXPECT_EQ(blocked.ses_patches->area_per_atom, whole.ses_patches->area_per_atom);
  EXPECT_EQ(blocked.measures.components.size(), whole.measures.components.size());
}

TEST(BlockedSes, IsTheSingleProcessSesCleanedOrNot) {
  for (const Placement& placement : placements()) {
    for (const bool cleanup : {false, true}) {
      ComputeSurfaceOptions options;
      options.surface = SurfaceKind::ses;
      options.spheres.probe = placement.probe;
      options.cleanup = cleanup;
      options.threads = 2;
      const bool large = placement.atoms.size() > 100;
      if (large && cleanup) continue;
      const ComputedSurface whole = compute_surface(placement.atoms, options);
      ASSERT_TRUE(whole.check.valid()) << placement.name;
      // Crambin (the slowest) uncleaned in 2 blocks: the command's test below has it cleaned.
      const std::vector<std::size_t> counts = large ? std::vector<std::size_t>{2} : std::vector<std::size_t>{2, 3};
      for (const std::size_t blocks : counts) {
        SCOPED_TRACE(placement.name + ", " + std::to_string(blocks) + " blocks" + (cleanup ? ", cleaned" : ""));
        std::vector<std::size_t> faces_of(blocks, 0);
        BlockedSurfaceOptions blocked_options;
        blocked_options.blocks = blocks;
        // Asked to stream, the SES is still drawn whole: the pieces come from it.
        blocked_options.streamed = blocks == 3;
        blocked_options.piece_done = [&](std::size_t b, const Mesh& piece) {
          faces_of.at(b) = piece.faces.size();
          for (std::size_t f = 0; f < piece.faces.size(); ++f) ASSERT_GE(piece.tag(f), 0);
        };
        const BlockedSurface blocked = compute_blocked_surface(placement.atoms, options, blocked_options);
        expect_same_surface(blocked.surface, whole);
        std::size_t handed_out = 0;
        for (std::size_t n : faces_of) handed_out += n;
        EXPECT_EQ(handed_out, whole.mesh.faces.size());
        ASSERT_EQ(blocked.blocks.size(), blocks);
        for (std::size_t b = 0; b < blocks; ++b) EXPECT_EQ(blocked.blocks[b].faces, faces_of[b]);
      }
    }
  }
}

// molsurf --surface ses --blocks 3: the pieces beside the index, with no seams' piece (the
// SES is cut from the whole surface), glued back by their coordinates into the surface that
// --merge writes and one process writes, byte for byte; the reports' areas, volumes and
// per-atom areas the single process's.
TEST(BlockedSes, CommandWritesTheSingleProcessSurfaceInPieces) {
  testing::TempDir dir;
  const std::string input = "'" + kData + "/pdb/1crn.pdb' --surface ses";
  ASSERT_EQ(testing::run_molsurf(input + " -o one.off --json one.json --per-atom one.csv -q", dir.path()).exit_code, 0);
  const auto run = testing::run_molsurf(input + " --blocks 3 -o s.pvtp --json s.json --per-atom s.csv -q", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_EQ(testing::run_molsurf(input + " --blocks 3 --merge -o merged.off -q", dir.path()).exit_code, 0);
  EXPECT_EQ(testing::read_text(dir.path() / "merged.off"), testing::read_text(dir.path() / "one.off"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "s_seams.vtp"));
  const Mesh whole = read_mesh(dir.path() / "one.off");
  const Mesh pieces = read_mesh(dir.path() / "s.pvtp");
  const MeshCheck check = check_mesh(pieces);
  EXPECT_TRUE(check.valid());
  EXPECT_EQ(pieces.faces.size(), whole.faces.size());
  EXPECT_EQ(pieces.vertices.size(), whole.vertices.size());
  EXPECT_NEAR(check.area, surface_area(whole), 1e-12 * check.area);
  const std::string one = testing::read_text(dir.path() / "one.json");
  const std::string blocked = testing::read_text(dir.path() / "s.json");
  for (const char* key : {"area", "volume", "facet_area", "facet_volume", "contact_area", "toroidal_area"})
    EXPECT_EQ(testing::json_number(blocked, key), testing::json_number(one, key)) << key;
  EXPECT_EQ(testing::read_text(dir.path() / "s.csv"), testing::read_text(dir.path() / "one.csv"));
}

}  // namespace
}  // namespace molsurf::blocks
