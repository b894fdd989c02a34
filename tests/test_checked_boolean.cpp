// valid_boolean: the Boolean the front ends run (through checked_boolean). Its result passes molsurf's check and
// CGAL's; where no rounding of the exact result is valid (sheets touching, or closer than
// rounding keeps apart) b is moved by a step far below any feature, and only then.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cgal_check.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/compute_surface.hpp"
#include "mesh/icosphere.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"

namespace molsurf {
namespace {

enum class Axis { x, y, z };

double& coordinate(Vec3& v, Axis axis) { return axis == Axis::x ? v.x : axis == Axis::y ? v.y : v.z; }

// The mirror image of m in the plane {axis = centre}, outward again (each face reversed).
// 2 * centre - c rounds, as a user's script would, unless centre is 0.
Mesh mirrored(const Mesh& m, Axis axis, double centre) {
  Mesh out = m;
  for (Vec3& v : out.vertices) coordinate(v, axis) = 2 * centre - coordinate(v, axis);
  for (Triangle& t : out.faces) std::swap(t[1], t[2]);
  return out;
}

double mean(const Mesh& m, Axis axis) {
  double sum = 0;
  for (Vec3 v : m.vertices) sum += coordinate(v, axis);
  return sum / static_cast<double>(m.vertices.size());
}

Mesh crambin_surface(double density) {
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  ComputeSurfaceOptions o;
  o.spheres.density = density;
  o.exact_areas = false;
  return compute_surface(s.atoms, o).mesh;
}

// Every operation, both ways: valid by both checks, b moved only when the plain result
// failed, and then by the first step; the volume within what the move can change.
int expect_checked(const Mesh& a, const Mesh& b, const std::string& what) {
  int moved = 0;
  for (const auto& [first, second, order] : {std::tuple{&a, &b, "A, B"}, std::tuple{&b, &a, "B, A"}})
    for (const BooleanOp op : {BooleanOp::union_, BooleanOp::intersection, BooleanOp::difference}) {
      const std::string name = what + " " + boolean_op_name(op) + " of " + order;
      const BooleanResult plain = boolean(*first, *second, op);
      const MeshCheck plain_check = check_mesh(plain.mesh);
      const CheckedBoolean r = valid_boolean(*first, *second, op);
      EXPECT_TRUE(r.check.valid()) << name << ": " << (r.check.defects().empty() ? "" : r.check.defects().front());
      EXPECT_EQ(testing::cgal_defects(r.result.mesh), "") << name;
      const double shift = norm(r.result.stats.b_moved_by);
      if (plain_check.valid()) {
        EXPECT_EQ(shift, 0) << name;
        EXPECT_TRUE(r.result.mesh.vertices == plain.mesh.vertices && r.result.mesh.faces == plain.mesh.faces) << name;
        continue;
      }
      EXPECT_GT(shift, 0) << name;
      ++moved;
      EXPECT_LE(shift, 64 * std::ldexp(1.0, -36) * 1.0001) << name;  // the first step, coordinates under 64
      EXPECT_NE(boolean_note(r.result.stats).find("moved by"), std::string::npos) << name;
      // The sliver wedges have no volume; moving b changes the volume by its area times the step.
      EXPECT_NEAR(r.check.volume, plain_check.volume, 1e-6 * std::fabs(plain_check.volume) + 1e-6) << name;
    }
  return moved;
}

// The case: 1crn at density 0.4 minus its mirror image about its mean x. Faces
// nearly perpendicular to the mirror plane meet their images at dihedral angles of 1e-15:
// the exact difference holds wedges thinner than rounding, which no rounding keeps valid.
TEST(CheckedBoolean, CrambinMinusItsMirrorImage) {
  const Mesh a = crambin_surface(0.4);
  int moved = 0;
  for (const Axis axis : {Axis::x, Axis::y, Axis::z})
    moved += expect_checked(a, mirrored(a, axis, mean(a, axis)), "1crn mirrored about its mean");
  EXPECT_GT(moved, 0);  // the family is still hard for the plain Boolean
  // Mirrored exactly (x -> -x): A and B share the plane x = 0 exactly.
  expect_checked(a, mirrored(a, Axis::x, 0), "1crn mirrored about x = 0");
}

TEST(CheckedBoolean, CrambinMirrorsAtOtherDensities) {
  const Mesh a = crambin_surface(1.0);
  expect_checked(a, mirrored(a, Axis::x, mean(a, Axis::x)), "1crn (density 1) mirrored about its mean x");
  expect_checked(a, mirrored(a, Axis::z, 0), "1crn (density 1) mirrored about z = 0");
}

// A chiral solid that is not a molecule: an ellipsoid-like polyhedron, sheared, and its
// mirror image about a plane through its middle, exactly and rounded.
TEST(CheckedBoolean, ChiralSolidAndItsMirrorImage) {
  Mesh a = make_icosphere({0, 0, 0}, 1.0, {.frequency = 4});
  for (Vec3& v : a.vertices) v = Vec3{3 * v.x + 0.7 * v.y + 0.2 * v.z + 0.3, 1.5 * v.y + 0.4 * v.z, v.z + 0.1 * v.x};
  ASSERT_TRUE(check_mesh(a).valid());
  int moved = 0;
  for (const Axis axis : {Axis::x, Axis::y, Axis::z}) {
    moved += expect_checked(a, mirrored(a, axis, 0), "chiral solid mirrored exactly");
    moved += expect_checked(a, mirrored(a, axis, mean(a, axis) + 0.1), "chiral solid mirrored, rounded");
  }
  EXPECT_GT(moved, 0);
}

// A valid result is returned as boolean() gives it, with its check.
TEST(CheckedBoolean, ValidResultsAreUnchanged) {
  const Mesh a = make_icosphere({0, 0, 0}, 1.0, {.frequency = 3});
  const Mesh b = make_icosphere({0.7, 0.2, 0.1}, 0.8, {.frequency = 3});
  const BooleanResult plain = boolean(a, b, BooleanOp::union_);
  const CheckedBoolean r = valid_boolean(a, b, BooleanOp::union_);
  EXPECT_TRUE(r.result.mesh.vertices == plain.mesh.vertices && r.result.mesh.faces == plain.mesh.faces);
  EXPECT_TRUE(r.check.valid());
  EXPECT_EQ(r.check.faces, plain.mesh.faces.size());
  EXPECT_EQ(norm(r.result.stats.b_moved_by), 0);
  EXPECT_TRUE(boolean_note(r.result.stats).empty());
}

}  // namespace
}  // namespace molsurf
