// Step 4 of the engine, classify (paper §2.4), on its own: the steps before it are run as
// boolean() runs them, and every sub-face's side is compared with what the geometry says
// (boxes, whose inside is known without the engine), together with how the verdicts were
// reached: seeds and crossings for most patches, one ray per patch otherwise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "boolean/arrangement.hpp"
#include "boolean/classify.hpp"
#include "boolean/cull.hpp"
#include "boolean/intersect.hpp"
#include "boolean/operands.hpp"
#include "boolean/split.hpp"
#include "support/shapes.hpp"

namespace molsurf::boolean_engine {
namespace {

// Steps 1-4 on two closed solids, whole (no active part).
struct Classified {
  Operands operands;
  Arrangement arrangement;
  SplitResult split;
  Classification classes;

  Classified(const Mesh& a, const Mesh& b) : operands(a, b, a, b) {
    std::vector<PairIntersection> pairs;
    for (auto [fa, fb] : cull_face_pairs(operands))
      if (PairIntersection p = intersect_faces(operands, fa, fb); !p.empty()) pairs.push_back(std::move(p));
    arrangement = build_arrangement(operands, pairs);
    split = split_faces(operands, arrangement);
    classes = classify_sub_faces(operands, arrangement, split);
  }

  // A point strictly inside the sub-face (its corners' rounded average: the sub-faces of
  // these tests are not slivers, so the rounding cannot carry it across an edge).
  Vec3 centroid(std::size_t s) const {
    Vec3 sum{0, 0, 0};
    for (std::uint32_t p : split.sub_faces[s].points) sum = sum + arrangement.points[p].rounded();
    return (1.0 / 3.0) * sum;
  }
  int operand(std::size_t s) const { return operands.operand_of_face(split.sub_faces[s].face); }
};

// Where a point on the boundary of one box lies against the other box [lo, hi]: strictly
// inside, strictly outside, or on its boundary (then the test does not judge).
enum class Against { inside, outside, boundary };
Against against_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  bool inside = true, outside = false;
  for (int axis = 0; axis < 3; ++axis) {
    inside &= p[axis] > lo[axis] && p[axis] < hi[axis];
    outside |= p[axis] < lo[axis] || p[axis] > hi[axis];
  }
  return inside ? Against::inside : outside ? Against::outside : Against::boundary;
}

struct Box {
  Vec3 lo, hi;
};

// Every sub-face of either box, off the other's boundary, gets the side its centroid has.
void expect_sides_match_boxes(const Classified& c, const Box& a, const Box& b, std::size_t* judged_out = nullptr) {
  std::size_t judged = 0;
  for (std::size_t s = 0; s < c.split.sub_faces.size(); ++s) {
    const Box& other = c.operand(s) == 0 ? b : a;
    const Against where = against_box(c.centroid(s), other.lo, other.hi);
    if (where == Against::boundary) continue;
    ++judged;
    EXPECT_EQ(c.classes.side[s], where == Against::inside ? Side::inside : Side::outside)
        << "sub-face " << s << " of operand " << c.operand(s) << " (face " << c.split.sub_faces[s].face << ")";
  }
  EXPECT_GT(judged, 0u);
  if (judged_out) *judged_out = judged;
}

TEST(ClassifyStep, OverlappingBoxesInGeneralPosition) {
  const Box a{{0, 0, 0}, {2, 2, 2}}, b{{0.73, 0.61, 0.57}, {2.91, 2.83, 2.77}};
  const Classified c(make_box(a.lo, a.hi, 3, 3, 3), make_box(b.lo, b.hi, 3, 3, 3));
  ASSERT_EQ(c.classes.side.size(), c.split.sub_faces.size());
  expect_sides_match_boxes(c, a, b);
  // Each solid's faces fall in two patches joined across the transversal crossing: the
  // patch with a corner outside the other's box is a seed (outside), and the crossing
  // makes the other patch inside. No ray is needed.
  EXPECT_EQ(c.classes.ray_casts, 0u);
  EXPECT_FALSE(c.split.opposite_sides.empty());
}

TEST(ClassifyStep, ANestedBoxWithoutContactTakesOneRay) {
  const Box a{{0, 0, 0}, {4, 4, 4}}, b{{1.1, 1.3, 1.2}, {2.9, 2.7, 2.8}};
  const Classified c(make_box(a.lo, a.hi, 2, 2, 2), make_box(b.lo, b.hi));
  std::size_t judged = 0;
  expect_sides_match_boxes(c, a, b, &judged);
  EXPECT_EQ(judged, c.split.sub_faces.size());  // no face is cut
  EXPECT_TRUE(c.split.opposite_sides.empty());
  for (std::size_t s = 0; s < c.split.sub_faces.size(); ++s)
    EXPECT_EQ(c.classes.side[s], c.operand(s) == 1 ? Side::inside : Side::outside);
  // The outer box's corners lie outside the inner one's box (a seed); the inner box has
  // neither a seed nor a crossing: one ray, from one of its own corners (not the exact path).
  EXPECT_EQ(c.classes.ray_casts, 1u);
  EXPECT_EQ(c.classes.exact_ray_casts, 0u);
}

// Faces in one plane: pieces of a box's top that lie in the other's top are coincident
// with the same orientation; where two boxes meet face to face, with the opposite one.
TEST(ClassifyStep, CoplanarTopsAreCoincidentWithTheSameOrientation) {
  const Box a{{0, 0, 0}, {2, 2, 2}}, b{{1.3, 0.7, 0.9}, {3.1, 2.9, 2}};  // tops both at z = 2
  const Classified c(make_box(a.lo, a.hi, 2, 2, 2), make_box(b.lo, b.hi, 2, 2, 2));
  std::size_t same = 0;
  for (std::size_t s = 0; s < c.split.sub_faces.size(); ++s) {
    const Vec3 m = c.centroid(s);
    const Box& other = c.operand(s) == 0 ? b : a;
    const bool in_both_tops = m.z == 2 && m.x > other.lo.x && m.x < other.hi.x && m.y > other.lo.y && m.y < other.hi.y;
    if (in_both_tops) {
      EXPECT_EQ(c.classes.side[s], Side::coincident_same) << "sub-face " << s;
      ++same;
    } else {
      EXPECT_NE(c.classes.side[s], Side::coincident_same) << "sub-face " << s;
      EXPECT_NE(c.classes.side[s], Side::coincident_opposite) << "sub-face " << s;
    }
  }
  EXPECT_GT(same, 0u);
  expect_sides_match_boxes(c, a, b);
}

TEST(ClassifyStep, BoxesFaceToFaceAreCoincidentWithOppositeOrientations) {
  const Box a{{0, 0, 0}, {2, 2, 2}}, b{{2, 0.4, 0.3}, {3.5, 1.7, 2.6}};  // a's x = 2 side on b's
  const Classified c(make_box(a.lo, a.hi, 2, 2, 2), make_box(b.lo, b.hi, 2, 2, 2));
  std::size_t opposite = 0;
  for (std::size_t s = 0; s < c.split.sub_faces.size(); ++s) {
    const Vec3 m = c.centroid(s);
    const bool shared = m.x == 2 && m.y > 0.4 && m.y < 1.7 && m.z > 0.3 && m.z < 2;
    if (shared) {
      EXPECT_EQ(c.classes.side[s], Side::coincident_opposite) << "sub-face " << s;
      ++opposite;
    } else {
      EXPECT_EQ(c.classes.side[s], Side::outside) << "sub-face " << s;  // the solids only touch
    }
  }
  EXPECT_GT(opposite, 0u);
}

// A corner of one box exactly on a face of the other: that vertex is on both surfaces and
// cannot seed its patch; the verdict still matches the geometry.
TEST(ClassifyStep, CornerOnTheOtherSurface) {
  const Box a{{0, 0, 0}, {2, 2, 2}};
  Mesh tilted = make_box({0, 0, 0}, {1, 1, 1});
  // Rotated so that one corner points down; that corner is then placed on a's top.
  const RigidTransform turn{{1, -1, 0}, 0.9553166181245093, {0, 0, 0}};
  tilted = transformed(tilted, turn);
  std::uint32_t lowest = 0;
  for (std::uint32_t v = 1; v < tilted.vertices.size(); ++v)
    if (tilted.vertices[v].z < tilted.vertices[lowest].z) lowest = v;
  const Vec3 shift{1.1 - tilted.vertices[lowest].x, 0.9 - tilted.vertices[lowest].y, 2 - tilted.vertices[lowest].z};
  for (Vec3& v : tilted.vertices) v = v + shift;
  ASSERT_EQ(tilted.vertices[lowest].z, 2.0);
  const Classified c(make_box(a.lo, a.hi, 2, 2, 2), tilted);
  for (std::size_t s = 0; s < c.split.sub_faces.size(); ++s) {
    if (c.operand(s) == 0) continue;
    EXPECT_EQ(c.classes.side[s], Side::outside) << "sub-face " << s;  // the tilted box sits on a
  }
  for (std::size_t s = 0; s < c.split.sub_faces.size(); ++s)
    if (c.operand(s) == 0) EXPECT_EQ(c.classes.side[s], Side::outside) << "sub-face " << s;
}

TEST(ClassifyStep, SelectionFollowsTheOperation) {
  EXPECT_EQ(select_sub_face(BooleanOp::union_, 0, Side::outside), Keep::keep);
  EXPECT_EQ(select_sub_face(BooleanOp::union_, 1, Side::inside), Keep::drop);
  EXPECT_EQ(select_sub_face(BooleanOp::intersection, 0, Side::inside), Keep::keep);
  EXPECT_EQ(select_sub_face(BooleanOp::intersection, 1, Side::outside), Keep::drop);
  EXPECT_EQ(select_sub_face(BooleanOp::difference, 1, Side::inside), Keep::keep_flipped);
  EXPECT_EQ(select_sub_face(BooleanOp::difference, 1, Side::outside), Keep::drop);
  // Coincident pieces: one copy survives where both solids keep that side.
  EXPECT_NE(select_sub_face(BooleanOp::union_, 0, Side::coincident_same),
            select_sub_face(BooleanOp::union_, 1, Side::coincident_same));
}

}  // namespace
}  // namespace molsurf::boolean_engine
