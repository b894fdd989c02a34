// Spatial blocks (src/blocks/): the atoms cut into blocks balanced by count, each block's
// piece computed from the block and its halo alone, the pieces glued along their seams.
// Before any cleanup the glued pieces must be the single-process one-pass union itself:
// the same faces on the same exact coordinates, hence the same area and volume.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "atom_fixtures.hpp"
#include "cli_runner.hpp"
#include "blocks/block_partition.hpp"
#include "blocks/block_piece.hpp"
#include "blocks/blocked_surface.hpp"
#include "blocks/coordinate_bisection.hpp"
#include "blocks/seam.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/surface_measures.hpp"
#include "surface/one_pass/one_pass_union.hpp"

namespace molsurf::blocks {
namespace {

const std::string kData = MOLSURF_DATA_DIR;
using testing::atom_at;

// A face as its corners' exact coordinates, turned so the least corner comes first (the
// orientation kept), and its atom.
using FaceKey = std::tuple<std::array<std::array<double, 3>, 3>, std::int32_t>;

std::vector<FaceKey> face_keys(const Mesh& mesh) {
  std::vector<FaceKey> keys;
  keys.reserve(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    std::array<std::array<double, 3>, 3> corners;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.vertices[mesh.faces[f][k]];
      corners[k] = {p.x, p.y, p.z};
    }
    const auto least = std::min_element(corners.begin(), corners.end());
    std::rotate(corners.begin(), least, corners.end());
    keys.emplace_back(corners, mesh.tag(f));
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

std::size_t json_count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

Mesh glued_blocks(std::span<const Atom> atoms, const SphereOptions& options, std::size_t blocks) {
  const BlockPartition partition = partition_blocks(atoms, options, blocks);
  std::vector<Mesh> pieces;
  std::vector<std::vector<SeamPoint>> seams;
  for (std::size_t b = 0; b < partition.size(); ++b) {
    BlockPiece piece = compute_block_piece(block_atoms(atoms, partition, b), options, 2);
    pieces.push_back(std::move(piece.mesh));
    seams.push_back(std::move(piece.seam));
  }
  return glue_pieces(pieces, seams, exact_same_point(atoms, options, partition.contained));
}

// Pieces read back from files: vertices at the same coordinates are one (the pieces of a
// checked surface share their seam vertices exactly); tags kept.
Mesh glued_by_coordinates(const std::vector<Mesh>& pieces) {
  Mesh glued;
  std::map<std::array<double, 3>, Index> vertex;
  for (const Mesh& piece : pieces) {
    std::vector<Index> vertex_of(piece.vertices.size());
    for (std::size_t v = 0; v < piece.vertices.size(); ++v) {
      const Vec3& p = piece.vertices[v];
      const auto [it, inserted] = vertex.try_emplace({p.x, p.y, p.z}, static_cast<Index>(glued.vertices.size()));
      if (inserted) glued.vertices.push_back(p);
      vertex_of[v] = it->second;
    }
    for (std::size_t f = 0; f < piece.faces.size(); ++f) {
      const Triangle& t = piece.faces[f];
      glued.faces.push_back({vertex_of[t[0]], vertex_of[t[1]], vertex_of[t[2]]});
      glued.face_tags.push_back(piece.tag(f));
    }
  }
  return glued;
}

// The glued pieces against the whole union: face for face, then area and volume.
void expect_whole_union(std::span<const Atom> atoms, const SphereOptions& options,
                        std::initializer_list<std::size_t> block_counts) {
  const Mesh whole = surface_detail::one_pass_union(atoms, options, 2).mesh;
  const std::vector<FaceKey> whole_faces = face_keys(whole);
  const double area = surface_area(whole), volume = signed_volume(whole);
  for (const std::size_t blocks : block_counts) {
    const Mesh glued = glued_blocks(atoms, options, blocks);
    EXPECT_TRUE(seam_edges(glued).empty()) << blocks << " blocks: the glued pieces are open";
    EXPECT_EQ(glued.faces.size(), whole.faces.size()) << blocks << " blocks";
    EXPECT_EQ(glued.vertices.size(), whole.vertices.size()) << blocks << " blocks";
    EXPECT_TRUE(face_keys(glued) == whole_faces) << blocks << " blocks: the faces differ";
    EXPECT_NEAR(surface_area(glued), area, 1e-12 * std::fabs(area)) << blocks << " blocks";
    EXPECT_NEAR(signed_volume(glued), volume, 1e-12 * std::fabs(volume)) << blocks << " blocks";
  }
}

TEST(CoordinateBisection, BalancedByCountAndDeterministic) {
  std::vector<Vec3> centres;
  for (int i = 0; i < 101; ++i) centres.push_back({std::fmod(i * 7.3, 13.0), std::fmod(i * 3.1, 5.0), 0.25 * i});
  for (std::size_t blocks : {1u, 2u, 3u, 4u, 7u}) {
    const auto block_of = bisect_coordinates(centres, blocks);
    std::vector<std::size_t> count(blocks, 0);
    for (auto b : block_of) ++count[b];
    const auto [lo, hi] = std::minmax_element(count.begin(), count.end());
    EXPECT_LE(*hi - *lo, 2u) << blocks << " blocks";
    EXPECT_EQ(block_of, bisect_coordinates(centres, blocks));
  }
}

// Every centre on one point: the cuts fall between indices, lowest first.
TEST(CoordinateBisection, TiesByIndex) {
  const std::vector<Vec3> centres(10, Vec3{1, 2, 3});
  const auto block_of = bisect_coordinates(centres, 2);
  for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(block_of[i], i < 5 ? 0u : 1u);
}

TEST(BlockPartition, HaloHoldsEveryNeighbourOfTheBlock) {
  const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  const SphereOptions options;
  const BlockPartition partition = partition_blocks(s.atoms, options, 3);
  std::size_t atoms = 0;
  for (std::size_t b = 0; b < 3; ++b) {
    atoms += partition.atoms[b].size();
    EXPECT_FALSE(partition.halo[b].empty());
    for (auto j : partition.halo[b]) EXPECT_NE(partition.block_of[j], b);
  }
  EXPECT_EQ(atoms, s.atoms.size());
}

class StructureInBlocks : public ::testing::TestWithParam<std::string> {};

TEST_P(StructureInBlocks, GluedPiecesAreTheWholeUnion) {
  const Structure s = read_structure(kData + "/pdb/" + GetParam());
  expect_whole_union(s.atoms, SphereOptions{}, {2, 3, 4, 7});
}

INSTANTIATE_TEST_SUITE_P(DataPdb, StructureInBlocks, ::testing::Values("1crn.pdb", "2hhb.pdb"));

// A full lattice: whole layers of atoms lie exactly on the cutting planes, split between
// blocks by index, and faces of neighbouring atoms are exactly coplanar.
TEST(BlocksDegenerate, LatticeOnTheCuttingPlanes) {
  for (double spacing : {1.5, 3.0})
    for (double probe : {0.0, 1.4}) {
      const std::vector<Atom> atoms = testing::lattice_4x4x3(spacing);
      SphereOptions options;
      options.probe = probe;
      SCOPED_TRACE("spacing " + std::to_string(spacing) + ", probe " + std::to_string(probe));
      expect_whole_union(atoms, options, {2, 3, 4, 7});
    }
}

// Copies of an atom in different blocks: the lowest index keeps its faces, whichever
// block holds it, and a copy held by another's ball adds nothing there either.
TEST(BlocksDegenerate, DuplicatesSplitAcrossBlocks) {
  const std::vector<Atom> atoms = testing::row_with_copies();  // 4: a copy of atom 2; 5: inside its ball
  const BlockPartition partition = partition_blocks(atoms, SphereOptions{}, 2);
  ASSERT_NE(partition.block_of[2], partition.block_of[4]);
  EXPECT_TRUE(partition.contained[4]);
  EXPECT_TRUE(partition.contained[5]);
  expect_whole_union(atoms, SphereOptions{}, {2, 3, 4, 7});
}

// After cleanup (each piece's seam frozen): a valid surface, whose facets' area is the
// single-process surface's within 1e-4 and whose components are the same, cavities
// spanning blocks joined through the seams; the same bytes on a second run.
TEST(BlockedSurface, CleanedBlocksMatchTheSingleProcessSurface) {
  const Structure s = read_structure(kData + "/pdb/2hhb.pdb");
  ComputeSurfaceOptions options;
  options.threads = 2;
  const ComputedSurface whole = compute_surface(s.atoms, options);
  std::size_t pieces_seen = 0;
  const BlockedSurface blocked = compute_blocked_surface(
      s.atoms, options, {.blocks = 3, .piece_done = [&](std::size_t, const Mesh& piece) {
                           EXPECT_FALSE(seam_edges(piece).empty());
                           ++pieces_seen;
                         }});
  EXPECT_EQ(pieces_seen, 3u);
  const Mesh& glued = blocked.surface.mesh;
  const MeshCheck check = check_mesh(glued);
  EXPECT_TRUE(check.valid());
  EXPECT_NEAR(check.area, whole.check.area, 1e-4 * whole.check.area);
  EXPECT_NEAR(check.volume, whole.check.volume, 1e-4 * whole.check.volume);
  // Each component's volume: the blocks' cleanup, which leaves a band around each seam to
  // the seams' own cleanup, makes other edits there than one process does (2hhb: 0.06 % at
  // most, on small cavities); within 0.5 % or 1e-5 A^3.
  const auto& components = blocked.surface.measures.components;
  ASSERT_EQ(components.size(), whole.measures.components.size());
  for (std::size_t c = 0; c < components.size(); ++c) {
    const double v = whole.measures.components[c].volume;
    EXPECT_EQ(components[c].cavity(), whole.measures.components[c].cavity()) << "component " << c;
    EXPECT_NEAR(components[c].volume, v, std::max(5e-3 * std::fabs(v), 1e-5)) << "component " << c;
  }
  // The seams' slivers are cleaned too: no face worse than the single-process surface's.
  EXPECT_GE(check.quality.min_angle_deg, whole.check.quality.min_angle_deg - 1e-9);
  // The exact areas, joined from the blocks' own arrangements, are the whole structure's to
  // rounding (a sphere's area may be integrated from another pole: tests/test_block_areas.cpp).
  ASSERT_EQ(blocked.surface.exact.area_per_sphere.size(), s.atoms.size());
  for (std::size_t a = 0; a < s.atoms.size(); ++a)
    EXPECT_NEAR(blocked.surface.exact.area_per_sphere[a], whole.exact.area_per_sphere[a],
                1e-10 * whole.exact.area_per_sphere[a] + 1e-12)
        << "atom " << a;
  const BlockedSurface again = compute_blocked_surface(s.atoms, options, {.blocks = 3});
  EXPECT_EQ(again.surface.exact.area_per_sphere, blocked.surface.exact.area_per_sphere);
  EXPECT_EQ(again.surface.mesh.faces, glued.faces);
  EXPECT_EQ(again.surface.mesh.face_tags, glued.face_tags);
  EXPECT_TRUE(again.surface.mesh.vertices == glued.vertices);
}

TEST(BlockedSurface, RefusesWhatItDoesNotSplit) {
  const std::vector<Atom> atoms{atom_at({0, 0, 0}, 1.5), atom_at({2, 0, 0}, 1.5)};
  ComputeSurfaceOptions options;
  options.method = SurfaceMethod::pairwise;
  EXPECT_THROW(compute_blocked_surface(atoms, options, {.blocks = 2}), Error);
  options = {};
  options.stern_probe = 2.0;
  EXPECT_THROW(compute_blocked_surface(atoms, options, {.blocks = 2}), Error);
  options = {};
  EXPECT_NO_THROW(compute_blocked_surface(atoms, options, {.blocks = 2}));
}

// The streamed job's output: each block's written faces and the seams' faces.
struct StreamedOutput {
  std::vector<Mesh> pieces;
  Mesh seams;
  BlockedSurface surface;
};

StreamedOutput streamed_blocks(std::span<const Atom> atoms, const ComputeSurfaceOptions& options, std::size_t blocks) {
  StreamedOutput out;
  out.pieces.resize(blocks);
  BlockedSurfaceOptions blocked;
  blocked.blocks = blocks;
  blocked.streamed = true;
  blocked.piece_done = [&](std::size_t b, const Mesh& piece) { out.pieces.at(b) = piece; };
  blocked.seams_done = [&](const Mesh& seams) { out.seams = seams; };
  out.surface = compute_blocked_surface(atoms, options, blocked);
  return out;
}

// Without cleanup the streamed pieces and the seams' piece are the whole one-pass union,
// face for face; the merged counts and measures are the glued surface's.
TEST(StreamedBlocks, UncleanedPiecesAndSeamsAreTheWholeUnion) {
  const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  const Mesh whole = surface_detail::one_pass_union(s.atoms, SphereOptions{}, 2).mesh;
  ComputeSurfaceOptions options;
  options.cleanup = false;
  for (std::size_t blocks : {2u, 3u, 7u}) {
    const StreamedOutput out = streamed_blocks(s.atoms, options, blocks);
    std::vector<Mesh> all = out.pieces;
    all.push_back(out.seams);
    const Mesh glued = glued_by_coordinates(all);
    EXPECT_TRUE(face_keys(glued) == face_keys(whole)) << blocks << " blocks: the faces differ";
    const SurfaceMeasures& m = out.surface.surface.measures;
    EXPECT_EQ(m.faces, whole.faces.size()) << blocks << " blocks";
    EXPECT_EQ(m.vertices, whole.vertices.size()) << blocks << " blocks";
    EXPECT_NEAR(m.area, surface_area(whole), 1e-12 * surface_area(whole)) << blocks << " blocks";
    EXPECT_NEAR(m.volume, signed_volume(whole), 1e-11 * signed_volume(whole)) << blocks << " blocks";
    EXPECT_EQ(m.components.size(), measure_components(whole).size()) << blocks << " blocks";
    for (const Mesh& piece : out.pieces) EXPECT_FALSE(seam_edges(piece).empty()) << blocks << " blocks";
  }
}

// Two crambins 1e6 A apart, one per block, uncleaned (so the pieces are the one-process
// union face for face). The streamed job sums volumes about its origin between them, 5e5 A
// from each, where a component's volume carries a rounding of about 1e-8 of itself (1e-4
// A^3 on crambin's); one process measures each component about its own vertex with an
// exact sign. A component closed within one piece is now measured as one process measures
// it: the same outer surfaces and cavities, and the same volumes.
TEST(StreamedBlocks, ComponentsFarFromTheOriginAreMeasuredAsOneProcessMeasuresThem) {
  const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  std::vector<Atom> atoms = s.atoms;
  for (const Atom& a : s.atoms) {
    Atom copy = a;
    copy.centre = copy.centre + Vec3{1e6, 3e5, -2e5};
    atoms.push_back(copy);
  }
  ComputeSurfaceOptions options;
  options.cleanup = false;
  options.exact_areas = false;
  const ComputedSurface whole = compute_surface(atoms, options);
  const std::vector<ComponentMeasure>& expected = whole.measures.components;
  ASSERT_EQ(expected.size(), 4u);
  const StreamedOutput out = streamed_blocks(atoms, options, 2);
  const std::vector<ComponentMeasure>& streamed = out.surface.surface.measures.components;
  ASSERT_EQ(streamed.size(), expected.size());
  for (std::size_t c = 0; c < expected.size(); ++c) {
    EXPECT_EQ(streamed[c].cavity(), expected[c].cavity()) << "component " << c;
    EXPECT_EQ(streamed[c].faces, expected[c].faces) << "component " << c;
    EXPECT_NEAR(streamed[c].volume, expected[c].volume, 1e-11 * std::fabs(expected[c].volume)) << "component " << c;
  }
  EXPECT_NEAR(out.surface.surface.measures.volume, whole.measures.volume, 1e-11 * whole.measures.volume);
}

// After cleanup: the pieces and seams read as one surface are valid, and are what the
// merged report describes; against the glued job (which holds the whole surface), the
// facets' area and volume within 1e-4, the same components (cavities spanning blocks
// joined through the seams), the same exact areas and shells; the same meshes twice.
TEST(StreamedBlocks, MatchTheGluedJob) {
  const Structure s = read_structure(kData + "/pdb/2hhb.pdb");
  ComputeSurfaceOptions options;
  options.threads = 2;
  const BlockedSurface glued = compute_blocked_surface(s.atoms, options, {.blocks = 3});
  const StreamedOutput out = streamed_blocks(s.atoms, options, 3);
  std::vector<Mesh> all = out.pieces;
  all.push_back(out.seams);
  const Mesh surface = glued_by_coordinates(all);
  const MeshCheck check = check_mesh(surface);
  EXPECT_TRUE(check.valid());
  const ComputedSurface& streamed = out.surface.surface;
  EXPECT_TRUE(streamed.mesh.faces.empty());
  EXPECT_EQ(streamed.measures.faces, surface.faces.size());
  EXPECT_EQ(streamed.measures.vertices, surface.vertices.size());
  EXPECT_NEAR(streamed.measures.area, check.area, 1e-9 * check.area);
  EXPECT_NEAR(streamed.measures.volume, check.volume, 1e-9 * check.volume);
  EXPECT_EQ(streamed.check.euler_characteristic, check.euler_characteristic);
  EXPECT_EQ(streamed.measures.atom_area.size(), s.atoms.size());
  const std::vector<double> atom_area = area_per_atom(surface, s.atoms.size());
  for (std::size_t a = 0; a < s.atoms.size(); ++a)
    EXPECT_NEAR(streamed.measures.atom_area[a], atom_area[a], 1e-9 * (1 + atom_area[a])) << "atom " << a;

  const SurfaceMeasures& whole = glued.surface.measures;
  EXPECT_NEAR(streamed.measures.area, whole.area, 1e-4 * whole.area);
  EXPECT_NEAR(streamed.measures.volume, whole.volume, 1e-4 * whole.volume);
  ASSERT_EQ(streamed.measures.components.size(), whole.components.size());
  for (std::size_t c = 0; c < whole.components.size(); ++c) {
    const double v = whole.components[c].volume;
    EXPECT_EQ(streamed.measures.components[c].cavity(), whole.components[c].cavity()) << "component " << c;
    EXPECT_NEAR(streamed.measures.components[c].volume, v, std::max(5e-3 * std::fabs(v), 1e-5)) << "component " << c;
  }
  EXPECT_EQ(streamed.component_shells, glued.surface.component_shells);
  // Both jobs join the same blocks' arrangements (against the whole structure's:
  // tests/test_block_areas.cpp).
  EXPECT_EQ(streamed.exact.area_per_sphere, glued.surface.exact.area_per_sphere);
  ASSERT_EQ(streamed.exact.shells.size(), glued.surface.exact.shells.size());
  for (std::size_t k = 0; k < streamed.exact.shells.size(); ++k) {
    EXPECT_EQ(streamed.exact.shells[k].spheres, glued.surface.exact.shells[k].spheres) << "shell " << k;
    EXPECT_EQ(streamed.exact.shells[k].volume, glued.surface.exact.shells[k].volume) << "shell " << k;
  }

  const StreamedOutput again = streamed_blocks(s.atoms, options, 3);
  for (std::size_t b = 0; b < 3; ++b) {
    EXPECT_EQ(again.pieces[b].faces, out.pieces[b].faces) << "block " << b;
    EXPECT_TRUE(again.pieces[b].vertices == out.pieces[b].vertices) << "block " << b;
  }
  EXPECT_EQ(again.seams.faces, out.seams.faces);
  EXPECT_TRUE(again.seams.vertices == out.seams.vertices);
}

// molsurf --blocks N -o NAME.pvtp: the pieces streamed beside the index with the seams'
// piece, the same bytes on every run; each piece sound but for its boundary, which the
// others close; read back and glued, a valid surface that the report describes, and whose
// report matches --merge's (the whole surface held at once).
class StreamedCommand : public ::testing::TestWithParam<int> {};

TEST_P(StreamedCommand, PiecesBesideTheIndexMatchTheMergedSurface) {
  const int blocks = GetParam();
  testing::TempDir one, two;
  const std::string input = "'" + kData + "/pdb/1crn.pdb' --blocks " + std::to_string(blocks);
  ASSERT_EQ(testing::run_molsurf(input + " -o s.pvtp --json s.json -q", one.path()).exit_code, 0);
  ASSERT_EQ(testing::run_molsurf(input + " -o s.pvtp -q", two.path()).exit_code, 0);
  ASSERT_EQ(testing::run_molsurf(input + " --merge -o merged.vtp --json merged.json -q", one.path()).exit_code, 0);
  std::vector<std::string> names{"s.pvtp", "s_seams.vtp"};
  for (int k = 0; k < blocks; ++k) names.push_back("s_" + std::to_string(k) + ".vtp");
  const std::string index = testing::read_text(one.path() / "s.pvtp");
  std::vector<Mesh> pieces;
  for (const std::string& name : names) {
    const std::string bytes = testing::read_text(one.path() / name);
    EXPECT_FALSE(bytes.empty()) << name;
    EXPECT_EQ(bytes, testing::read_text(two.path() / name)) << name;
    if (name == "s.pvtp") continue;
    EXPECT_NE(index.find("<Piece Source=\"" + name + "\"/>"), std::string::npos) << name;
    pieces.push_back(read_mesh(one.path() / name));
    const MeshCheck piece = check_mesh(pieces.back());
    EXPECT_GT(piece.boundary_edges, 0u) << name;
    EXPECT_TRUE(piece_problems(piece, piece.boundary_edges).empty()) << name;
  }
  const Mesh glued = glued_by_coordinates(pieces);
  const MeshCheck check = check_mesh(glued);
  EXPECT_TRUE(check.valid());
  const std::string report = testing::read_text(one.path() / "s.json");
  EXPECT_EQ(testing::json_number(report, "faces"), static_cast<double>(glued.faces.size()));
  // The report's own vertex count (an earlier "vertices" is a shell's).
  EXPECT_EQ(testing::json_number(report.substr(report.find("\n  \"vertices\"")), "vertices"),
            static_cast<double>(glued.vertices.size()));
  EXPECT_NEAR(testing::json_number(report, "facet_area"), check.area, 1e-9 * check.area);
  EXPECT_NEAR(testing::json_number(report, "facet_volume"), check.volume, 1e-9 * check.volume);
  const std::string merged = testing::read_text(one.path() / "merged.json");
  for (const char* key : {"facet_area", "facet_volume"}) {
    const double whole = testing::json_number(merged, key);
    EXPECT_NEAR(testing::json_number(report, key), whole, 1e-4 * whole) << key;
  }
  EXPECT_EQ(testing::json_number(report, "area"), testing::json_number(merged, "area"));  // exact, from the spheres
  EXPECT_EQ(testing::json_number(report, "cavities"), testing::json_number(merged, "cavities"));
  EXPECT_EQ(json_count(report, "\"kind\": \"cavity\""), json_count(merged, "\"kind\": \"cavity\""));
}

INSTANTIATE_TEST_SUITE_P(Crambin, StreamedCommand, ::testing::Values(3, 5));

TEST(BlocksCommand, RefusesAVolumeMeshAroundStreamedPieces) {
  testing::TempDir dir;
  const auto run = testing::run_molsurf("'" + kData + "/pdb/1crn.pdb' --blocks 2 -o s.pvtp --volume-mesh v.msh", dir.path());
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("--merge"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "s_0.vtp"));
}

// A block per atom at most: more would be empty pieces, each a file and a pass of its own
// (a million blocks on one atom ran for hours, writing a million files), and 65 536 in all.
TEST(BlocksCommand, RefusesMoreBlocksThanAtomsAndTakesTheIndexInAnyCase) {
  testing::TempDir dir;
  {
    std::ofstream pdb(dir.path() / "three.pdb");
    pdb << "ATOM      1  N   ALA A   1       0.000   0.000   0.000  1.00  0.00           N\n"
           "ATOM      2  CA  ALA A   1       1.450   0.000   0.000  1.00  0.00           C\n"
           "ATOM      3  C   ALA A   1       2.000   1.400   0.000  1.00  0.00           C\n"
           "END\n";
  }
  const auto beyond = testing::run_molsurf("three.pdb --blocks 65537 -o s.pvtp", dir.path());
  EXPECT_EQ(beyond.exit_code, 2);
  EXPECT_NE(beyond.err.find("expected a whole number in 1..65536"), std::string::npos) << beyond.err;
  for (const char* blocks : {"4", "65536"}) {
    for (const char* output : {"s.pvtp", "m.vtp --merge"}) {
      const auto run = testing::run_molsurf(std::string("three.pdb --blocks ") + blocks + " -o " + output, dir.path());
      EXPECT_EQ(run.exit_code, 1) << blocks << " " << output;
      EXPECT_NE(run.err.find(std::string(blocks) + " blocks for 3 atoms; at most one block per atom"), std::string::npos)
          << run.err;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "s_0.vtp"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "s.pvtp"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "m.vtp"));
  // The index's extension in any case, as every mesh format's.
  const auto three = testing::run_molsurf("three.pdb --blocks 3 -o S.PVTP -q", dir.path());
  EXPECT_EQ(three.exit_code, 0) << three.err;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "S_2.vtp"));
  EXPECT_EQ(testing::run_molsurf("check S.PVTP", dir.path()).exit_code, 0);
}

// Streamed pieces hold one block's spheres at a time, so --max-faces limits each block with
// its halo: 1crn's 151 980 sphere faces in all are refused at 140 000, its four blocks are not
// (the largest with its halo has 113 580); glued (--merge) the whole is held and refused, and a
// block over the limit is named.
TEST(BlocksCommand, TheFacesLimitHoldsPerBlockWhenStreamed) {
  testing::TempDir dir;
  const std::string input = "'" + kData + "/pdb/1crn.pdb'";
  const auto whole = testing::run_molsurf(input + " --max-faces 140000 -o w.vtp", dir.path());
  EXPECT_EQ(whole.exit_code, 1);
  EXPECT_NE(whole.err.find("151980 faces"), std::string::npos) << whole.err;
  const auto streamed = testing::run_molsurf(input + " --blocks 4 --max-faces 140000 -o s.pvtp -q", dir.path());
  EXPECT_EQ(streamed.exit_code, 0) << streamed.err;
  EXPECT_EQ(testing::run_molsurf("check s.pvtp", dir.path()).exit_code, 0);
  const auto merged = testing::run_molsurf(input + " --blocks 4 --merge --max-faces 140000 -o m.vtp", dir.path());
  EXPECT_EQ(merged.exit_code, 1);
  const auto block = testing::run_molsurf(input + " --blocks 4 --max-faces 100000 -o b.pvtp", dir.path());
  EXPECT_EQ(block.exit_code, 1);
  EXPECT_NE(block.err.find("(block 3 of 4 with its halo)"), std::string::npos) << block.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "b_0.vtp"));
}

TEST(BlocksCommand, RefusesMergeWithoutBlocksOrIntoAnIndex) {
  testing::TempDir dir;
  const std::string input = "'" + kData + "/pdb/1crn.pdb'";
  const auto no_blocks = testing::run_molsurf(input + " --merge -o s.vtp", dir.path());
  EXPECT_EQ(no_blocks.exit_code, 1);
  EXPECT_NE(no_blocks.err.find("--blocks"), std::string::npos);
  const auto into_index = testing::run_molsurf(input + " --blocks 2 --merge -o s.pvtp", dir.path());
  EXPECT_EQ(into_index.exit_code, 1);
  EXPECT_NE(into_index.err.find("--merge"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "s.pvtp"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "s_0.vtp"));
}

}  // namespace
}  // namespace molsurf::blocks
