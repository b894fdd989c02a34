// A block's exact areas (src/blocks/block_areas.*: each block's true spheres arranged among
// its halo, src/arrangement/arrangement_part.*) joined into the whole structure's
// (src/arrangement/joined_parts.*) against the arrangement of all the spheres at once: the
// same per-atom areas, shells (outer surfaces and cavities, with their lining atoms), totals
// and counts, on proteins, on lattices whose layers lie on the cutting planes (points where
// four or more spheres meet, split between blocks), on a cage whose cavity spans every block,
// and with copies split across blocks. The parts travel as bytes, as between processes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "arrangement/joined_parts.hpp"
#include "atom_fixtures.hpp"
#include "blocks/block_areas.hpp"
#include "blocks/block_partition.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/io.hpp"
#include "molsurf/surface_measures.hpp"

namespace molsurf::blocks {
namespace {

const std::string kData = MOLSURF_DATA_DIR;
using testing::atom_at;

// Every block's part, each through its bytes.
std::vector<arrangement::ArrangementPart> parts_of(std::span<const Atom> atoms, const SphereOptions& options,
                                                   std::size_t blocks) {
  const BlockPartition partition = partition_blocks(atoms, options, blocks);
  std::vector<arrangement::ArrangementPart> parts;
  for (std::size_t b = 0; b < partition.size(); ++b) {
    std::string bytes;
    put_arrangement_part(bytes, block_arrangement(block_atoms(atoms, partition, b), options, 2));
    ByteReader in(bytes);
    parts.push_back(get_arrangement_part(in));
    EXPECT_TRUE(in.done());
  }
  return parts;
}

SphereArrangement joined(std::span<const Atom> atoms, const SphereOptions& options, std::size_t blocks) {
  return arrangement::join_parts(parts_of(atoms, options, blocks), atoms.size(), [&](std::uint32_t i) {
    return arrangement::Ball{atoms[i].centre, sphere_radius(atoms[i], options)};
  });
}

// Within rounding: sums taken in another order, and a sphere's area integrated from another
// pole when its neighbour list (the power diagram of the block and halo) holds another
// sphere that covers nothing.
void expect_close(double joined, double whole, const std::string& what) {
  EXPECT_NEAR(joined, whole, 1e-10 * std::fabs(whole) + 1e-12) << what;
}

// The joined parts of `blocks` blocks against the whole arrangement.
void expect_joined_whole(std::span<const Atom> atoms, const SphereOptions& options, std::size_t blocks,
                         const SphereArrangement& whole) {
  SCOPED_TRACE(std::to_string(blocks) + " blocks");
  const SphereArrangement j = joined(atoms, options, blocks);
  ASSERT_EQ(j.area_per_sphere.size(), whole.area_per_sphere.size());
  for (std::size_t i = 0; i < atoms.size(); ++i)
    expect_close(j.area_per_sphere[i], whole.area_per_sphere[i], "atom " + std::to_string(i));
  expect_close(j.area, whole.area, "area");
  expect_close(j.volume, whole.volume, "volume");
  // (Not the circles: a block's neighbour lists, from the power diagram of the block and its
  // halo, may hold a few more spheres, whose circles are counted though they cover nothing.)
  EXPECT_EQ(j.stats.spheres, whole.stats.spheres);
  EXPECT_EQ(j.stats.buried, whole.stats.buried);
  EXPECT_EQ(j.stats.degenerate_points, whole.stats.degenerate_points);
  EXPECT_EQ(j.stats.vertices, whole.vertices.size());
  EXPECT_EQ(j.stats.arcs, whole.arcs.size());
  ASSERT_EQ(j.shells.size(), whole.shells.size());
  for (std::size_t s = 0; s < whole.shells.size(); ++s) {
    const ArrangementShell &a = j.shells[s], &b = whole.shells[s];
    const std::string shell = "shell " + std::to_string(s);
    EXPECT_EQ(a.cavity(), b.cavity()) << shell;
    EXPECT_EQ(a.spheres, b.spheres) << shell;
    expect_close(a.area, b.area, shell + " area");
    expect_close(a.volume, b.volume, shell + " volume");
    EXPECT_NEAR(norm(a.centroid - b.centroid), 0, 1e-9) << shell;
  }
  // The outer shells' share of each atom (what --outer-only reports), and each shell's
  // own atoms matched to the shells (how the mesh's components find theirs) as the whole
  // arrangement matches them.
  const std::vector<double> outer = exact_atom_area(j, true), whole_outer = exact_atom_area(whole, true);
  for (std::size_t i = 0; i < atoms.size(); ++i)
    expect_close(outer[i], whole_outer[i], "outer area of atom " + std::to_string(i));
  std::vector<std::vector<std::uint32_t>> lining;
  for (const ArrangementShell& s : whole.shells) lining.push_back(s.spheres);
  std::vector<std::vector<std::uint32_t>> same = lining;
  EXPECT_EQ(shells_of_atom_sets(lining, j), shells_of_atom_sets(same, whole));
}

// The whole arrangement, and each block count's joined parts against it.
SphereArrangement expect_whole_arrangement(std::span<const Atom> atoms, const SphereOptions& options,
                                           std::initializer_list<std::size_t> block_counts) {
  SphereArrangement whole = compute_areas(atoms, options, 2).arrangement;
  for (const std::size_t blocks : block_counts) expect_joined_whole(atoms, options, blocks, whole);
  return whole;
}

class ProteinInBlocks : public ::testing::TestWithParam<std::string> {};

TEST_P(ProteinInBlocks, JoinedPartsAreTheWholeArrangement) {
  const Structure s = read_structure(kData + "/pdb/" + GetParam());
  const SphereArrangement whole = expect_whole_arrangement(s.atoms, SphereOptions{}, {1, 2, 3, 5});
  EXPECT_GE(whole.shells.size(), 2u);  // an outer surface and at least one cavity to join
}

INSTANTIATE_TEST_SUITE_P(DataPdb, ProteinInBlocks, ::testing::Values("1crn.pdb", "2hhb.pdb"));

// Whole layers of atoms on the cutting planes, split between blocks by index: vertices where
// four or more spheres meet (aliases of one point) on the blocks' boundaries.
TEST(BlockAreasDegenerate, LatticeOnTheCuttingPlanes) {
  std::size_t degenerate = 0;
  for (double spacing : {1.5, 3.0})
    for (double probe : {0.0, 1.4}) {
      const std::vector<Atom> atoms = testing::lattice_4x4x3(spacing);
      SphereOptions options;
      options.probe = probe;
      SCOPED_TRACE("spacing " + std::to_string(spacing) + ", probe " + std::to_string(probe));
      degenerate += expect_whole_arrangement(atoms, options, {2, 3, 4, 7}).stats.degenerate_points;
    }
  EXPECT_GT(degenerate, 0u);
}

// A closed cage of atoms on a sphere: its inner cavity and its outer surface each run through
// every block, joined only through the keys the blocks share.
TEST(BlockAreasDegenerate, CavitySpanningEveryBlock) {
  std::vector<Atom> atoms;
  const int n = 240;
  for (int k = 0; k < n; ++k) {  // a Fibonacci sphere of radius 10 A, about 2.3 A between atoms
    const double z = 1 - (2 * k + 1.0) / n, rho = std::sqrt(1 - z * z);
    const double phi = k * std::numbers::pi * (3 - std::sqrt(5.0));
    atoms.push_back(atom_at({10 * rho * std::cos(phi), 10 * rho * std::sin(phi), 10 * z}, 2.0));
  }
  SphereOptions options;
  options.probe = 0;
  const SphereArrangement whole = expect_whole_arrangement(atoms, options, {2, 3, 4, 7});
  ASSERT_EQ(whole.shells.size(), 2u);
  EXPECT_FALSE(whole.shells[0].cavity());
  EXPECT_TRUE(whole.shells[1].cavity());
  EXPECT_EQ(whole.shells[1].spheres.size(), atoms.size());
}

// Copies of an atom in different blocks and an atom held by another's ball: buried alike,
// whichever block holds them.
TEST(BlockAreasDegenerate, DuplicatesSplitAcrossBlocks) {
  const std::vector<Atom> atoms = testing::row_with_copies();  // 4: a copy of atom 2; 5: inside its ball
  const BlockPartition partition = partition_blocks(atoms, SphereOptions{}, 2);
  ASSERT_NE(partition.block_of[2], partition.block_of[4]);
  EXPECT_EQ(expect_whole_arrangement(atoms, SphereOptions{}, {2, 3, 4, 7}).stats.buried, 2u);
}

TEST(BlockAreas, RefusesPartsThatDoNotAddUp) {
  const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  std::vector<arrangement::ArrangementPart> parts = parts_of(s.atoms, SphereOptions{}, 3);
  auto ball = [&](std::uint32_t i) { return arrangement::Ball{s.atoms[i].centre, s.atoms[i].radius}; };
  std::vector<arrangement::ArrangementPart> missing(parts.begin(), parts.end() - 1);
  EXPECT_THROW(arrangement::join_parts(missing, s.atoms.size(), ball), std::invalid_argument);
  EXPECT_THROW(arrangement::join_parts(parts, s.atoms.size() - 1, ball), std::invalid_argument);
  std::string bytes;
  put_arrangement_part(bytes, parts[0]);
  bytes.resize(bytes.size() - 1);
  ByteReader in(bytes);
  EXPECT_THROW(get_arrangement_part(in), std::invalid_argument);
}

}  // namespace
}  // namespace molsurf::blocks
