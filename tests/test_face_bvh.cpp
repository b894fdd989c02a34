#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include "geometry/face_bvh.hpp"

using molsurf::BoundingBox;
using molsurf::Vec3;
using molsurf::geometry::BoxBvh;

namespace {

// Boxes on a coarse grid so that exact ties (touching faces, edges, corners) are common.
std::vector<BoundingBox> random_boxes(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> corner(0, 40), size(0, 4);
  std::vector<BoundingBox> boxes(n);
  for (auto& b : boxes) {
    b.min = {double(corner(rng)), double(corner(rng)), double(corner(rng))};
    b.max = b.min + Vec3{double(size(rng)), double(size(rng)), double(size(rng))};
  }
  return boxes;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> brute_force_pairs(const std::vector<BoundingBox>& boxes) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::uint32_t i = 0; i < boxes.size(); ++i)
    for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(i, j);
  return pairs;
}

}  // namespace

TEST(BoxBvh, TiesOverlap) {
  BoundingBox a{{0, 0, 0}, {1, 1, 1}}, corner_touch{{1, 1, 1}, {2, 2, 2}}, apart{{1.5, 0, 0}, {2, 1, 1}};
  EXPECT_TRUE(a.overlaps(corner_touch));
  EXPECT_FALSE(a.overlaps(apart));
  EXPECT_FALSE(a.overlaps(BoundingBox{}));  // empty overlaps nothing
}

TEST(BoxBvh, PairsEqualBruteForce) {
  for (const std::size_t n : {0u, 1u, 3u, 4u, 5u, 17u, 500u, 3000u}) {
    const auto boxes = random_boxes(n, static_cast<unsigned>(n) + 1);
    const BoxBvh bvh(boxes);
    EXPECT_EQ(bvh.item_count(), n);
    const auto expected = brute_force_pairs(boxes);
    EXPECT_EQ(bvh.overlapping_pairs(), expected) << n << " boxes";
    if (n >= 500) EXPECT_GT(expected.size(), n / 10) << "the test should have many overlaps";
  }
}

TEST(BoxBvh, LeafPairsVisitEveryOverlappingPairOnce) {
  for (const std::size_t n : {0u, 1u, 4u, 5u, 17u, 500u, 3000u}) {
    const auto boxes = random_boxes(n, static_cast<unsigned>(n) + 11);
    const BoxBvh bvh(boxes);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> found;
    for (std::size_t leaf = 0; leaf < bvh.leaf_count(); ++leaf)
      bvh.for_each_pair_at_leaf(leaf, [&](std::uint32_t i, std::uint32_t j) {
        found.emplace_back(std::min(i, j), std::max(i, j));
      });
    std::sort(found.begin(), found.end());  // a pair seen twice stays twice
    EXPECT_EQ(found, brute_force_pairs(boxes)) << n << " boxes";
  }
}

TEST(BoxBvh, QueryEqualsBruteForce) {
  const auto boxes = random_boxes(2000, 99);
  const BoxBvh bvh(boxes);
  const auto queries = random_boxes(200, 7);
  for (const BoundingBox& q : queries) {
    std::vector<std::uint32_t> found, expected;
    bvh.for_each_overlap(q, [&](std::uint32_t id) { found.push_back(id); });
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
      if (q.overlaps(boxes[i])) expected.push_back(i);
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected);
  }
}

TEST(BoxBvh, FacesOfAMeshWithExclusions) {
  molsurf::Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {5, 5, 5}, {6, 5, 5}, {5, 6, 5}};
  mesh.faces = {{0, 1, 2}, {1, 3, 2}, {4, 5, 6}, {0, 3, 1}};
  const std::vector<std::uint8_t> include{1, 1, 1, 0};
  const BoxBvh bvh = BoxBvh::for_faces(mesh, include);
  EXPECT_EQ(bvh.item_count(), 3u);
  using Pair = std::pair<std::uint32_t, std::uint32_t>;
  EXPECT_EQ(bvh.overlapping_pairs(), (std::vector<Pair>{{0, 1}}));
  EXPECT_EQ(BoxBvh::for_faces(mesh).overlapping_pairs(), (std::vector<Pair>{{0, 1}, {0, 3}, {1, 3}}));
}

// The tree stores its boxes in single precision, rounded outward: every pair of boxes that
// overlap or touch in double precision must still be found, whatever their coordinates
// (here, none representable as a float), and a pair found beyond that may only be apart
// by the rounding (a few float ulps).
TEST(BoxBvh, SinglePrecisionBoundsMissNoPairOfDoubleBoxes) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> corner(-120.0, 120.0), size(0.0, 3.0);
  std::vector<BoundingBox> boxes;
  for (int k = 0; k < 1500; ++k) {
    BoundingBox a;
    a.min = {corner(rng), corner(rng), corner(rng)};
    a.max = a.min + Vec3{size(rng), size(rng), size(rng)};
    boxes.push_back(a);
    // Its neighbour touches it exactly in x (a tie), or misses it by 1e-12.
    BoundingBox b = a;
    b.min.x = a.max.x + (k % 2 == 0 ? 0.0 : 1e-12);
    b.max.x = b.min.x + size(rng);
    boxes.push_back(b);
  }
  const BoxBvh bvh(boxes);
  const auto expected = brute_force_pairs(boxes);
  const auto found = bvh.overlapping_pairs();
  EXPECT_TRUE(std::includes(found.begin(), found.end(), expected.begin(), expected.end()));
  EXPECT_GE(expected.size(), 750u);
  for (const auto& [i, j] : found) {
    const BoundingBox& a = boxes[i];
    const BoundingBox& b = boxes[j];
    const double gap = std::max({a.min.x - b.max.x, b.min.x - a.max.x, a.min.y - b.max.y, b.min.y - a.max.y,
                                 a.min.z - b.max.z, b.min.z - a.max.z});
    EXPECT_LE(gap, 1e-4) << i << ", " << j;
  }
  // Queries by double boxes see the same superset.
  for (std::uint32_t i = 0; i < boxes.size(); i += 7) {
    std::vector<std::uint32_t> hits;
    bvh.for_each_overlap(boxes[i], [&](std::uint32_t j) { hits.push_back(j); });
    for (std::uint32_t j = 0; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) EXPECT_NE(std::find(hits.begin(), hits.end(), j), hits.end()) << i << ", " << j;
  }
}
