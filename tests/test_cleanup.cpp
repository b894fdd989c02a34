#include <gtest/gtest.h>

#include <algorithm>

#include "molsurf/atoms.hpp"
#include "molsurf/cleanup.hpp"
#include "molsurf/icosphere.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/shapes.hpp"
#include "molsurf/surface.hpp"

namespace molsurf {
namespace {

TEST(Cleanup, LeavesAGoodMeshAlone) {
  Mesh sphere = make_icosphere({}, 2, {.frequency = 4, .tag = 0});
  const Mesh original = sphere;
  const CleanupStats s = improve_surface(sphere);
  EXPECT_EQ(s.collapses + s.flips, 0u);
  EXPECT_TRUE(sphere.faces == original.faces);
}

TEST(Cleanup, CollapsesANeedleAndStaysValid) {
  // A cube whose top face has a vertex 1e-6 from a corner: two needles.
  Mesh m = make_box({0, 0, 0}, {1, 1, 1});
  const Index extra = static_cast<Index>(m.vertices.size());
  m.vertices.push_back({1 - 1e-6, 1, 1});
  // Split every face on the edge (1,1,1)-(0,1,1) at the extra point.
  auto index_of = [&](const Vec3& p) {
    return static_cast<Index>(std::find(m.vertices.begin(), m.vertices.end(), p) - m.vertices.begin());
  };
  const Index a = index_of({1, 1, 1}), b = index_of({0, 1, 1});
  ASSERT_LT(b, extra);
  std::vector<Triangle> faces;
  for (Triangle t : m.faces) {
    int i = 0;
    for (; i < 3; ++i)
      if ((t[i] == a && t[(i + 1) % 3] == b) || (t[i] == b && t[(i + 1) % 3] == a)) break;
    if (i == 3) {
      faces.push_back(t);
      continue;
    }
    const Index u = t[i], v = t[(i + 1) % 3], w = t[(i + 2) % 3];
    faces.push_back({u, extra, w});
    faces.push_back({extra, v, w});
  }
  m.faces = faces;
  ASSERT_TRUE(check_mesh(m).valid());
  ASSERT_EQ(mesh_quality(m).below_1deg, 2u);
  const CleanupStats s = improve_surface(m);
  EXPECT_GE(s.collapses, 1u);
  EXPECT_EQ(mesh_quality(m).below_1deg, 0u);
  EXPECT_TRUE(check_mesh(m).valid());
  EXPECT_NEAR(signed_volume(m), 1, 1e-5);
}

TEST(Cleanup, CrambinSurfaceImprovesAndStaysValid) {
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  SurfaceResult r = solvent_accessible_surface(s.atoms, {});
  Mesh again = r.mesh;
  const CleanupStats stats = improve_surface(r.mesh);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  EXPECT_LT(stats.after.below_1deg * 10, stats.before.below_1deg);  // at least 90 % fewer
  EXPECT_LT(stats.after.below_5deg * 10, stats.before.below_5deg);
  EXPECT_LT(std::abs(stats.area_after - stats.area_before), 1e-3 * stats.area_before);
  improve_surface(again);  // deterministic
  EXPECT_TRUE(again.faces == r.mesh.faces);
  EXPECT_TRUE(again.vertices == r.mesh.vertices);
}

}  // namespace
}  // namespace molsurf
