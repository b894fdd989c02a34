// The mirror-image family on every structure in data/pdb that reads in a second (label
// `long`): each structure's surface at densities 0.4 and 1 against its mirror images about
// its mean x, y and z, every operation both ways. valid_boolean's result must pass
// molsurf's check, and CGAL's wherever b had to be moved.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cgal_check.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"

namespace molsurf {
namespace {

Mesh mirrored(const Mesh& m, int axis) {
  double sum = 0;
  for (const Vec3& v : m.vertices) sum += v[axis];
  const double centre = sum / static_cast<double>(m.vertices.size());
  Mesh out = m;
  for (Vec3& v : out.vertices) (axis == 0 ? v.x : axis == 1 ? v.y : v.z) = 2 * centre - v[axis];
  for (Triangle& t : out.faces) std::swap(t[1], t[2]);
  return out;
}

class MirrorImages : public ::testing::TestWithParam<std::string> {};

TEST_P(MirrorImages, EveryOperationIsValid) {
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/" + GetParam());
  for (const double density : {0.4, 1.0}) {
    ComputeSurfaceOptions o;
    o.spheres.density = density;
    o.exact_areas = false;
    const Mesh a = compute_surface(s.atoms, o).mesh;
    for (int axis = 0; axis < 3; ++axis) {
      const Mesh b = mirrored(a, axis);
      for (const auto& [first, second] : {std::pair{&a, &b}, std::pair{&b, &a}})
        for (const BooleanOp op : {BooleanOp::union_, BooleanOp::intersection, BooleanOp::difference}) {
          const std::string what = GetParam() + " density " + std::to_string(density) + " axis " +
                                   std::to_string(axis) + " " + boolean_op_name(op) +
                                   (first == &a ? " (A, B)" : " (B, A)");
          const CheckedBoolean r = valid_boolean(*first, *second, op);
          EXPECT_TRUE(r.check.valid()) << what;
          if (norm(r.result.stats.b_moved_by) > 0) {
            EXPECT_EQ(testing::cgal_defects(r.result.mesh), "") << what;
          }
        }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Structures, MirrorImages, ::testing::Values("1crn.pdb", "1ubq.pdb", "3pqr.cif", "1j8k.cif"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '.') c = '_';
                           return name;
                         });

}  // namespace
}  // namespace molsurf
