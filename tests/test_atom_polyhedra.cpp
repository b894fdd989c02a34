// The atoms' polyhedra as the one-pass union reads them: the balls that bound each one,
// and what those balls settle about a constructed point known only within its box.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "atom_fixtures.hpp"
#include "geometry/interval.hpp"
#include "surface/atom_polyhedra.hpp"

namespace molsurf::surface_detail {
namespace {

using geometry::Interval;

std::array<Interval, 3> box(const Vec3& lo, const Vec3& hi) {
  return {Interval(lo.x, hi.x), Interval(lo.y, hi.y), Interval(lo.z, hi.z)};
}

TEST(AtomPolyhedra, BallsBoundEveryVertexAndFacePlane) {
  const std::vector<Atom> atoms{testing::atom_at({1.5, -2, 30}, 1.7), testing::atom_at({-40, 7.25, 3}, 1.52)};
  const AtomPolyhedra polyhedra(atoms, SphereOptions{});
  for (std::size_t a = 0; a < atoms.size(); ++a) {
    std::vector<Vec3> vertices;
    polyhedra.vertices(a, vertices);
    const Vec3 c = polyhedra.centre(a);
    for (const Vec3& v : vertices) EXPECT_LE(norm(v - c), polyhedra.circumradius(a));
    for (const Triangle& t : polyhedra.shape(a).unit.faces) {
      const Vec3 p = vertices[t[0]], n = cross(vertices[t[1]] - p, vertices[t[2]] - p);
      EXPECT_GE(dot(p - c, n) / norm(n), polyhedra.inradius(a));  // the face plane's distance
    }
  }
}

// The one-pass union drops a block of faces whole when its ball lies in a neighbour's
// inscribed ball: every vertex of the block's faces must lie in that ball, as computed.
TEST(AtomPolyhedra, BlockBallsHoldTheirFaces) {
  for (const double density : {0.3, 2.0, 4.0}) {
    const std::vector<Atom> atoms{testing::atom_at({1.5, -2, 30}, 1.7), testing::atom_at({-4000, 7.25, 3}, 1.0)};
    SphereOptions options;
    options.density = density;
    const AtomPolyhedra polyhedra(atoms, options);
    for (std::size_t a = 0; a < atoms.size(); ++a) {
      std::vector<Vec3> vertices;
      polyhedra.vertices(a, vertices);
      const PolyhedronTemplate& shape = polyhedra.shape(a);
      const std::size_t block_faces = static_cast<std::size_t>(shape.frequency) * shape.frequency;
      ASSERT_EQ(shape.unit.faces.size(), 20 * block_faces);
      const double scale = polyhedra.scale(a);
      for (std::size_t f = 0; f < shape.unit.faces.size(); ++f) {
        const std::size_t b = f / block_faces;
        const Vec3 centre = polyhedra.centre(a) + shape.block_centre[b] * scale;
        const double radius = shape.block_radius[b] * scale + 2 * polyhedra.vertex_error(a);
        for (Index v : shape.unit.faces[f]) EXPECT_LE(norm(vertices[v] - centre), radius) << "face " << f;
      }
      // A block is one icosahedron face's share: far smaller than the polyhedron.
      for (std::size_t b = 0; b < 20; ++b) EXPECT_LT(shape.block_radius[b], 0.7) << b;
    }
  }
}

TEST(AtomPolyhedra, BallsSettleOnlyWhatTheWholeBoxSays) {
  const Vec3 c{10, 20, 30};
  const double inner = 1.5, outer = 2;
  // A tight box in the inscribed ball, or beyond the circumscribed one.
  EXPECT_EQ(settled_by_balls(box({10.5, 20, 30}, {10.5000001, 20, 30}), c, inner, outer), true);
  EXPECT_EQ(settled_by_balls(box({12.5, 20, 30}, {12.5000001, 20, 30}), c, inner, outer), false);
  // Between the balls: the exact test decides.
  EXPECT_EQ(settled_by_balls(box({11.8, 20, 30}, {11.8000001, 20, 30}), c, inner, outer), std::nullopt);
  // A wide box (a line nearly parallel to a plane) whose midpoint lies far outside while
  // the box reaches into the inscribed ball: not settled (its midpoint would say outside).
  EXPECT_EQ(settled_by_balls(box({9.5, 20, 30}, {16.5, 20, 30}), c, inner, outer), std::nullopt);
  // ... or whose midpoint lies inside while the box reaches beyond: not settled either.
  EXPECT_EQ(settled_by_balls(box({9, 19, 29}, {11.5, 21, 31}), c, inner, outer), std::nullopt);
  // A box around the centre wider than the inscribed ball, and one that only grazes it.
  EXPECT_EQ(settled_by_balls(box({8, 18, 28}, {12, 22, 32}), c, inner, outer), std::nullopt);
  EXPECT_EQ(settled_by_balls(box({11.4, 20, 30}, {11.6, 20, 30}), c, inner, outer), std::nullopt);
  // Beyond the circumscribed ball on one axis only, far along it: outside.
  EXPECT_EQ(settled_by_balls(box({9, 22.5, 29}, {11, 23, 31}), c, inner, outer), false);
  // A box with an unbounded side says nothing.
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(settled_by_balls(box({10, 20, 30}, {inf, 20, 30}), c, inner, outer), std::nullopt);
}

}  // namespace
}  // namespace molsurf::surface_detail
