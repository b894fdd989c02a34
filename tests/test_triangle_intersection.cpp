#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <random>

#include "geometry/triangle_intersection.hpp"

using molsurf::Mesh;
using molsurf::Vec3;
using molsurf::geometry::classify_triangle_pair;
using molsurf::geometry::folded_flat;
using molsurf::geometry::is_degenerate_face;
using molsurf::geometry::segment_meets_triangle;
using Relation = molsurf::geometry::TrianglePairRelation;

namespace {

Mesh make_mesh(std::initializer_list<Vec3> vertices, std::initializer_list<molsurf::Triangle> faces) {
  Mesh m;
  m.vertices = vertices;
  m.faces = faces;
  return m;
}

// Two faces (0,1,2) and (3,4,5) with no shared index.
Relation classify_separate(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e, const Vec3& f) {
  const Mesh m = make_mesh({a, b, c, d, e, f}, {{0, 1, 2}, {3, 4, 5}});
  const Relation r = classify_triangle_pair(m, 0, 1);
  EXPECT_EQ(classify_triangle_pair(m, 1, 0), r) << "the relation must be symmetric";
  return r;
}

const Vec3 kO{0, 0, 0}, kX2{2, 0, 0}, kY2{0, 2, 0};  // a reference triangle in z = 0

}  // namespace

TEST(SegmentMeetsTriangle, NonCoplanarCases) {
  // Straight through the interior: proper.
  auto m = segment_meets_triangle({0.5, 0.5, -1}, {0.5, 0.5, 1}, kO, kX2, kY2);
  EXPECT_TRUE(m.meets);
  EXPECT_TRUE(m.proper);
  // Through a vertex, through an edge: meets, not proper.
  m = segment_meets_triangle({0, 0, -1}, {0, 0, 1}, kO, kX2, kY2);
  EXPECT_TRUE(m.meets);
  EXPECT_FALSE(m.proper);
  m = segment_meets_triangle({1, 0, -1}, {1, 0, 1}, kO, kX2, kY2);
  EXPECT_TRUE(m.meets);
  EXPECT_FALSE(m.proper);
  // Endpoint on the face: meets, not proper.
  m = segment_meets_triangle({0.5, 0.5, 0}, {0.5, 0.5, 1}, kO, kX2, kY2);
  EXPECT_TRUE(m.meets);
  EXPECT_FALSE(m.proper);
  // Misses beside the triangle; stops short of the plane.
  EXPECT_FALSE(segment_meets_triangle({1.5, 1.5, -1}, {1.5, 1.5, 1}, kO, kX2, kY2).meets);
  EXPECT_FALSE(segment_meets_triangle({0.5, 0.5, 1e-300}, {0.5, 0.5, 1}, kO, kX2, kY2).meets);
  // Just outside the hypotenuse x + y = 2 by one ulp: exactness matters.
  const double beyond = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(segment_meets_triangle({beyond, 1, -1}, {beyond, 1, 1}, kO, kX2, kY2).meets);
  EXPECT_TRUE(segment_meets_triangle({1, 1, -1}, {1, 1, 1}, kO, kX2, kY2).meets);
}

TEST(SegmentMeetsTriangle, CoplanarCases) {
  // Crosses the triangle in its plane, from outside to outside: meets, never proper.
  auto m = segment_meets_triangle({-1, 0.5, 0}, {3, 0.5, 0}, kO, kX2, kY2);
  EXPECT_TRUE(m.meets);
  EXPECT_FALSE(m.proper);
  // Entirely inside.
  EXPECT_TRUE(segment_meets_triangle({0.2, 0.2, 0}, {0.5, 0.3, 0}, kO, kX2, kY2).meets);
  // Collinear with an edge, overlapping it / beyond its end.
  EXPECT_TRUE(segment_meets_triangle({-1, 0, 0}, {0.5, 0, 0}, kO, kX2, kY2).meets);
  EXPECT_TRUE(segment_meets_triangle({2, 0, 0}, {3, 0, 0}, kO, kX2, kY2).meets);
  EXPECT_FALSE(segment_meets_triangle({2.5, 0, 0}, {3, 0, 0}, kO, kX2, kY2).meets);
  // Outside, parallel to the hypotenuse.
  EXPECT_FALSE(segment_meets_triangle({3, 0, 0}, {0, 3, 0}, kO, kX2, kY2).meets);
  // A triangle in a vertical plane (normal has no z component) still projects properly.
  EXPECT_TRUE(segment_meets_triangle({0.5, 0, -1}, {0.5, 0, 3}, Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{0, 0, 2}).meets);
  EXPECT_FALSE(segment_meets_triangle({1.5, 0, 1.5}, {3, 0, 3}, Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{0, 0, 2}).meets);
}

TEST(DegenerateFace, RepeatedIndexAndCollinearCorners) {
  const Mesh m = make_mesh({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {1, 0, 0}, {0, 0, 1}, {0.1, 0.1, 0.1}},
                           {{0, 0, 1}, {0, 1, 2}, {0, 3, 4}, {0, 1, 5}});
  EXPECT_TRUE(is_degenerate_face(m, 0));
  EXPECT_TRUE(is_degenerate_face(m, 1));
  // Two of its three coordinate projections are degenerate, the third is not.
  EXPECT_FALSE(is_degenerate_face(m, 2));
  // 0.1 is not exactly representable but (0.1,0.1,0.1) is still exactly on the diagonal.
  EXPECT_TRUE(is_degenerate_face(m, 3));
}

TEST(TrianglePair, SharedEdge) {
  const Vec3 u{0, 0, 0}, v{1, 0, 0}, a{0, 1, 0};
  // Coplanar, corners on opposite sides: a flat pair of neighbours.
  EXPECT_EQ(classify_triangle_pair(make_mesh({u, v, a, {0, -1, 0}}, {{0, 1, 2}, {1, 0, 3}}), 0, 1), Relation::apart);
  // Bent along the edge.
  EXPECT_EQ(classify_triangle_pair(make_mesh({u, v, a, {0, 1, 1}}, {{0, 1, 2}, {1, 0, 3}}), 0, 1), Relation::apart);
  // Folded flat onto each other.
  EXPECT_EQ(classify_triangle_pair(make_mesh({u, v, a, {0.5, 0.5, 0}}, {{0, 1, 2}, {1, 0, 3}}), 0, 1),
            Relation::intersecting);
  // Almost folded (off the plane by 1e-300): not coplanar, so fine.
  EXPECT_EQ(classify_triangle_pair(make_mesh({u, v, a, {0.5, 0.5, 1e-300}}, {{0, 1, 2}, {1, 0, 3}}), 0, 1),
            Relation::apart);
  // Same three indices.
  EXPECT_EQ(classify_triangle_pair(make_mesh({u, v, a}, {{0, 1, 2}, {2, 1, 0}}), 0, 1), Relation::duplicate);
}

TEST(TrianglePair, SharedVertex) {
  auto pair = [](const Vec3& c, const Vec3& d) {
    const Mesh m = make_mesh({kO, kX2, kY2, c, d}, {{0, 1, 2}, {0, 3, 4}});
    return classify_triangle_pair(m, 0, 1);
  };
  EXPECT_EQ(pair({1, 0, 1}, {0, 1, 1}), Relation::apart);           // above the plane
  EXPECT_EQ(pair({-1, 0.1, 0}, {-0.1, -1, 0}), Relation::apart);    // coplanar, opposite wedge
  EXPECT_EQ(pair({-1, 0, 0}, {0, -1, 0}), Relation::apart);         // coplanar, edges collinear but apart
  EXPECT_EQ(pair({1, 0.2, 0}, {0.2, 1, 0}), Relation::intersecting);  // coplanar, inside the other
  EXPECT_EQ(pair({0.5, 0.5, -1}, {0.5, 0.5, 1}), Relation::intersecting);  // pierces it
  // Stands on the first face's edge from v: the faces touch along a segment, no crossing.
  EXPECT_EQ(pair({1, 0, 0}, {1, 0, 1}), Relation::contact);
  EXPECT_EQ(pair({3, -3, -1}, {3, -3, 1}), Relation::apart);       // straddles the plane, misses
  // A vertical wedge from v over the diagonal x = y: cuts the face along a segment from v.
  EXPECT_EQ(pair({3, 3, -1}, {3, 3, 1}), Relation::intersecting);
  // A vertical face over the diagonal standing on it (not through it): a contact.
  EXPECT_EQ(pair({3, 3, 0}, {3, 3, 1}), Relation::contact);
  // Coplanar, one inside the other but facing the other way: pressed face to face.
  EXPECT_EQ(pair({0.2, 1, 0}, {1, 0.2, 0}), Relation::contact);
}

// Faces at one shared vertex lying face to face: a contact for classify_triangle_pair,
// a flat fold for the rounding repair of a Boolean's result.
TEST(TrianglePair, FoldedFlat) {
  auto fold = [](const Vec3& c, const Vec3& d) {
    const Mesh m = make_mesh({kO, kX2, kY2, c, d}, {{0, 1, 2}, {0, 3, 4}});
    const bool f = folded_flat(m, m.faces[0], m.faces[1]);
    EXPECT_EQ(folded_flat(m, m.faces[1], m.faces[0]), f) << "symmetric";
    return f;
  };
  EXPECT_TRUE(fold({0.2, 1, 0}, {1, 0.2, 0}));              // coplanar, overlapping, facing away
  EXPECT_FALSE(fold({1, 0.2, 0}, {0.2, 1, 0}));             // facing the same way (a crossing instead)
  EXPECT_FALSE(fold({0.2, 1, 0x1p-20}, {1, 0.2, 0}));       // not coplanar
  EXPECT_FALSE(fold({-0.1, -1, 0}, {-1, -0.1, 0}));         // coplanar, facing away, apart
  EXPECT_FALSE(fold({1, 0, 0}, {0, 0, 1}));                  // touching along an edge line only
  // A shared edge or no shared index is not such a fold.
  const Mesh edge = make_mesh({kO, kX2, kY2, {1, 1, 0}}, {{0, 1, 2}, {1, 0, 3}});
  EXPECT_FALSE(folded_flat(edge, edge.faces[0], edge.faces[1]));
  const Mesh apart = make_mesh({kO, kX2, kY2, {0.1, 0.1, 0}, {0.1, 1, 0}, {1, 0.1, 0}}, {{0, 1, 2}, {3, 4, 5}});
  EXPECT_FALSE(folded_flat(apart, apart.faces[0], apart.faces[1]));
}

TEST(TrianglePair, NoSharedIndex) {
  // Far apart.
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {5, 5, 5}, {6, 5, 5}, {5, 6, 5}), Relation::apart);
  // Straddling the plane but beside the triangle.
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {3, 3, -1}, {3, 3, 1}, {4, 3, 0}), Relation::apart);
  // Interpenetrating.
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {5, 5, 0}), Relation::intersecting);
  // Coplanar overlap facing the same way: partial, a coincident copy, and a midpoint
  // triangle (no vertex strictly inside the other, no proper edge crossing, yet
  // positive-area overlap).
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {1, -1, 0}, {3, 0, 0}, {1, 1, 0}), Relation::intersecting);
  EXPECT_EQ(classify_separate(kO, kX2, kY2, kO, kX2, kY2), Relation::intersecting);
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}), Relation::intersecting);
  // The same overlaps facing opposite ways: solids pressed face to face, a contact.
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {1, -1, 0}, {1, 1, 0}, {3, 0, 0}), Relation::contact);
  EXPECT_EQ(classify_separate(kO, kX2, kY2, kO, kY2, kX2), Relation::contact);
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}), Relation::contact);
  // Coplanar, touching along part of an edge only: a contact.
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {1, 0, 0}, {3, 0, 0}, {2, -1, 0}), Relation::contact);
  // Coplanar, apart.
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {3, 0, 0}, {4, 0, 0}, {3, 1, 0}), Relation::apart);
}

TEST(TrianglePair, Contacts) {
  // Vertex exactly on the face, the rest above.
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {0.5, 0.5, 0}, {1, 1, 1}, {0, 1, 1}), Relation::contact);
  // One ulp above instead: apart.
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {0.5, 0.5, 0x1p-1074}, {1, 1, 1}, {0, 1, 1}), Relation::apart);
  // Vertex on an edge.
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {1, 0, 0}, {1, -1, 1}, {1, 1, 1}), Relation::contact);
  // Coincident vertices at different indices (a duplicated touching point).
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {0, 0, 0}, {-1, 0, -1}, {0, -1, -1}), Relation::contact);
  // Edge on edge: an edge of the second passes through a point of the first's edge y = 0.
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {1, -1, 1}, {1, 1, -1}, {1, -5, -5}), Relation::contact);
  // A vertical triangle standing on the face along a segment.
  EXPECT_EQ(classify_separate(kO, kX2, kY2, {1, -1, 0}, {1, 1, 0}, {1, 0, 1}), Relation::contact);
}

// Random triangles on a tiny integer grid (so coplanar, collinear and coincident cases
// abound): the answers may not depend on how the same geometry is written down.
TEST(TrianglePair, InvariantUnderRelabelling) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> coord(0, 2);
  auto point = [&] { return Vec3{double(coord(rng)), double(coord(rng)), double(coord(rng))}; };
  int counts[4] = {0, 0, 0, 0};
  for (int trial = 0; trial < 20000; ++trial) {
    Mesh m = make_mesh({point(), point(), point(), point(), point(), point()}, {{0, 1, 2}, {3, 4, 5}});
    if (is_degenerate_face(m, 0) || is_degenerate_face(m, 1)) continue;
    const Relation r = classify_triangle_pair(m, 0, 1);
    ++counts[static_cast<int>(r)];
    ASSERT_EQ(classify_triangle_pair(m, 1, 0), r) << trial;
    Mesh rotated = m;
    rotated.faces = {{1, 2, 0}, {5, 3, 4}};
    ASSERT_EQ(classify_triangle_pair(rotated, 0, 1), r) << trial;
    Mesh both_reversed = m;
    both_reversed.faces = {{0, 2, 1}, {3, 5, 4}};
    ASSERT_EQ(classify_triangle_pair(both_reversed, 0, 1), r) << trial;
    // The segment test: endpoints swapped, triangle rotated or reversed.
    const Vec3 &p = m.vertices[3], &q = m.vertices[4], &a = m.vertices[0], &b = m.vertices[1], &c = m.vertices[2];
    const auto s = segment_meets_triangle(p, q, a, b, c);
    const auto s2 = segment_meets_triangle(q, p, c, a, b);
    const auto s3 = segment_meets_triangle(p, q, a, c, b);
    ASSERT_TRUE(s.meets == s2.meets && s.proper == s2.proper && s.meets == s3.meets && s.proper == s3.proper)
        << trial;
    ASSERT_TRUE(!s.proper || s.meets);
  }
  // The grid must produce every kind of relation, or the test proves little.
  EXPECT_GT(counts[static_cast<int>(Relation::apart)], 100);
  EXPECT_GT(counts[static_cast<int>(Relation::contact)], 100);
  EXPECT_GT(counts[static_cast<int>(Relation::intersecting)], 100);
}

// With shared indices: the second face reuses corners of the first.
TEST(TrianglePair, SharedIndicesInvariantUnderRelabelling) {
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> coord(0, 2);
  std::uniform_int_distribution<molsurf::Index> corner(0, 4);
  auto point = [&] { return Vec3{double(coord(rng)), double(coord(rng)), double(coord(rng))}; };
  int intersecting = 0, apart = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const molsurf::Index i = corner(rng), j = corner(rng), k = corner(rng);
    if (i == j || j == k || k == i) continue;
    Mesh m = make_mesh({point(), point(), point(), point(), point()}, {{0, 1, 2}, {i, j, k}});
    if (is_degenerate_face(m, 0) || is_degenerate_face(m, 1)) continue;
    const Relation r = classify_triangle_pair(m, 0, 1);
    ASSERT_EQ(classify_triangle_pair(m, 1, 0), r) << trial;
    Mesh rotated = m;
    rotated.faces = {{2, 0, 1}, {j, k, i}};
    ASSERT_EQ(classify_triangle_pair(rotated, 0, 1), r) << trial;
    intersecting += r == Relation::intersecting;
    apart += r == Relation::apart;
  }
  EXPECT_GT(intersecting, 100);
  EXPECT_GT(apart, 100);
}
