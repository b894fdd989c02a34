// What a streamed piece keeps as its border (src/blocks/streamed_piece.cpp) and how far
// the seams' cleanup may carry a band face (src/blocks/band_reach.hpp). The border must
// hold every written face within band_reach of the piece's band vertices or within
// border_reach of another block's atom's sphere, and nothing else; BandVertices::drift
// must bound how far a face's points lie from its block's band.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "blocks/band_reach.hpp"
#include "blocks/held_blocks.hpp"
#include "blocks/piece_job.hpp"
#include "blocks/streamed_piece.hpp"
#include "geometry/triangle_distance.hpp"
#include "molsurf/io.hpp"

namespace molsurf::blocks {
namespace {

const std::string kData = MOLSURF_DATA_DIR;

// Two strips of unit right triangles in the plane z = 0: block 0's for x in [0, 4],
// block 1's for x in [4, 8], sharing the vertices on x = 4.
struct TwoBands {
  Mesh mesh;
  std::vector<std::uint32_t> block;
};

TwoBands two_bands() {
  TwoBands out;
  for (int y = 0; y <= 1; ++y)
    for (int x = 0; x <= 8; ++x) out.mesh.vertices.push_back({double(x), double(y), 0});
  auto at = [](int x, int y) { return static_cast<Index>(y * 9 + x); };
  for (int x = 0; x < 8; ++x) {
    out.mesh.faces.push_back({at(x, 0), at(x + 1, 0), at(x + 1, 1)});
    out.mesh.faces.push_back({at(x, 0), at(x + 1, 1), at(x, 1)});
    out.mesh.face_tags.push_back(x);
    out.mesh.face_tags.push_back(x);
    out.block.push_back(x < 4 ? 0 : 1);
    out.block.push_back(x < 4 ? 0 : 1);
  }
  return out;
}

Mesh one_face(const Vec3& a, const Vec3& b, const Vec3& c) {
  Mesh m;
  m.vertices = {a, b, c};
  m.faces = {{0, 1, 2}};
  m.face_tags = {0};
  return m;
}

TEST(BandReach, DriftOfAFaceOnItsBandIsItsCornersReach) {
  const TwoBands band = two_bands();
  const BandVertices vertices(band.mesh, band.block, 3.0);
  // A band face: its corners are band vertices, its points within 1/sqrt(3) of its
  // longest edge (sqrt(2)) of one of them.
  const double on_band = vertices.drift(band.mesh, 0, 0);
  EXPECT_GE(on_band, std::sqrt(2.0) / std::sqrt(3.0));
  EXPECT_LE(on_band, 0.58 * std::sqrt(2.0));
  // Lifted by 0.25 off the plane: every corner 0.25 from its nearest band vertex.
  const Mesh lifted = one_face({1, 0, 0.25}, {2, 0, 0.25}, {2, 1, 0.25});
  EXPECT_NEAR(vertices.drift(lifted, 0, 0), 0.25 + vertices.drift(band.mesh, 0, 0), 1e-12);
  // The seam's vertices (x = 4) belong to both blocks; x = 6 only to block 1.
  const Mesh at_seam = one_face({4, 0, 0}, {4.5, 0, 0}, {4, 0.5, 0});
  EXPECT_LT(vertices.drift(at_seam, 0, 0), 1.0);
  EXPECT_LT(vertices.drift(at_seam, 0, 1), 1.0);
  const Mesh far_side = one_face({7, 0, 0}, {8, 0, 0}, {8, 1, 0});
  EXPECT_LT(vertices.drift(far_side, 0, 1), 1.0);
  EXPECT_EQ(vertices.drift(far_side, 0, 0), HUGE_VAL) << "a corner 4 from block 0's nearest vertex, beyond the reach";
  const Mesh beyond = one_face({1, 0, 3.5}, {2, 0, 3.5}, {2, 1, 3.5});
  EXPECT_EQ(vertices.drift(beyond, 0, 0), HUGE_VAL);
}

std::array<Vec3, 3> corners(const Mesh& m, std::size_t f) {
  return {m.vertices[m.faces[f][0]], m.vertices[m.faces[f][1]], m.vertices[m.faces[f][2]]};
}

using FaceKey = std::array<std::array<double, 3>, 3>;

FaceKey key_of(const Mesh& m, std::size_t f) {
  FaceKey k;
  for (int i = 0; i < 3; ++i) {
    const Vec3& p = m.vertices[m.faces[f][i]];
    k[i] = {p.x, p.y, p.z};
  }
  std::sort(k.begin(), k.end());
  return k;
}

// Each piece of 1crn in 3 blocks, against a search through every pair: a written face is
// in the border exactly when it comes within band_reach of a band vertex of its piece or
// within border_reach of the sphere of an atom of another block.
TEST(BandReach, TheBorderIsEveryWrittenFaceNearTheBandOrAnotherBlock) {
  const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  ComputeSurfaceOptions requested;
  requested.threads = 2;
  const BlockJob job = plan_block_job(s.atoms, requested, 3, true);
  const HeldBlocks whole(s.atoms, job.partition);
  const double band_near = band_reach(job.options.spheres), atom_near = border_reach(job.options.spheres);
  // Distances this close to a reach are left alone: the border widens its reaches by a
  // millionth of an angstrom so that no face in doubt is dropped.
  const double doubt = 1e-5;
  for (std::size_t b = 0; b < 3; ++b) {
    SCOPED_TRACE("block " + std::to_string(b));
    PieceMessage piece = make_piece(whole, b, job.options, 2);
    const SplitPiece split = split_piece(std::move(piece), whole.held(), job.options.spheres, volume_origin(s.atoms));
    std::set<FaceKey> border;
    for (std::size_t f = 0; f < split.kept.border.faces.size(); ++f) border.insert(key_of(split.kept.border, f));
    std::vector<Vec3> band;
    for (const Triangle& t : split.kept.band.faces)
      for (Index v : t) band.push_back(split.kept.band.vertices[v]);
    ASSERT_FALSE(band.empty());
    std::size_t kept = 0, near_band = 0, near_atoms = 0;
    const Mesh& w = split.written;
    for (std::size_t f = 0; f < w.faces.size(); ++f) {
      const auto [p, q, r] = corners(w, f);
      double to_band = HUGE_VAL, to_atoms = HUGE_VAL;
      for (const Vec3& v : band) to_band = std::min(to_band, geometry::distance_to_triangle(v, p, q, r));
      for (std::size_t a = 0; a < s.atoms.size(); ++a)
        if (job.partition.block_of[a] != b)
          to_atoms = std::min(to_atoms, geometry::distance_to_triangle(s.atoms[a].centre, p, q, r) -
                                            sphere_radius(s.atoms[a], job.options.spheres));
      if (std::abs(to_band - band_near) < doubt || std::abs(to_atoms - atom_near) < doubt) continue;
      const bool needed = to_band < band_near || to_atoms < atom_near;
      near_band += to_band < band_near;
      near_atoms += to_atoms < atom_near;
      kept += needed;
      EXPECT_EQ(border.count(key_of(w, f)) == 1, needed) << "written face " << f << ": " << to_band
                                                          << " A from the band, " << to_atoms
                                                          << " A from another block's sphere";
    }
    EXPECT_EQ(kept, split.kept.border.faces.size());
    EXPECT_GT(near_band, 0u);
    EXPECT_GT(near_atoms, 0u);
    EXPECT_LT(kept, w.faces.size());
  }
}

}  // namespace
}  // namespace molsurf::blocks
