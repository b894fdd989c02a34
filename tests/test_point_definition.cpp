// PointDefinition: a point of the one-pass union named by the elements that define it.
#include <gtest/gtest.h>

#include <vector>

#include "atom_fixtures.hpp"
#include "geometry/implicit_point.hpp"
#include "geometry/predicates.hpp"
#include "surface/atom_polyhedra.hpp"
#include "surface/one_pass/point_definition.hpp"

namespace molsurf::surface_detail {
namespace {

using geometry::ImplicitPoint;

class PointDefinitionTest : public ::testing::Test {
 protected:
  PointDefinitionTest()
      : atoms{testing::atom_at({0, 0, 0}, 1.7), testing::atom_at({2.1, 0.3, -0.4}, 1.5),
              testing::atom_at({0.9, 1.8, 0.5}, 1.6)},
        polyhedra(atoms, options()) {}
  static SphereOptions options() {
    SphereOptions o;
    o.frequency = 3;
    o.probe = 0;
    return o;
  }
  std::array<Vec3, 3> face(std::uint32_t atom, std::uint32_t f) const {
    const Triangle& t = polyhedra.shape(atom).unit.faces[f];
    return {polyhedra.vertex(atom, t[0]), polyhedra.vertex(atom, t[1]), polyhedra.vertex(atom, t[2])};
  }
  std::vector<Atom> atoms;
  AtomPolyhedra polyhedra;
};

TEST_F(PointDefinitionTest, AnEdgeIsNamedAlikeFromEitherEnd) {
  const auto a = PointDefinition::edge_plane(0, 7, 3, 1, 11), b = PointDefinition::edge_plane(0, 3, 7, 1, 11);
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.hash(), b.hash());
  EXPECT_NE(a, PointDefinition::edge_plane(0, 3, 7, 1, 12));
  EXPECT_NE(a, PointDefinition::edge_plane(2, 3, 7, 1, 11));
}

TEST_F(PointDefinitionTest, ThreePlanesAreNamedAlikeInAnyOrder) {
  const auto a = PointDefinition::three_planes({{{2, 5}, {0, 9}, {1, 4}}});
  const auto b = PointDefinition::three_planes({{{1, 4}, {2, 5}, {0, 9}}});
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.hash(), b.hash());
  EXPECT_NE(a, PointDefinition::three_planes({{{1, 4}, {2, 6}, {0, 9}}}));
}

TEST_F(PointDefinitionTest, KindsNeverCompareEqual) {
  // The same ids under another kind name another point.
  PointDefinition v = PointDefinition::vertex(0, 3), e = PointDefinition::edge_plane(0, 3, 0, 0, 0);
  e.id = v.id;
  EXPECT_NE(v, e);
}

TEST_F(PointDefinitionTest, AVertexIsThePolyhedronsVertex) {
  const ImplicitPoint p = construct(PointDefinition::vertex(1, 17), polyhedra);
  ASSERT_TRUE(p.is_explicit());
  EXPECT_EQ(p.explicit_value(), polyhedra.vertex(1, 17));
}

TEST_F(PointDefinitionTest, AnEdgePlanePointLiesOnTheFacePlane) {
  // Find an edge of atom 0 that crosses a face plane of atom 1 and a face it meets.
  const PolyhedronTemplate& shape = polyhedra.shape(0);
  int tested = 0;
  for (const auto& e : shape.edges) {
    const Vec3 p = polyhedra.vertex(0, e[0]), q = polyhedra.vertex(0, e[1]);
    for (std::uint32_t g = 0; g < polyhedra.shape(1).unit.faces.size(); ++g) {
      const auto t = face(1, g);
      const int sp = geometry::orient3d(t[0], t[1], t[2], p), sq = geometry::orient3d(t[0], t[1], t[2], q);
      if (sp * sq >= 0) continue;
      const ImplicitPoint x = construct(PointDefinition::edge_plane(0, e[1], e[0], 1, g), polyhedra);
      EXPECT_EQ(x.kind(), ImplicitPoint::Kind::line_plane);
      EXPECT_EQ(geometry::orient3d(t[0], t[1], t[2], x), 0);
      EXPECT_TRUE(geometry::same_point(x, ImplicitPoint::line_plane(p, q, t[0], t[1], t[2])));
      ++tested;
    }
  }
  EXPECT_GT(tested, 10);
}

TEST_F(PointDefinitionTest, AThreePlanePointLiesOnAllThreePlanes) {
  const auto a = face(0, 4), b = face(1, 30), c = face(2, 55);
  const ImplicitPoint x = construct(PointDefinition::three_planes({{{2, 55}, {0, 4}, {1, 30}}}), polyhedra);
  EXPECT_EQ(x.kind(), ImplicitPoint::Kind::three_planes);
  for (const auto& t : {a, b, c}) EXPECT_EQ(geometry::orient3d(t[0], t[1], t[2], x), 0);
}

}  // namespace
}  // namespace molsurf::surface_detail
