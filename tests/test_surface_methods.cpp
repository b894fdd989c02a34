// The one-pass union against the pairwise union: small structures at every density and
// probe, and the families of degenerate placements (grids, equal radii, duplicates,
// tangency, lattices, symmetric shells) that broke the engine before. The large
// structures run under the `long` label (test_long_surface_methods.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "atom_fixtures.hpp"
#include "degenerate_placements.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/error.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/surface.hpp"
#include "surface/atom_polyhedra.hpp"
#include "surface/solvent_accessible_surface.hpp"
#include "surface_methods.hpp"

namespace molsurf {
namespace {

const std::string kData = MOLSURF_DATA_DIR;

using testing::atom_at;

SphereOptions spheres(double probe, double density, int frequency = 0) {
  SphereOptions o;
  o.probe = probe;
  o.density = density;
  o.frequency = frequency;
  return o;
}

class SmallStructure : public ::testing::TestWithParam<std::tuple<std::string, double, double>> {};

TEST_P(SmallStructure, MethodsAgree) {
  const auto& [name, probe, density] = GetParam();
  const Structure s = read_structure(kData + "/pdb/" + name);
  EXPECT_TRUE(testing::methods_agree(s.atoms, spheres(probe, density)));
}

INSTANTIATE_TEST_SUITE_P(DataPdb, SmallStructure,
                         ::testing::Combine(::testing::Values("1crn.pdb"), ::testing::Values(0.0, 1.4),
                                            ::testing::Values(1.0, 2.0, 4.0)));

TEST(SurfaceMethods, ThreadCountChangesNoByte) {
  const Structure s = read_structure(kData + "/pdb/1crn.pdb");
  SphereUnionOptions o;
  o.threads = 1;
  const SphereUnion one = solvent_accessible_surface(s.atoms, o);
  o.threads = 2;
  const SphereUnion two = solvent_accessible_surface(s.atoms, o);
  ASSERT_EQ(one.method, SurfaceMethod::one_pass);
  EXPECT_EQ(one.mesh.faces, two.mesh.faces);
  EXPECT_EQ(one.mesh.face_tags, two.mesh.face_tags);
  ASSERT_EQ(one.mesh.vertices.size(), two.mesh.vertices.size());
  for (std::size_t v = 0; v < one.mesh.vertices.size(); ++v) ASSERT_EQ(one.mesh.vertices[v], two.mesh.vertices[v]);
}

// Two equal atoms on a 0.1 A grid in one plane: the pairwise union crashed on about one
// placement in 30 (NaN vertices from an unbounded filter box), and offsets along two axes
// make many faces of the two icospheres exactly or nearly coplanar.
TEST(SurfaceMethods, TwoEqualAtomsOnAGrid) {
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j) {
      const std::vector<Atom> atoms{atom_at({0, 0, 0}, 1.5), atom_at({0.1 * i, 0.1 * j, 0}, 1.5)};
      EXPECT_TRUE(testing::methods_agree(atoms, spheres(1.4, 2))) << "offset " << 0.1 * i << ", " << 0.1 * j;
    }
}

TEST(SurfaceMethods, TwoCarbonsOfTheCrashReport) {
  const std::vector<Atom> atoms{atom_at({-0.6, -0.5, 0.5}, 1.7), atom_at({-0.5, -0.6, 0.5}, 1.7)};
  EXPECT_TRUE(testing::methods_agree(atoms, spheres(1.4, 2)));
  const std::vector<Atom> close{atom_at({0, 0, 0}, 1.5), atom_at({1e-15, 0, 0}, 1.5)};
  EXPECT_TRUE(testing::methods_agree(close, spheres(1.4, 2)));
}

TEST(SurfaceMethods, DuplicatesCostNothingAndKeepTheFirst) {
  std::vector<Atom> atoms(200, atom_at({1, 2, 3}, 1.7));
  atoms.push_back(atom_at({3, 2, 3}, 1.7));
  SphereUnionOptions o;
  const SphereUnion r = solvent_accessible_surface(atoms, o);
  EXPECT_EQ(r.one_pass.contained_atoms, 199u);
  EXPECT_TRUE(testing::valid_surface(r.mesh));
  for (std::int32_t tag : r.mesh.face_tags) EXPECT_TRUE(tag == 0 || tag == 200) << tag;
  EXPECT_TRUE(testing::methods_agree(std::span(atoms).subspan(195), o.spheres));
}

// Spheres whose polyhedra touch or nearly touch: centres at the sum of the circumradii
// and a hair either side, along the axes and along a diagonal.
TEST(SurfaceMethods, TouchingSpheres) {
  const SphereOptions o = spheres(0, 2, 3);
  for (const Vec3 dir : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{1, 1, 0}})
    for (double scale : {1 - 1e-12, 1.0, 1 + 1e-12}) {
      const double d = 2 * 1.5 * scale / std::sqrt(dot(dir, dir));
      const std::vector<Atom> atoms{atom_at({0, 0, 0}, 1.5), atom_at(dir * d, 1.5)};
      EXPECT_TRUE(testing::methods_agree(atoms, o)) << dir.x << dir.y << dir.z << " " << scale;
    }
}

// Atoms on a cubic lattice: equal radii, spacing equal to the radius (many coplanar and
// coincident features) and to twice the radius (touching), at the coarsest spheres.
TEST(SurfaceMethods, Lattices) {
  for (double spacing : {1.5, 3.0, 2.0})
    for (int frequency : {1, 2}) {
      std::vector<Atom> atoms;
      for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y)
          for (int z = 0; z < 2; ++z) atoms.push_back(atom_at(Vec3{double(x), double(y), double(z)} * spacing, 1.5));
      SphereUnionOptions o;
      o.spheres = spheres(0, 2, frequency);
      const SphereUnion r = solvent_accessible_surface(atoms, o);
      EXPECT_EQ(r.one_pass.open_edges, 0u);
      EXPECT_TRUE(testing::valid_surface(r.mesh)) << "spacing " << spacing << " n=" << frequency;
    }
}

// Six atoms placed symmetrically around a seventh: the symmetric shells of the crash
// report (every pair of neighbours related by a symmetry of the icosphere or of the grid).
TEST(SurfaceMethods, SymmetricShells) {
  for (double d : {1.0, 1.5, 2.9, 3.0})
    for (double r : {1.2, 1.5}) {
      std::vector<Atom> atoms{atom_at({0, 0, 0}, r)};
      for (int axis = 0; axis < 3; ++axis)
        for (double s : {-1.0, 1.0}) {
          Vec3 c{0, 0, 0};
          (axis == 0 ? c.x : axis == 1 ? c.y : c.z) = s * d;
          atoms.push_back(atom_at(c, r));
        }
      EXPECT_TRUE(testing::methods_agree(atoms, spheres(1.4, 2))) << "d " << d << " r " << r;
    }
}

// A neighbour moved along the direction of a block of faces towards the placement where
// its inscribed ball starts to hold that block's ball (the block is then dropped whole),
// and a hair either side of it.
TEST(SurfaceMethods, BlocksAtTheEdgeOfBeingBuried) {
  const SphereOptions o = spheres(1.4, 2);
  const std::vector<Atom> pair{atom_at({0, 0, 0}, 1.6), atom_at({0, 0, 0}, 1.8)};
  const surface_detail::AtomPolyhedra polyhedra(pair, o);
  const surface_detail::PolyhedronTemplate& shape = polyhedra.shape(0);
  for (const std::size_t b : {0, 7, 19}) {
    const Vec3 towards = shape.block_centre[b] * polyhedra.scale(0);
    const double radius = shape.block_radius[b] * polyhedra.scale(0) + 2 * polyhedra.vertex_error(0);
    // The neighbour's centre on the block's axis, its inscribed ball just holding the block's ball.
    const double buried_from = norm(towards) - (polyhedra.inradius(1) - radius);
    ASSERT_GT(buried_from, 0);
    for (const double d : {buried_from - 0.6 * radius, buried_from - 0.3 * radius, buried_from - 0.1 * radius,
                           buried_from - 1e-9, buried_from, buried_from + 1e-9, buried_from + 0.05}) {
      const std::vector<Atom> atoms{pair[0], atom_at(towards * (d / norm(towards)), 1.8)};
      EXPECT_TRUE(testing::methods_agree(atoms, o)) << "block " << b << " at " << d;
    }
  }
}

TEST(SurfaceMethods, NestedAtomsLeaveOnlyTheOuter) {
  const std::vector<Atom> atoms{atom_at({0, 0, 0}, 3.0), atom_at({0.2, 0.1, 0}, 1.0), atom_at({-0.5, 0, 0.3}, 0.5)};
  SphereUnionOptions o;
  const SphereUnion r = solvent_accessible_surface(atoms, o);
  for (std::int32_t tag : r.mesh.face_tags) EXPECT_EQ(tag, 0);
  EXPECT_TRUE(testing::methods_agree(atoms, o.spheres));
}

// Huge spheres whose centres are close compared with their radii (1crn with --probe 1e9
// at frequency 1 ran for hours): every face is crossed by hundreds of neighbour faces.
// The one-pass union refuses them with one clear error, quickly, instead of a hang.
TEST(SurfaceMethods, NearlyCoincidentHugeSpheresAreRefusedPlainly) {
  std::vector<Atom> atoms;
  for (int k = 0; k < 160; ++k)
    atoms.push_back(atom_at({std::fmod(0.37 * k, 3.0), std::fmod(0.61 * k, 2.0), std::fmod(0.13 * k, 1.5)}, 1.7));
  SphereUnionOptions o;
  o.spheres = spheres(1e9, 2, 1);
  try {
    solvent_accessible_surface(atoms, o);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("too complex"), std::string::npos) << e.what();
  }
  // The same placement with molecular radii is an ordinary surface.
  o.spheres = spheres(1.4, 2);
  EXPECT_TRUE(check_mesh(solvent_accessible_surface(atoms, o).mesh, {}).valid());
}

// Seeds of the long degenerate battery that once failed. Icosahedral shells at frequency 2,
// probe 0.7: faces of several atoms' polyhedra meet in one plane, and the one-pass
// surface's rounding repair collapsed a sliver into a real face folded flat over its
// neighbours (0.07 A^2 counted twice, no volume, valid to the exact test because rounding
// kept the sheets an ulp apart); the pairwise surface had none. Icosahedral shells and a
// lattice at frequency 1, probe 0.7: three rounded points within 5e-16 of one point of
// the input that the pairwise merges could not join (two crossing pairs).
TEST(SurfaceMethods, DegenerateSeedsThatOnceFailed) {
  struct Case {
    testing::PlacementFamily family;
    std::uint32_t seed;
    int frequency;
  };
  const Case cases[] = {{testing::PlacementFamily::icosahedral_shell, 1021, 2},
                        {testing::PlacementFamily::icosahedral_shell, 1030, 2},
                        {testing::PlacementFamily::icosahedral_shell, 1048, 2},
                        {testing::PlacementFamily::icosahedral_shell, 1086, 2},
                        {testing::PlacementFamily::icosahedral_shell, 1091, 2},
                        {testing::PlacementFamily::icosahedral_shell, 1008, 1},
                        {testing::PlacementFamily::lattice, 1051, 1}};
  for (const Case& c : cases) {
    const testing::DegeneratePlacement p = testing::degenerate_placement(c.family, c.seed);
    EXPECT_TRUE(testing::methods_agree(p.atoms, spheres(0.7, 2, c.frequency), 1))
        << p.family << " seed " << c.seed << " frequency " << c.frequency;
  }
}

}  // namespace
}  // namespace molsurf
