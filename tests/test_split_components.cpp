// One closed surface per file: the parts of a surface in the report's order, each closed
// and outward on its own, with its faces, tags and vertices in their original order, and
// named NAME.outer.EXT, NAME.outer-K.EXT, NAME.cavity-K.EXT.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesh/icosphere.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/split_components.hpp"
#include "molsurf/surface_report.hpp"

using namespace molsurf;

namespace {

// Appends `part` to `mesh`, turned inside out when `inward` (a cavity's faces point into it).
void append(Mesh& mesh, Mesh part, bool inward) {
  const Index offset = static_cast<Index>(mesh.vertex_count());
  for (std::size_t f = 0; f < part.face_count(); ++f) {
    Triangle t = part.faces[f];
    if (inward) std::swap(t[1], t[2]);
    for (Index& v : t) v += offset;
    mesh.faces.push_back(t);
    mesh.face_tags.push_back(part.face_tags[f]);
  }
  mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
}

// A molecule-like surface: a large outer sphere holding two cavities (the smaller listed
// first, to see the parts sorted by area), and a small outer sphere apart (an ion).
Mesh surface_with_cavities() {
  Mesh mesh;
  append(mesh, make_icosphere({0, 0, 0}, 10, {.frequency = 6, .tag = 0}), false);
  append(mesh, make_icosphere({3, 0, 0}, 1, {.frequency = 3, .tag = 1}), true);
  append(mesh, make_icosphere({-3, 1, 0}, 2, {.frequency = 3, .tag = 2}), true);
  append(mesh, make_icosphere({30, 0, 0}, 1.5, {.frequency = 2, .tag = 3}), false);
  return mesh;
}

}  // namespace

TEST(SplitComponents, PartsInTheReportsOrderEachClosedAndOutward) {
  const Mesh mesh = surface_with_cavities();
  ASSERT_TRUE(check_mesh(mesh).valid());
  const std::vector<SurfaceComponent> parts = split_components(mesh);
  const std::vector<ComponentMeasure> measures = measure_components(mesh);
  ASSERT_EQ(parts.size(), 4u);
  ASSERT_EQ(measures.size(), 4u);
  using Kind = SurfaceComponent::Kind;
  const Kind kinds[] = {Kind::outer, Kind::outer, Kind::cavity, Kind::cavity};
  const std::size_t numbers[] = {1, 2, 1, 2};
  const std::int32_t tags[] = {0, 3, 2, 1};  // big sphere, ion, larger cavity, smaller cavity
  double area = 0;
  std::size_t faces = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const SurfaceComponent& part = parts[i];
    EXPECT_EQ(part.kind, kinds[i]) << i;
    EXPECT_EQ(part.number, numbers[i]) << i;
    EXPECT_EQ(part.mesh.face_count(), measures[i].faces) << i;
    EXPECT_DOUBLE_EQ(part.area, measures[i].area) << i;
    EXPECT_NEAR(part.volume, std::abs(measures[i].volume), 1e-9 * std::abs(measures[i].volume)) << i;
    ASSERT_TRUE(std::all_of(part.mesh.face_tags.begin(), part.mesh.face_tags.end(),
                            [&](std::int32_t t) { return t == tags[i]; }))
        << i;
    // On its own: closed, 2-manifold, outward (a cavity turned), no defect at all.
    const MeshCheck check = check_mesh(part.mesh);
    EXPECT_TRUE(check.valid()) << i << ": " << (check.defects().empty() ? "" : check.defects()[0]);
    EXPECT_EQ(check.components, 1u);
    EXPECT_GT(signed_volume(part.mesh), 0) << i;
    EXPECT_NEAR(surface_area(part.mesh), part.area, 1e-9 * part.area);
    area += part.area;
    faces += part.mesh.face_count();
  }
  EXPECT_EQ(faces, mesh.face_count());
  EXPECT_NEAR(area, surface_area(mesh), 1e-9 * area);
}

// A part's vertices are the whole surface's in their order, its faces in theirs: the
// rows of a part follow the rows of the surface it came from.
TEST(SplitComponents, VerticesAndFacesKeepTheirOrder) {
  const Mesh mesh = surface_with_cavities();
  for (const SurfaceComponent& part : split_components(mesh)) {
    std::vector<std::size_t> from;  // the original vertex of each of the part's vertices
    for (const Vec3& p : part.mesh.vertices)
      from.push_back(static_cast<std::size_t>(std::find(mesh.vertices.begin(), mesh.vertices.end(), p) -
                                              mesh.vertices.begin()));
    EXPECT_TRUE(std::is_sorted(from.begin(), from.end()));
    // The first face of the part is the first face of the whole with its tag, corners
    // in the same cyclic order or turned for a cavity.
    const std::int32_t tag = part.mesh.face_tags.front();
    const std::size_t first = static_cast<std::size_t>(
        std::find(mesh.face_tags.begin(), mesh.face_tags.end(), tag) - mesh.face_tags.begin());
    Triangle expected = mesh.faces[first];
    if (part.kind == SurfaceComponent::Kind::cavity) std::swap(expected[1], expected[2]);
    const Triangle& t = part.mesh.faces.front();
    EXPECT_EQ((Triangle{static_cast<Index>(from[t[0]]), static_cast<Index>(from[t[1]]), static_cast<Index>(from[t[2]])}),
              expected);
  }
}

TEST(SplitComponents, OutputNames) {
  SurfaceComponent part;
  EXPECT_EQ(component_output_path("out/2hhb.vtp", part), "out/2hhb.outer.vtp");
  part.number = 2;
  EXPECT_EQ(component_output_path("2hhb.vtp", part), "2hhb.outer-2.vtp");
  part.kind = SurfaceComponent::Kind::cavity;
  part.number = 1;
  EXPECT_EQ(component_output_path("x.y.PLY", part), "x.y.cavity-1.PLY");
  part.number = 12;
  EXPECT_EQ(component_output_path("a/b.face", part), "a/b.cavity-12.face");
}

TEST(SplitComponents, EmptyMeshHasNoParts) { EXPECT_TRUE(split_components(Mesh{}).empty()); }
