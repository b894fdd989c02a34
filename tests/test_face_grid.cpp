// The editing layer's faces by place (mesh/face_grid.hpp): every face whose box meets a
// query is found, before and after faces change, whatever the cells' size.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "mesh/face_grid.hpp"
#include "mesh/icosphere.hpp"

namespace molsurf {
namespace {

// Every face marked in `indexed` whose box meets the box of every seventh face is visited.
void expect_finds_every_overlapping_face(const FaceGrid& grid, const Mesh& m, const std::vector<std::uint8_t>& indexed) {
  for (std::size_t q = 0; q < m.faces.size(); q += 7) {
    const BoundingBox box = bounding_box(m, q);
    std::vector<std::uint8_t> found(m.faces.size(), 0);
    grid.near(box, [&](std::uint32_t g) {
      found[g] = 1;
      return true;
    });
    for (std::size_t g = 0; g < m.faces.size(); ++g)
      if (indexed[g] && box.overlaps(bounding_box(m, g))) EXPECT_TRUE(found[g]) << q << " " << g;
  }
}

// An icosphere off the origin, so that its coordinates are not single-precision numbers.
Mesh off_centre_sphere() { return make_icosphere({10.1, -3.3, 7.7}, 2, {.frequency = 6, .tag = 0}); }

// Including faces that leave the box the grid was built for (clamped onto its border).
TEST(FaceGrid, FindsEveryFaceWhoseBoxMeetsTheQuery) {
  Mesh m = off_centre_sphere();
  FaceGrid grid(m, 0.3);
  std::vector<std::uint8_t> indexed(m.faces.size(), 1);
  expect_finds_every_overlapping_face(grid, m, indexed);
  // Face 0 goes; face 1 moves far outside the original box; face 2 changes and comes back.
  grid.erase(0);
  indexed[0] = 0;
  grid.erase(1);
  m.vertices.push_back({50, 50, 50});
  m.faces[1][0] = static_cast<Index>(m.vertices.size() - 1);
  grid.insert(1);
  grid.erase(2);
  grid.insert(2);
  expect_finds_every_overlapping_face(grid, m, indexed);
  std::size_t visits = 0;
  EXPECT_FALSE(grid.near(bounding_box(m), [&](std::uint32_t) { return ++visits < 3; }));  // stops when told
  EXPECT_EQ(visits, 3u);
  bool far_found = false;
  grid.near(bounding_box(m, 1), [&](std::uint32_t g) {
    far_found = far_found || g == 1;
    return true;
  });
  EXPECT_TRUE(far_found);
}

// The stored boxes are single precision, rounded outward: each holds its face's exact box,
// so rejecting on it never drops a face that meets the query.
TEST(FaceGrid, StoredBoxesHoldTheFacesExactBoxes) {
  Mesh m = off_centre_sphere();
  const FaceGrid grid(m, 0.3);
  std::size_t rounded = 0;
  for (std::uint32_t f = 0; f < m.faces.size(); ++f) {
    const BoundingBox exact = bounding_box(m, f), stored = grid.box(f);
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(stored.min[a], exact.min[a]);
      EXPECT_GE(stored.max[a], exact.max[a]);
      rounded += stored.min[a] != exact.min[a];
    }
  }
  EXPECT_GT(rounded, m.faces.size());  // the test saw rounding, not only exact floats
}

// When fine cells would hold more entries than the offsets can count, the cells grow
// until they do not; every query still finds its faces.
TEST(FaceGrid, CellsGrowWhenTheEntriesWouldNotFit) {
  const Mesh m = off_centre_sphere();
  const FaceGrid fine(m, 0.05);
  const FaceGrid capped(m, 0.05, m.faces.size() + m.faces.size() / 4);
  EXPECT_GT(capped.cell_size(), fine.cell_size());
  const std::vector<std::uint8_t> indexed(m.faces.size(), 1);
  expect_finds_every_overlapping_face(capped, m, indexed);
  const FaceGrid one_cell_each(m, 0.05, m.faces.size());
  expect_finds_every_overlapping_face(one_cell_each, m, indexed);
}

}  // namespace
}  // namespace molsurf
