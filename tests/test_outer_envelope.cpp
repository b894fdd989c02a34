// The outer envelope (paper §2.4 visibility flood fill): union_outer_envelope and
// `molsurf boolean union --outer-only`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <random>

#include "boolean_invariants.hpp"
#include "cli_runner.hpp"
#include "geometry/predicates.hpp"
#include "geometry/ray_parity.hpp"
#include "mesh/icosphere.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "random_pairs.hpp"
#include "support/shapes.hpp"

namespace molsurf {
namespace {

// A square patch [-half, half]^2 at height z, normal +z, n x n cells: an open surface.
Mesh square_patch(double half, double z, int n) {
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.vertices.push_back({-half + 2 * half * i / n, -half + 2 * half * j / n, z});
  auto at = [n](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// The faces of m whose components (through shared vertices) have positive volume: the
// union without its cavities (none of the closed tests has an island inside a cavity).
Mesh without_cavities(const Mesh& m) {
  const Components c = connected_components(m);
  std::vector<double> volume(c.count, 0);  // by the divergence theorem, per component
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const Triangle& t = m.faces[f];
    volume[c.face_component[f]] += dot(m.vertices[t[0]], cross(m.vertices[t[1]], m.vertices[t[2]])) / 6;
  }
  Mesh out;
  out.vertices = m.vertices;
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    if (volume[c.face_component[f]] > 0) out.faces.push_back(m.faces[f]);
  return out;
}

void expect_same_surface(const Mesh& got, const Mesh& want, const std::string& what) {
  EXPECT_EQ(got.face_count(), want.face_count()) << what;
  EXPECT_NEAR(surface_area(got), surface_area(want), 1e-12 * surface_area(want)) << what;
  EXPECT_NEAR(signed_volume(got), signed_volume(want), 1e-12 * std::fabs(signed_volume(want))) << what;
}

// For closed operands: the envelope is a valid closed surface (or one whose sheets only
// touch, where the solids do) equal to the union's outer part.
BooleanResult expect_union_outer_part(const Mesh& a, const Mesh& b, const std::string& what) {
  const BooleanResult e = union_outer_envelope(a, b);
  EXPECT_TRUE(testing::valid_or_only_touching(e.mesh)) << what;
  EXPECT_EQ(e.stats.two_sided_faces, 0u) << what;
  const BooleanResult u = boolean(a, b, BooleanOp::union_);
  expect_same_surface(e.mesh, without_cavities(u.mesh), what);
  return e;
}

TEST(OuterEnvelope, OverlappingCubesEqualTheUnion) {
  const Mesh a = make_box({0, 0, 0}, {2, 2, 2}, 3, 3, 3);
  const Mesh b = transformed(make_box({0, 0, 0}, {2, 2, 2}, 2, 2, 2), {{1, 2, 3}, 0.4, {1.1, 0.7, 0.9}});
  const BooleanResult e = expect_union_outer_part(a, b, "cubes");
  EXPECT_EQ(e.mesh.face_count(), boolean(a, b, BooleanOp::union_).mesh.face_count());
  EXPECT_EQ(e.stats.envelope_components, 1u);
  EXPECT_GT(e.stats.intersection_points, 0u);
}

TEST(OuterEnvelope, OverlappingSpheresEqualTheUnion) {
  const Mesh a = make_icosphere({0, 0, 0}, 1.0, {.frequency = 6, .tag = 1});
  const Mesh b = make_icosphere({0.9, 0.31, 0.17}, 0.8, {.frequency = 5, .tag = 2});
  const BooleanResult e = expect_union_outer_part(a, b, "spheres");
  ASSERT_EQ(e.mesh.face_tags.size(), e.mesh.face_count());
  for (std::size_t f = 0; f < e.mesh.face_count(); ++f) EXPECT_EQ(e.mesh.face_tags[f], e.face_operand[f] + 1);
}

TEST(OuterEnvelope, DegenerateContactsEqualTheUnion) {
  // Coplanar faces with the same orientation (sharing four sides), face to face
  // (opposite orientation), touching along an edge, and identical operands.
  const Mesh cube = make_box({0, 0, 0}, {1, 1, 1}, 2, 2, 2);
  expect_union_outer_part(cube, make_box({0.5, 0, 0}, {1.5, 1, 1}, 2, 2, 2), "coplanar same");
  expect_union_outer_part(cube, make_box({1, 0.25, 0.25}, {2, 0.75, 0.75}), "face to face");
  expect_union_outer_part(cube, make_box({1, 1, 0}, {2, 2, 1}), "touching along an edge");
  const BooleanResult same = expect_union_outer_part(cube, cube, "identical");
  EXPECT_EQ(same.mesh.face_count(), cube.face_count());
}

// Random pairs (half of them snapped to a grid: coplanar faces, shared vertices, edges
// through edges): the envelope is the union's outer part.
TEST(OuterEnvelope, RandomPairsEqualTheUnion) {
  const int seeds = std::getenv("MOLSURF_ENVELOPE_SEEDS") ? std::atoi(std::getenv("MOLSURF_ENVELOPE_SEEDS")) : 60;
  for (int seed = 0; seed < seeds; ++seed) {
    const auto pair = testing::random_pair(static_cast<std::uint64_t>(seed));
    const std::string what = "seed " + std::to_string(seed) + ": " + pair.description;
    try {
      expect_union_outer_part(pair.a, pair.b, what);
    } catch (const std::exception& e) {
      ADD_FAILURE() << what << " threw: " << e.what();
    }
  }
}

TEST(OuterEnvelope, DisjointAndNestedSolids) {
  const Mesh a = make_icosphere({0, 0, 0}, 1.0, {.frequency = 3});
  const Mesh far = make_icosphere({5, 0.5, 0}, 1.0, {.frequency = 3});
  const BooleanResult both = expect_union_outer_part(a, far, "disjoint");
  EXPECT_EQ(both.mesh.face_count(), a.face_count() + far.face_count());
  EXPECT_EQ(both.stats.envelope_components_kept, 2u);
  const Mesh inner = make_icosphere({0.1, 0.2, 0.05}, 0.5, {.frequency = 2});
  for (const auto& [x, y] : {std::pair{&a, &inner}, std::pair{&inner, &a}}) {
    const BooleanResult e = union_outer_envelope(*x, *y);
    expect_same_surface(e.mesh, a, "nested");
    EXPECT_EQ(e.stats.envelope_components, 2u);
    EXPECT_EQ(e.stats.envelope_components_kept, 1u);
  }
}

// A cup (a box with a square well open at the top) and a lid: the union encloses the
// well as a cavity, which the envelope drops.
TEST(OuterEnvelope, CavityMadeByTheUnionIsRemoved) {
  const Mesh box = make_box({0, 0, 0}, {4, 4, 4}, 2, 2, 2);
  const Mesh well = make_box({1, 1, 1}, {3, 3, 5.3}, 2, 2, 2);
  const Mesh cup = boolean(box, well, BooleanOp::difference).mesh;
  ASSERT_TRUE(testing::valid_surface(cup));
  const Mesh lid = make_box({-0.5, -0.5, 3.5}, {4.5, 4.5, 4.5}, 3, 3, 1);
  const BooleanResult u = boolean(cup, lid, BooleanOp::union_);
  ASSERT_TRUE(testing::valid_surface(u.mesh));
  ASSERT_EQ(connected_components(u.mesh).count, 2u);  // the outside and the cavity
  const BooleanResult e = expect_union_outer_part(cup, lid, "cup and lid");
  EXPECT_EQ(connected_components(e.mesh).count, 1u);
  EXPECT_LT(e.mesh.face_count(), u.mesh.face_count());
  // The cavity [1,3]^2 x [1,3.5] is filled.
  EXPECT_NEAR(signed_volume(e.mesh), signed_volume(u.mesh) + 2 * 2 * 2.5, 1e-12 * signed_volume(e.mesh));
}

// A hollow sphere (an operand with a cavity), a sphere overlapping its outside and an
// island floating in the cavity: only the outside remains.
TEST(OuterEnvelope, CavityOfAnOperandAndIslandInsideAreRemoved) {
  const Mesh big = make_icosphere({0, 0, 0}, 2.0, {.frequency = 5});
  const Mesh hole = make_icosphere({0.05, -0.02, 0.03}, 1.2, {.frequency = 4});
  const Mesh hollow = boolean(big, hole, BooleanOp::difference).mesh;
  ASSERT_EQ(connected_components(hollow).count, 2u);
  const Mesh bump = make_icosphere({2.1, 0.3, 0.2}, 0.7, {.frequency = 4});
  const BooleanResult e = expect_union_outer_part(hollow, bump, "hollow and bump");
  EXPECT_EQ(connected_components(e.mesh).count, 1u);
  const Mesh outside = boolean(big, bump, BooleanOp::union_).mesh;
  expect_same_surface(e.mesh, outside, "hollow and bump = big and bump");

  const Mesh island = make_icosphere({0.1, 0.15, -0.05}, 0.4, {.frequency = 2});
  Mesh hollow_with_island = hollow;
  hollow_with_island.append(island);
  const BooleanResult u = boolean(hollow_with_island, bump, BooleanOp::union_);
  EXPECT_EQ(connected_components(u.mesh).count, 3u);
  const BooleanResult f = union_outer_envelope(hollow_with_island, bump);
  EXPECT_TRUE(testing::valid_surface(f.mesh));
  EXPECT_EQ(f.stats.envelope_components, 3u);
  EXPECT_EQ(f.stats.envelope_components_kept, 1u);
  expect_same_surface(f.mesh, outside, "island in the cavity");
}

// Area of the cross-section of a closed outward mesh by the plane z = h (exact enough:
// the section polygon from each crossing face, oriented by the face's normal).
double section_area(const Mesh& m, double h) {
  double area = 0;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    std::vector<Vec3> hits;
    for (int i = 0; i < 3; ++i) {
      const Vec3 &p = m.vertices[m.faces[f][i]], &q = m.vertices[m.faces[f][(i + 1) % 3]];
      if ((p.z - h) * (q.z - h) < 0) hits.push_back(p + ((h - p.z) / (q.z - p.z)) * (q - p));
    }
    if (hits.size() != 2) continue;
    const Vec3 n = face_normal(m, f);
    const Vec3 along{-n.y, n.x, 0};  // z x n: counter-clockwise seen from +z
    Vec3 p = hits[0], q = hits[1];
    if (dot(q - p, along) < 0) std::swap(p, q);
    area += 0.5 * (p.x * q.y - p.y * q.x);
  }
  return area;
}

TEST(OuterEnvelope, PlaneThroughASphereIsAnOpenEnvelope) {
  const double h = 0.1234;
  const Mesh sphere = make_icosphere({0, 0, 0}, 1.0, {.frequency = 5});
  const int n = 12;
  const Mesh plane = square_patch(2.0, h, n);
  ASSERT_EQ(check_mesh(plane).boundary_edges, 4u * n);
  for (const auto& [x, y] : {std::pair{&sphere, &plane}, std::pair{&plane, &sphere}}) {
    const int sphere_operand = x == &sphere ? 0 : 1;
    const BooleanResult e = union_outer_envelope(*x, *y);
    const Mesh& m = e.mesh;
    const MeshCheck c = check_mesh(m);
    // Open along the patch's outer boundary only, with three faces on each edge of the
    // circle where the ring of the plane meets the sphere; nothing crosses.
    EXPECT_EQ(c.boundary_edges, 4u * n);
    for (std::size_t f : c.examples_boundary) {
      bool on_rim = false;
      for (Index v : m.faces[f]) on_rim |= std::fabs(m.vertices[v].x) == 2.0 || std::fabs(m.vertices[v].y) == 2.0;
      EXPECT_TRUE(on_rim);
    }
    EXPECT_GT(c.nonmanifold_edges, 0u);
    EXPECT_EQ(c.misoriented_edges, 0u);
    EXPECT_EQ(c.degenerate_faces, 0u);
    EXPECT_EQ(c.intersecting_pairs, 0u);

    double sphere_area = 0, plane_area = 0;
    std::size_t plane_faces = 0;
    const geometry::RayParity in_sphere(sphere);
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      const Triangle& t = m.faces[f];
      if (e.face_operand[f] == sphere_operand) {
        sphere_area += face_area(m, f);
        // Sphere faces keep their outward orientation.
        EXPECT_GT(dot(face_normal(m, f), face_normal(sphere, e.face_source[f])), 0.99);
      } else {
        plane_area += face_area(m, f);
        ++plane_faces;
        const Vec3 centroid = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
        EXPECT_FALSE(in_sphere.inside(centroid)) << "plane face " << f << " inside the sphere";
      }
    }
    // Both caps are seen; of the plane, all but the disc inside the sphere, from both sides.
    EXPECT_NEAR(sphere_area, surface_area(sphere), 1e-12 * surface_area(sphere));
    const double disc = section_area(sphere, h);
    EXPECT_GT(disc, 0.9 * M_PI * (1 - h * h));
    EXPECT_NEAR(plane_area, 16.0 - disc, 1e-12 * 16.0);
    EXPECT_EQ(e.stats.two_sided_faces, plane_faces);
    EXPECT_EQ(e.stats.envelope_components_kept, 1u);
  }
}

// Whether p lies on a face of m (exactly).
bool on_surface(const Mesh& m, const Vec3& p) {
  for (const Triangle& t : m.faces) {
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    if (geometry::orient3d(a, b, c, p) != 0) continue;
    // In the plane: inside the closed triangle in a projection where it does not vanish.
    int u = 0, v = 1;
    if (geometry::normal_sign_z(a, b, c) == 0) {
      u = geometry::normal_sign_x(a, b, c) != 0 ? 1 : 2;
      v = geometry::normal_sign_x(a, b, c) != 0 ? 2 : 0;
    }
    const int s0 = geometry::orient2d(a[u], a[v], b[u], b[v], p[u], p[v]);
    const int s1 = geometry::orient2d(b[u], b[v], c[u], c[v], p[u], p[v]);
    const int s2 = geometry::orient2d(c[u], c[v], a[u], a[v], p[u], p[v]);
    if ((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0)) return true;
  }
  return false;
}

// Random solids cut by a plane patch (for odd seeds snapped: the patch then often lies in
// a box's face or passes through vertices and edges): the result is sound and open along
// the patch's rim only, and it keeps every face of the solid that the patch does not cover.
TEST(OuterEnvelope, RandomSolidsCutByAPlane) {
  const int seeds = std::getenv("MOLSURF_ENVELOPE_SEEDS") ? std::atoi(std::getenv("MOLSURF_ENVELOPE_SEEDS")) : 40;
  for (int seed = 0; seed < seeds; ++seed) {
    const auto pair = testing::random_pair(static_cast<std::uint64_t>(seed));
    std::mt19937_64 rng(seed + 1000);
    const bool snapped = seed % 2 == 1;
    const int n = snapped ? 4 * (1 + static_cast<int>(rng() % 3)) : 1 + static_cast<int>(rng() % 9);
    // Through the middle part of the solid's height.
    const BoundingBox box = bounding_box(pair.a);
    const double mid = 0.5 * (box.min.z + box.max.z), extent = box.max.z - box.min.z;
    double h = mid + std::uniform_real_distribution<double>(-0.3, 0.3)(rng) * extent;
    if (snapped) h = std::round(4 * h) / 4;
    const Mesh plane = square_patch(6.0, h, n);  // beyond the solid
    const std::string what = "seed " + std::to_string(seed) + ": " + pair.description + " cut at z = " +
                             std::to_string(h) + ", " + std::to_string(n) + " cells";
    for (const bool plane_first : {false, true}) {
      try {
        const BooleanResult e = plane_first ? union_outer_envelope(plane, pair.a) : union_outer_envelope(pair.a, plane);
        const MeshCheck c = check_mesh(e.mesh, {.max_examples = 1000000});
        EXPECT_EQ(c.degenerate_faces + c.duplicate_faces + c.intersecting_pairs + c.misoriented_edges, 0u)
            << what << "\n" << ::testing::PrintToString(c.defects());
        EXPECT_EQ(c.boundary_edges, 4u * n) << what;
        for (std::size_t f : c.examples_boundary) {
          bool on_rim = false;
          for (Index v : e.mesh.faces[f])
            on_rim |= std::fabs(e.mesh.vertices[v].x) == 6.0 || std::fabs(e.mesh.vertices[v].y) == 6.0;
          EXPECT_TRUE(on_rim) << what << ": face " << f;
        }
        EXPECT_EQ(e.stats.envelope_components_kept, 1u) << what;
        EXPECT_GT(e.stats.two_sided_faces, 0u) << what;
        // Area: the solid is wholly seen except where the patch lies on it; the patch
        // less what lies inside or on the solid is seen (bounds both ways).
        double solid_area = 0, plane_area = 0;
        const int solid_operand = plane_first ? 1 : 0;
        for (std::size_t f = 0; f < e.mesh.face_count(); ++f)
          (e.face_operand[f] == solid_operand ? solid_area : plane_area) += face_area(e.mesh, f);
        EXPECT_LE(solid_area, surface_area(pair.a) * (1 + 1e-12)) << what;
        // The solid is convex: all of it is seen (where the patch lies on it, a's copy stays).
        if (!plane_first) EXPECT_NEAR(solid_area, surface_area(pair.a), 1e-12 * surface_area(pair.a)) << what;
        // No piece of the patch inside the solid.
        const geometry::RayParity in_solid(pair.a);
        for (std::size_t f = 0; f < e.mesh.face_count(); ++f) {
          if (e.face_operand[f] == solid_operand) continue;
          const Triangle& t = e.mesh.faces[f];
          const Vec3 centroid = (e.mesh.vertices[t[0]] + e.mesh.vertices[t[1]] + e.mesh.vertices[t[2]]) / 3.0;
          if (!on_surface(pair.a, centroid))  // else the patch lies in a face of the solid
            EXPECT_FALSE(in_solid.inside(centroid)) << what << ": patch face " << f;
        }
        EXPECT_LT(plane_area, 144.0) << what;
        EXPECT_NEAR(solid_area + plane_area, surface_area(e.mesh), 1e-9 * surface_area(e.mesh)) << what;
      } catch (const std::exception& ex) {
        ADD_FAILURE() << what << " threw: " << ex.what();
      }
    }
  }
}

TEST(OuterEnvelope, OpenPatchInsideOrBesideASolid) {
  const Mesh sphere = make_icosphere({0, 0, 0}, 1.0, {.frequency = 4});
  const Mesh inside = square_patch(0.3, 0.05, 3);
  const BooleanResult hidden = union_outer_envelope(sphere, inside);
  expect_same_surface(hidden.mesh, sphere, "patch inside");
  EXPECT_EQ(hidden.stats.envelope_components_kept, 1u);
  Mesh beside = square_patch(0.5, 0, 2);
  for (Vec3& v : beside.vertices) v.x += 3;
  const BooleanResult both = union_outer_envelope(beside, sphere);
  EXPECT_EQ(both.mesh.face_count(), sphere.face_count() + beside.face_count());
  EXPECT_EQ(both.stats.two_sided_faces, beside.face_count());
  // Only a patch: seen from both sides, kept as given.
  const BooleanResult alone = union_outer_envelope(beside, Mesh{});
  EXPECT_EQ(alone.mesh.face_count(), beside.face_count());
}

TEST(OuterEnvelope, Deterministic) {
  const Mesh sphere = make_icosphere({0, 0, 0}, 1.0, {.frequency = 4});
  const Mesh plane = square_patch(1.5, -0.31, 7);
  const BooleanResult x = union_outer_envelope(sphere, plane), y = union_outer_envelope(sphere, plane);
  ASSERT_EQ(x.mesh.faces, y.mesh.faces);
  ASSERT_EQ(x.mesh.vertices.size(), y.mesh.vertices.size());
  for (std::size_t v = 0; v < x.mesh.vertices.size(); ++v) EXPECT_EQ(x.mesh.vertices[v], y.mesh.vertices[v]);
}

TEST(OuterEnvelope, CommandLine) {
  testing::TempDir dir;
  write_mesh(dir.path() / "sphere.off", make_icosphere({0, 0, 0}, 1.0, {.frequency = 4}));
  write_mesh(dir.path() / "plane.off", square_patch(2.0, 0.2, 6));
  write_mesh(dir.path() / "cube.off", make_box({0.3, 0.2, 0.1}, {1.4, 1.3, 1.2}));
  auto r = testing::run_molsurf("boolean union sphere.off plane.off -o env.off --outer-only", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("outer envelope"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("open surface"), std::string::npos) << r.out;
  EXPECT_EQ(read_mesh(dir.path() / "env.off").face_count(),
            union_outer_envelope(read_mesh(dir.path() / "sphere.off"), read_mesh(dir.path() / "plane.off"))
                .mesh.face_count());
  // Without --outer-only an open operand is refused.
  r = testing::run_molsurf("boolean union sphere.off plane.off -o u.off", dir.path());
  EXPECT_NE(r.exit_code, 0);
  // Closed operands: a valid closed result.
  r = testing::run_molsurf("boolean union sphere.off cube.off -o c.off --outer-only", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("open surface"), std::string::npos) << r.out;
  // --outer-envelope is the same flag under its own name: the same file.
  r = testing::run_molsurf("boolean union sphere.off cube.off -o e.off --outer-envelope", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(read_mesh(dir.path() / "e.off").vertices, read_mesh(dir.path() / "c.off").vertices);
  EXPECT_EQ(read_mesh(dir.path() / "e.off").faces, read_mesh(dir.path() / "c.off").faces);
  // Only with union.
  r = testing::run_molsurf("boolean intersection sphere.off cube.off -o i.off --outer-only", dir.path());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--outer-only"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace molsurf
