// A process's share of a structure cut into blocks (src/blocks/block_share.hpp): what the
// first process of an MPI launch sends each other one instead of the whole structure. A
// share must hold less than the whole structure, every atom of its blocks and their halos,
// and enough around them that a piece made from the share is the piece made from the
// whole structure byte for byte (its border included), and that its file names the same
// atoms.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "blocks/block_share.hpp"
#include "blocks/held_blocks.hpp"
#include "blocks/piece_job.hpp"
#include "blocks/streamed_piece.hpp"
#include "cli_runner.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/io.hpp"

namespace molsurf::blocks {
namespace {

const std::string kData = MOLSURF_DATA_DIR;

ComputeSurfaceOptions job_options() {
  ComputeSurfaceOptions options;
  options.threads = 2;
  return options;
}

bool same_atom(const Atom& a, const Atom& b) {
  return a.centre.x == b.centre.x && a.centre.y == b.centre.y && a.centre.z == b.centre.z && a.radius == b.radius &&
         a.element == b.element && a.atom_name == b.atom_name && a.residue_name == b.residue_name &&
         a.residue_number == b.residue_number && a.insertion_code == b.insertion_code && a.chain == b.chain &&
         a.serial == b.serial && a.occupancy == b.occupancy && a.b_factor == b.b_factor && a.charge == b.charge &&
         a.hetero == b.hetero && a.polarity == b.polarity;
}

void expect_same_mesh(const Mesh& a, const Mesh& b, const std::string& what) {
  EXPECT_TRUE(a.vertices == b.vertices) << what;
  EXPECT_TRUE(a.faces == b.faces) << what;
  EXPECT_TRUE(a.face_tags == b.face_tags) << what;
}

// Field by field: the bytes a piece travels as hold struct padding.
void expect_same_kept(const StreamedPiece& a, const StreamedPiece& b) {
  expect_same_mesh(a.band, b.band, "band");
  expect_same_mesh(a.border, b.border, "border");
  ASSERT_EQ(a.seam.size(), b.seam.size());
  for (std::size_t k = 0; k < a.seam.size(); ++k) {
    EXPECT_TRUE(a.seam[k].position == b.seam[k].position) << "seam point " << k;
    EXPECT_TRUE(a.seam[k].definition == b.seam[k].definition) << "seam point " << k;
    EXPECT_EQ(a.seam[k].atom, b.seam[k].atom) << "seam point " << k;
  }
  EXPECT_EQ(a.border_open_edges, b.border_open_edges);
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.area, b.area);
  EXPECT_EQ(a.volume, b.volume);
  EXPECT_EQ(a.stray, b.stray);
  ASSERT_EQ(a.atom_area.size(), b.atom_area.size());
  for (std::size_t k = 0; k < a.atom_area.size(); ++k) {
    EXPECT_EQ(a.atom_area[k].atom, b.atom_area[k].atom);
    EXPECT_EQ(a.atom_area[k].area, b.atom_area[k].area);
  }
  ASSERT_EQ(a.parts.size(), b.parts.size());
  for (std::size_t k = 0; k < a.parts.size(); ++k) {
    EXPECT_EQ(a.parts[k].faces, b.parts[k].faces);
    EXPECT_EQ(a.parts[k].area, b.parts[k].area);
    EXPECT_EQ(a.parts[k].volume, b.parts[k].volume);
    EXPECT_EQ(a.parts[k].atoms, b.parts[k].atoms);
    EXPECT_TRUE(a.parts[k].joints == b.parts[k].joints);
  }
  EXPECT_EQ(a.stats.atoms, b.stats.atoms);
  EXPECT_EQ(a.stats.halo_atoms, b.stats.halo_atoms);
  EXPECT_EQ(a.cleanup.collapses, b.cleanup.collapses);
  EXPECT_EQ(a.cleanup.flips, b.cleanup.flips);
}

TEST(BlockShare, HoldsItsBlocksAndHalosAndLessThanTheWhole) {
  const Structure s = read_structure(kData + "/pdb/2hhb.pdb");
  const BlockJob job = plan_block_job(s.atoms, job_options(), 2, true);
  const std::size_t n = s.atoms.size();
  for (int rank = 0; rank < 2; ++rank) {
    SCOPED_TRACE("process " + std::to_string(rank));
    const BlockShare share = share_of_process(s.atoms, job.partition, job.options.spheres, rank, 2);
    // The point of the share: a process of two never holds the whole structure.
    EXPECT_LT(share.atoms.size(), n);
    ASSERT_EQ(share.blocks, std::vector<std::size_t>{static_cast<std::size_t>(rank)});
    const auto b = static_cast<std::size_t>(rank);
    EXPECT_GE(share.atoms.size(), job.partition.atoms[b].size() + job.partition.halo[b].size());
    EXPECT_EQ(share.total_atoms, n);
    EXPECT_EQ(share.block_count, 2u);
    EXPECT_TRUE(std::is_sorted(share.global_index.begin(), share.global_index.end()));
    for (std::size_t k = 0; k < share.atoms.size(); ++k) {
      const std::uint32_t g = share.global_index[k];
      ASSERT_LT(g, n);
      EXPECT_TRUE(same_atom(share.atoms[k], s.atoms[g])) << "atom " << g;
      EXPECT_EQ(share.block_of[k], job.partition.block_of[g]);
      EXPECT_EQ(share.contained[k], job.partition.contained[g]);
    }
    // Its block and halo, as positions in the share, name the partition's atoms.
    ASSERT_EQ(share.own.size(), 1u);
    ASSERT_EQ(share.own[0].size(), job.partition.atoms[b].size());
    for (std::size_t k = 0; k < share.own[0].size(); ++k)
      EXPECT_EQ(share.global_index[share.own[0][k]], job.partition.atoms[b][k]);
    ASSERT_EQ(share.halo[0].size(), job.partition.halo[b].size());
    for (std::size_t k = 0; k < share.halo[0].size(); ++k)
      EXPECT_EQ(share.global_index[share.halo[0][k]], job.partition.halo[b][k]);
  }
}

TEST(BlockShare, TravelsAsBytes) {
  const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  const BlockJob job = plan_block_job(s.atoms, job_options(), 3, true);
  // Process 0 of 2 makes blocks 0 and 2.
  const BlockShare share = share_of_process(s.atoms, job.partition, job.options.spheres, 0, 2);
  ASSERT_EQ(share.blocks, (std::vector<std::size_t>{0, 2}));
  const std::string bytes = block_share_bytes(share);
  const BlockShare back = read_block_share(bytes);
  EXPECT_EQ(back.block_count, share.block_count);
  EXPECT_EQ(back.total_atoms, share.total_atoms);
  EXPECT_EQ(back.origin.x, share.origin.x);
  EXPECT_EQ(back.origin.z, share.origin.z);
  ASSERT_EQ(back.atoms.size(), share.atoms.size());
  for (std::size_t k = 0; k < share.atoms.size(); ++k) EXPECT_TRUE(same_atom(back.atoms[k], share.atoms[k])) << k;
  EXPECT_EQ(back.global_index, share.global_index);
  EXPECT_EQ(back.block_of, share.block_of);
  EXPECT_EQ(back.contained, share.contained);
  EXPECT_EQ(back.blocks, share.blocks);
  EXPECT_EQ(back.own, share.own);
  EXPECT_EQ(back.halo, share.halo);
  EXPECT_FALSE(back.partition.has_value());
  EXPECT_THROW(read_block_share(std::string_view(bytes).substr(0, bytes.size() - 1)), std::invalid_argument);
  EXPECT_THROW(read_block_share(bytes + "x"), std::invalid_argument);
}

TEST(HeldAtoms, FindsAtomsByTheirGlobalIndex) {
  const std::vector<Atom> atoms(3);
  const std::vector<std::uint32_t> global{4, 9, 20}, block_of{0, 1, 1};
  const std::vector<std::uint8_t> contained{0, 0, 1};
  const HeldAtoms held{atoms, global, block_of, contained};
  EXPECT_EQ(held.local(4), 0u);
  EXPECT_EQ(held.local(9), 1u);
  EXPECT_EQ(held.local(20), 2u);
  for (std::uint32_t g : {0u, 5u, 21u}) EXPECT_EQ(held.local(g), HeldAtoms::kNotHeld) << g;
  const HeldAtoms whole{atoms, {}, block_of, contained};
  EXPECT_EQ(whole.local(2), 2u);
  EXPECT_EQ(whole.local(3), HeldAtoms::kNotHeld);
  EXPECT_EQ(whole.global(1), 1u);
  EXPECT_EQ(held.global(1), 9u);
}

// Each block's streamed piece (the faces written, the band, the border and the summary)
// made by a process from its share equals the one made from the whole structure, and its
// file names the same atoms; in 2 blocks on 2 processes and in 3 blocks on 2 (a process
// with two blocks).
TEST(BlockShare, PiecesFromTheShareEqualPiecesFromTheWhole) {
  const Structure s = read_structure(kData + "/pdb/2hhb.pdb");
  const testing::TempDir dir;
  for (const std::size_t blocks : {std::size_t{2}, std::size_t{3}}) {
    const BlockJob job = plan_block_job(s.atoms, job_options(), blocks, true);
    const HeldBlocks whole(s.atoms, job.partition);
    const Vec3 origin = volume_origin(s.atoms);
    for (int rank = 0; rank < 2; ++rank) {
      const BlockShare share = share_of_process(s.atoms, job.partition, job.options.spheres, rank, 2);
      EXPECT_LT(share.atoms.size(), s.atoms.size());
      const HeldBlocks held(share);
      EXPECT_EQ(share.origin.y, origin.y);
      for (std::size_t b : share.blocks) {
        SCOPED_TRACE(std::to_string(blocks) + " blocks, block " + std::to_string(b));
        SplitPiece from_share = split_piece(make_piece(held, b, job.options, 2), held.held(), job.options.spheres,
                                            share.origin);
        SplitPiece from_whole = split_piece(make_piece(whole, b, job.options, 2), whole.held(), job.options.spheres,
                                            origin);
        EXPECT_FALSE(from_whole.kept.border.faces.empty());
        ASSERT_FALSE(from_whole.written.faces.empty());
        expect_same_mesh(from_share.written, from_whole.written, "written");
        expect_same_kept(from_share.kept, from_whole.kept);
        // The piece's file: residues and chains of the share's atoms, tagged by their global index.
        MeshWriteOptions by_share;
        by_share.atoms = share.atoms;
        by_share.atom_tags = share.global_index;
        MeshWriteOptions by_whole;
        by_whole.atoms = s.atoms;
        write_mesh(dir.path() / "share.vtp", from_share.written, by_share);
        write_mesh(dir.path() / "whole.vtp", from_whole.written, by_whole);
        EXPECT_EQ(testing::read_text(dir.path() / "share.vtp"), testing::read_text(dir.path() / "whole.vtp"));
      }
    }
  }
}

// Atom tags only where the writer reads them, and only tags the atoms have.
TEST(BlockShare, AtomTagsAreCheckedBeforeWriting) {
  const testing::TempDir dir;
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  mesh.face_tags = {7, 7, 9, 9};
  const std::vector<Atom> atoms(2);
  const std::vector<std::uint32_t> tags{7, 9};
  MeshWriteOptions options;
  options.atoms = atoms;
  options.atom_tags = tags;
  EXPECT_NO_THROW(write_mesh(dir.path() / "t.vtp", mesh, options));
  EXPECT_NO_THROW(write_mesh(dir.path() / "t.vtk", mesh, options));
  EXPECT_THROW(write_mesh(dir.path() / "t.ply", mesh, options), Error);
  mesh.face_tags[3] = 8;
  EXPECT_THROW(write_mesh(dir.path() / "u.vtp", mesh, options), Error);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "u.vtp"));
}

}  // namespace
}  // namespace molsurf::blocks
