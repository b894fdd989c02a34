// Step 3 of the engine, split (paper §2.3), on its own: the face's points with exact
// predicates (face_points.hpp), the ear clippers (ear_clipping.hpp) and the advancing
// front (advancing_front.hpp), on hand-made faces whose right answer is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <span>
#include <utility>
#include <vector>

#include "boolean/advancing_front.hpp"
#include "boolean/ear_clipping.hpp"
#include "boolean/face_points.hpp"
#include "geometry/implicit_point.hpp"

namespace molsurf::boolean_engine {
namespace {

using geometry::ImplicitPoint;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// The face (0,0,0), (8,0,0), (0,8,0) in the plane z = 0 (counter-clockwise seen from +z),
// with points added by the tests after its three corners (ids 0, 1, 2).
struct Face {
  std::vector<ImplicitPoint> points;
  std::vector<Vec3> at;
  std::uint32_t add(const Vec3& p) {
    points.push_back(ImplicitPoint::explicit_point(p));
    at.push_back(p);
    return static_cast<std::uint32_t>(points.size() - 1);
  }
  Face() {
    add({0, 0, 0});
    add({8, 0, 0});
    add({0, 8, 0});
  }
  Projection projection() const { return face_projection(at[0], at[1], at[2]); }
  double signed_area(const std::array<std::uint32_t, 3>& t) const {
    const Vec3 &a = at[t[0]], &b = at[t[1]], &c = at[t[2]];
    return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
};

bool has_edge(const Triangles& triangles, std::uint32_t a, std::uint32_t b) {
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      if ((t[k] == a && t[(k + 1) % 3] == b) || (t[k] == b && t[(k + 1) % 3] == a)) return true;
  return false;
}

// Every triangle counter-clockwise and none degenerate, together covering the face
// exactly once (their areas sum to the face's), every given point used, every constraint
// an edge.
void expect_tiles_the_face(const Face& face, const Triangles& triangles, const std::vector<std::uint32_t>& used,
                           const std::vector<std::pair<std::uint32_t, std::uint32_t>>& constraints) {
  double area = 0;
  std::set<std::uint32_t> corners;
  for (const auto& t : triangles) {
    EXPECT_GT(face.signed_area(t), 0) << t[0] << " " << t[1] << " " << t[2];
    area += face.signed_area(t);
    corners.insert(t.begin(), t.end());
  }
  EXPECT_DOUBLE_EQ(area, 32.0);
  for (std::uint32_t p : used) EXPECT_TRUE(corners.count(p)) << "point " << p << " unused";
  for (auto [a, b] : constraints) EXPECT_TRUE(has_edge(triangles, a, b)) << "constraint " << a << "-" << b;
}

TEST(FacePoints, OrientsAndSortsExactlyOnACollinearRun) {
  Face face;
  const std::uint32_t m = face.add({4, 0, 0}), q = face.add({2, 0, 0}), r = face.add({6, 0, 0});
  const FacePoints points({0, 1, 2, m, q, r}, face.points, face.projection());
  EXPECT_EQ(points.orient(points.local(0), points.local(1), points.local(2)), 1);
  EXPECT_EQ(points.orient(points.local(0), points.local(m), points.local(1)), 0);  // on edge 0
  std::vector<std::uint32_t> ids{r, m, q};
  sort_along_segment(ids, face.at[0], face.at[1], face.points);
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{q, m, r}));
  sort_along_segment(ids, face.at[1], face.at[0], face.points);  // the other way
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{r, m, q}));
}

TEST(FacePoints, FindsTheLocalIndexOfCloseAndOfSpreadIds) {
  Face face;
  // Close ids (a table): in any order, repeated (the first place counts), missing ones refused.
  const FacePoints close({5, 3, 7, 3}, face.points, face.projection());
  EXPECT_EQ(close.local(5), 0);
  EXPECT_EQ(close.local(3), 1);
  EXPECT_EQ(close.local(7), 2);
  for (const std::uint32_t missing : {0u, 2u, 4u, 6u, 8u, 1000u}) EXPECT_THROW(close.local(missing), std::out_of_range);
  // Spread ids (a sorted list), as the pairwise engine's global ones.
  const FacePoints spread({0, 1000000, 7, 1000000}, face.points, face.projection());
  EXPECT_EQ(spread.local(1000000), 1);
  EXPECT_EQ(spread.local(7), 2);
  for (const std::uint32_t missing : {1u, 8u, 999999u, 1000001u}) EXPECT_THROW(spread.local(missing), std::out_of_range);
}

TEST(FacePoints, SplitsASegmentAtThePointsOnIt) {
  Face face;
  const std::uint32_t a = face.add({1, 1, 0}), b = face.add({5, 1, 0}), on = face.add({3, 1, 0}),
                      off = face.add({3, 2, 0});
  const FacePoints points({0, 1, 2, a, b, on, off}, face.points, face.projection());
  std::vector<std::vector<std::uint32_t>> collinear;
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> segments{{a, b}};
  auto pieces = split_segments_at_points(segments, points, collinear);
  for (auto& [s, t] : pieces)
    if (s > t) std::swap(s, t);
  std::sort(pieces.begin(), pieces.end());
  EXPECT_EQ(pieces, (std::vector<std::pair<std::uint32_t, std::uint32_t>>{{a, on}, {b, on}}));
  ASSERT_EQ(collinear.size(), 1u);
  EXPECT_EQ(std::count(collinear[0].begin(), collinear[0].end(), off), 0);
}

TEST(EarClipping, CutsAFaceAlongChordsIntoConvexPieces) {
  Face face;
  // One point inside each edge; chords between them cut off the three corners.
  const std::uint32_t e0 = face.add({4, 0, 0}), e1 = face.add({4, 4, 0}), e2 = face.add({0, 4, 0});
  const std::vector<std::uint32_t> boundary{0, e0, 1, e1, 2, e2};
  const std::vector<std::vector<std::uint32_t>> edge_runs{{0, e0, 1}, {1, e1, 2}, {2, e2, 0}};
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> chords{{e0, e1}, {e1, e2}, {e2, e0}};
  const auto triangles = triangulate_chords(boundary, edge_runs, chords, face.points, face.projection());
  ASSERT_TRUE(triangles.has_value());
  EXPECT_EQ(triangles->size(), 4u);
  expect_tiles_the_face(face, *triangles, boundary, chords);
}

// Two traces that cross at an interior point, each from edge to edge.
FaceToSplit crossing_traces(Face& face, std::vector<std::uint32_t>& used) {
  const std::uint32_t e0 = face.add({3, 0, 0}), e1 = face.add({3, 5, 0}), e2a = face.add({0, 2, 0}),
                      e1b = face.add({6, 2, 0}), x = face.add({3, 2, 0});
  FaceToSplit f;
  f.boundary = {0, e0, 1, e1b, e1, 2, e2a};
  f.interior = {x};
  f.constraints = {{e0, x}, {x, e1}, {e2a, x}, {x, e1b}};
  f.collinear_sets = {{0, e0, 1}, {1, e1b, e1, 2}, {2, e2a, 0}, {e0, x, e1}, {e2a, x, e1b}};
  f.projection = face.projection();
  used = f.boundary;
  used.push_back(x);
  return f;
}

std::vector<std::uint32_t> boundary_and_interior(const FaceToSplit& f) {
  std::vector<std::uint32_t> ids = f.boundary;
  ids.insert(ids.end(), f.interior.begin(), f.interior.end());
  return ids;
}

// The face of crossing_traces with its points, as the ear clippers take them (not
// copied: `points` refers to `face`).
struct CrossingFace {
  Face face;
  std::vector<std::uint32_t> used;
  FaceToSplit f = crossing_traces(face, used);
  FacePoints points{boundary_and_interior(f), face.points, f.projection};
};

TEST(EarClipping, CutsAFaceAlongTracesThatCrossInside) {
  const CrossingFace c;
  const auto triangles = triangulate_polylines(c.f, c.points);
  ASSERT_TRUE(triangles.has_value());
  expect_tiles_the_face(c.face, *triangles, c.used, c.f.constraints);
}

TEST(EarClipping, LeavesOutThePiecesNotWanted) {
  // The one-pass union drops the pieces inside a neighbour before clipping them: here the
  // piece at corner 0 (the rectangle 0, (3,0), (3,2), (0,2): area 6).
  const CrossingFace c;
  const auto all = triangulate_polylines(c.f, c.points);
  ASSERT_TRUE(all.has_value());
  int asked = 0;
  PolylineWork work;
  const auto wanted = triangulate_polylines(c.f, c.points, work, [&](std::span<const std::uint32_t> corners) {
    ++asked;
    return std::find(corners.begin(), corners.end(), 0u) == corners.end();
  });
  ASSERT_TRUE(wanted.has_value());
  EXPECT_EQ(asked, 4);
  double area = 0;
  for (const auto& t : *wanted) {
    EXPECT_EQ(std::count(t.begin(), t.end(), 0u), 0);
    EXPECT_NE(std::find(all->begin(), all->end(), t), all->end()) << "not a triangle of the whole face's";
    area += c.face.signed_area(t);
  }
  EXPECT_DOUBLE_EQ(area, 32.0 - 6.0);
  EXPECT_EQ(wanted->size(), all->size() - 2);
}

TEST(AdvancingFront, TriangulatesWhatTheEarClippersLeave) {
  // A point inside the face on no constraint (a neighbour's vertex poking through): no
  // polyline reaches it, so the ear clippers refuse and the front takes it.
  Face face;
  std::vector<std::uint32_t> used;
  FaceToSplit f = crossing_traces(face, used);
  const std::uint32_t loose = face.add({1, 5, 0});
  f.interior.push_back(loose);
  used.push_back(loose);
  const FacePoints points(boundary_and_interior(f), face.points, f.projection);
  EXPECT_FALSE(triangulate_polylines(f, points).has_value());
  const Triangles triangles = retriangulate_face(f, points);
  expect_tiles_the_face(face, triangles, used, f.constraints);
}

}  // namespace
}  // namespace molsurf::boolean_engine
