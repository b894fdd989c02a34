#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "mesh/icosphere.hpp"
#include "mesh_fixtures.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/mesh_check.hpp"
#include "support/shapes.hpp"

using molsurf::check_mesh;
using molsurf::Mesh;
using molsurf::MeshCheck;
using molsurf::Vec3;

namespace {

// Outward tetrahedron on the corner `o`, edge length `s`.
Mesh tetrahedron(const Vec3& o = {0, 0, 0}, double s = 1) {
  Mesh m;
  m.vertices = {o, o + Vec3{s, 0, 0}, o + Vec3{0, s, 0}, o + Vec3{0, 0, s}};
  m.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

// Outward axis-aligned cube [lo, lo + s]^3: vertex index = x + 2y + 4z, two triangles per side.
Mesh cube(const Vec3& lo = {0, 0, 0}, double s = 1) {
  Mesh m;
  for (int k = 0; k < 8; ++k) m.vertices.push_back(lo + s * Vec3{double(k & 1), double((k >> 1) & 1), double(k >> 2)});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.faces.push_back({molsurf::Index(q[0]), molsurf::Index(q[1]), molsurf::Index(q[2])});
    m.faces.push_back({molsurf::Index(q[0]), molsurf::Index(q[2]), molsurf::Index(q[3])});
  }
  return m;
}

Mesh flipped(Mesh m) {
  for (auto& f : m.faces) std::swap(f[1], f[2]);
  return m;
}

Mesh joined(const Mesh& a, const Mesh& b) {
  Mesh m = a;
  const auto offset = static_cast<molsurf::Index>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto f : b.faces) m.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  return m;
}

bool mentions(const MeshCheck& c, const std::string& word) {
  const auto lines = c.defects();
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(word) != std::string::npos; });
}

// The invariant every result must keep: valid exactly when no defect line is printed.
void expect_consistent(const MeshCheck& c) { EXPECT_EQ(c.valid(), c.defects().empty()); }

}  // namespace

TEST(MeshCheck, ValidClosedMeshes) {
  for (const Mesh& m : {tetrahedron(), cube(), cube({-3, 2, 7.5}, 0.1)}) {
    const MeshCheck c = check_mesh(m);
    EXPECT_TRUE(c.valid());
    EXPECT_TRUE(c.closed() && c.manifold() && c.oriented());
    EXPECT_EQ(c.edges, m.faces.size() * 3 / 2);
    EXPECT_EQ(c.euler_characteristic, 2);
    EXPECT_EQ(c.components, 1u);
    EXPECT_EQ(c.intersecting_pairs + c.contact_pairs + c.degenerate_faces + c.duplicate_faces, 0u);
    EXPECT_TRUE(c.self_intersections_checked);
    EXPECT_GT(c.volume, 0);
    expect_consistent(c);
  }
  EXPECT_NEAR(check_mesh(cube()).volume, 1.0, 1e-12);
}

// An empty mesh has no defect (a Boolean may be empty: the engine's checks accept it), but
// it is no surface: the verdict says `empty`, and `molsurf check` fails it.
TEST(MeshCheck, EmptyMeshHasNoDefectButIsNoSurface) {
  const MeshCheck c = check_mesh(Mesh{});
  EXPECT_TRUE(c.valid());
  EXPECT_TRUE(c.defects().empty());
  EXPECT_TRUE(c.empty());
  EXPECT_EQ(c.verdict(), MeshCheck::Verdict::empty);
  EXPECT_EQ(check_mesh(cube()).verdict(), MeshCheck::Verdict::valid);
  EXPECT_EQ(check_mesh(flipped(cube())).verdict(), MeshCheck::Verdict::invalid);
}

// Scaled to 1e300 the area and volume overflow: a surface that cannot be measured is
// not valid (it was, with NaN measures).
TEST(MeshCheck, NonFiniteMeasuresAreInvalid) {
  Mesh m = molsurf::make_icosphere({0, 0, 0}, 1.0, {.frequency = 2});
  for (Vec3& p : m.vertices) p = 1e300 * p;
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.non_finite_measures);
  EXPECT_FALSE(c.valid());
  EXPECT_EQ(c.verdict(), MeshCheck::Verdict::invalid);
  EXPECT_TRUE(mentions(c, "not finite"));
  expect_consistent(c);
}

// A NaN or infinite coordinate (a library caller's mesh; readers refuse them) is a
// defect, and no exact predicate is asked about it.
TEST(MeshCheck, NonFiniteCoordinatesAreInvalidWithoutGeometry) {
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Mesh m = cube();
    m.vertices[3].y = bad;
    const MeshCheck c = check_mesh(m);
    EXPECT_EQ(c.non_finite_vertices, 1u);
    EXPECT_FALSE(c.valid());
    EXPECT_FALSE(c.self_intersections_checked);
    EXPECT_TRUE(c.closed());
    EXPECT_TRUE(mentions(c, "non-finite coordinate"));
    expect_consistent(c);
  }
}

// `molsurf check` on the files of issue 12, item 7: none is called valid.
TEST(MeshCheckCli, BrokenFilesAreNotValid) {
  const molsurf::testing::TempDir dir;
  const auto put = [&](const char* name, const std::string& text) {
    std::ofstream(dir.path() / name, std::ios::binary) << text;
  };
  put("truncated.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n");  // cut before the faces
  std::string stl = std::string(80, ' ') + std::string(4, '\0');       // count 0, then a facet
  stl += std::string(50, '\1');
  put("zero.stl", stl);
  put("empty.vert", "");
  put("empty.face", "");
  Mesh huge = molsurf::make_icosphere({0, 0, 0}, 1.0, {.frequency = 1});
  for (Vec3& p : huge.vertices) p = 1e300 * p;
  molsurf::write_mesh(dir.path() / "huge.off", huge);
  for (const char* name : {"truncated.obj", "zero.stl", "empty.vert", "huge.off"}) {
    const auto r = molsurf::testing::run_molsurf(std::string("check ") + name, dir.path());
    EXPECT_NE(r.exit_code, 0) << name << "\n" << r.out << r.err;
    EXPECT_EQ(r.out.find("\nVALID:"), std::string::npos) << name << "\n" << r.out;
  }
  const auto empty = molsurf::testing::run_molsurf("check truncated.obj", dir.path());
  EXPECT_NE(empty.out.find("EMPTY: no faces"), std::string::npos) << empty.out;
  const auto json = molsurf::testing::run_molsurf("check --json truncated.obj", dir.path());
  EXPECT_NE(json.out.find("\"valid\": false"), std::string::npos) << json.out;
}

TEST(MeshCheck, HoleIsBoundary) {
  Mesh m = cube();
  m.faces.erase(m.faces.begin() + 5);
  const MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.boundary_edges, 3u);
  EXPECT_FALSE(c.closed());
  EXPECT_FALSE(c.valid());
  EXPECT_TRUE(mentions(c, "boundary edges"));
  EXPECT_TRUE(std::is_sorted(c.examples_boundary.begin(), c.examples_boundary.end()));
  EXPECT_FALSE(c.examples_boundary.empty());
  expect_consistent(c);
}

TEST(MeshCheck, FlippedFaceIsMisoriented) {
  Mesh m = cube();
  std::swap(m.faces[3][1], m.faces[3][2]);
  const MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.misoriented_edges, 3u);
  EXPECT_TRUE(c.closed());
  EXPECT_FALSE(c.oriented());
  EXPECT_FALSE(c.valid());
  EXPECT_TRUE(std::find(c.examples_misoriented.begin(), c.examples_misoriented.end(), 3u) != c.examples_misoriented.end());
  EXPECT_TRUE(mentions(c, "misoriented"));
  expect_consistent(c);
}

TEST(MeshCheck, ThreeFacesOnAnEdgeIsNonManifold) {
  Mesh m = tetrahedron();
  m.vertices.push_back({0.5, -1, -1});
  m.faces.push_back({0, 1, 4});  // a fin on edge (0,1)
  const MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.nonmanifold_edges, 1u);
  EXPECT_EQ(c.boundary_edges, 2u);
  EXPECT_FALSE(c.manifold());
  EXPECT_FALSE(c.valid());
  EXPECT_TRUE(mentions(c, "non-manifold edge"));
  expect_consistent(c);
}

TEST(MeshCheck, TwoTetrahedraSharingOneVertexIndex) {
  Mesh m = tetrahedron();
  // A second tetrahedron hanging from vertex 3 = (0,0,1), mirrored above it.
  m.vertices.push_back({1, 0, 2});
  m.vertices.push_back({0, 1, 2});
  m.vertices.push_back({0, 0, 2});
  // Corners 3,4,5,6, outward.
  m.faces.push_back({3, 5, 4});
  m.faces.push_back({3, 4, 6});
  m.faces.push_back({3, 6, 5});
  m.faces.push_back({4, 5, 6});
  const MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.nonmanifold_vertices, 1u);
  EXPECT_EQ(c.examples_nonmanifold_vertex, std::vector<std::size_t>{3});
  EXPECT_TRUE(c.closed());
  EXPECT_TRUE(c.oriented());
  EXPECT_EQ(c.intersecting_pairs, 0u);
  EXPECT_GT(c.volume, 0);
  EXPECT_FALSE(c.valid());
  EXPECT_TRUE(mentions(c, "non-manifold vertices") || mentions(c, "non-manifold vertex"));
  expect_consistent(c);
}

TEST(MeshCheck, InterpenetratingCubesIntersect) {
  const MeshCheck c = check_mesh(joined(cube(), cube({0.5, 0.25, 0.3})));
  EXPECT_GT(c.intersecting_pairs, 0u);
  EXPECT_EQ(c.components, 2u);
  EXPECT_TRUE(c.closed() && c.manifold() && c.oriented());
  EXPECT_FALSE(c.valid());
  EXPECT_TRUE(mentions(c, "intersecting"));
  EXPECT_TRUE(std::is_sorted(c.examples_intersecting.begin(), c.examples_intersecting.end()));
  // Deterministic across runs (parallel loop).
  const MeshCheck again = check_mesh(joined(cube(), cube({0.5, 0.25, 0.3})));
  EXPECT_EQ(again.intersecting_pairs, c.intersecting_pairs);
  EXPECT_EQ(again.examples_intersecting, c.examples_intersecting);
  expect_consistent(c);
}

TEST(MeshCheck, InterpenetratingTetrahedraIntersect) {
  const MeshCheck c = check_mesh(joined(tetrahedron(), tetrahedron({0.2, 0.2, 0.2})));
  EXPECT_GT(c.intersecting_pairs, 0u);
  EXPECT_FALSE(c.valid());
}

TEST(MeshCheck, TetrahedraTouchingAtADuplicatedPointAreContacts) {
  // The second tetrahedron's corner (0,0,0) coincides with the first's, at another index.
  Mesh second = tetrahedron();
  for (auto& v : second.vertices) v = -1.0 * v;
  second = flipped(second);  // mirroring through the origin turned it inside out
  const MeshCheck c = check_mesh(joined(tetrahedron(), second));
  EXPECT_GT(c.contact_pairs, 0u);
  EXPECT_EQ(c.intersecting_pairs, 0u);
  EXPECT_EQ(c.components, 2u);
  EXPECT_EQ(c.inward_components, 0u);
  EXPECT_FALSE(c.valid());  // shells touching: a defect, as an exact self-intersection test says
  expect_consistent(c);
}

TEST(MeshCheck, CubesTouchingFaceToFaceAreContacts) {
  const MeshCheck c = check_mesh(joined(cube(), cube({1, 0, 0})));
  EXPECT_GT(c.contact_pairs, 0u);
  EXPECT_EQ(c.intersecting_pairs, 0u);
  EXPECT_FALSE(c.valid());
  // Offset by half a side along y: partial face overlap, still only touching.
  const MeshCheck shifted = check_mesh(joined(cube(), cube({1, 0.5, 0.25})));
  EXPECT_GT(shifted.contact_pairs, 0u);
  EXPECT_EQ(shifted.intersecting_pairs, 0u);
  EXPECT_FALSE(shifted.valid());
  // A hair apart: no contact, valid.
  EXPECT_TRUE(check_mesh(joined(cube(), cube({1 + 1e-12, 0, 0}))).valid());
}

TEST(MeshCheck, CoincidentCopyIntersects) {
  // The same cube twice with separate vertices: every face overlaps its copy, same facing.
  const MeshCheck c = check_mesh(joined(cube(), cube()));
  EXPECT_GE(c.intersecting_pairs, 12u);
  EXPECT_FALSE(c.valid());
}

TEST(MeshCheck, InsideOutIsInward) {
  const MeshCheck c = check_mesh(flipped(cube()));
  EXPECT_EQ(c.inward_components, 1u);
  EXPECT_TRUE(c.closed() && c.manifold() && c.oriented());
  EXPECT_LT(c.volume, 0);
  EXPECT_FALSE(c.valid());
  EXPECT_TRUE(mentions(c, "inward"));
  expect_consistent(c);
}

TEST(MeshCheck, CavityIsValid) {
  const MeshCheck c = check_mesh(joined(cube({-2, -2, -2}, 5), flipped(cube())));
  EXPECT_EQ(c.components, 2u);
  EXPECT_EQ(c.inward_components, 0u);
  EXPECT_NEAR(c.volume, 124.0, 1e-9);
  EXPECT_TRUE(c.valid());
  expect_consistent(c);
}

// The nesting ray starts at a vertex of the cavity; this cavity's first vertex lies on
// the outer wall (a contact), which says nothing about inside or outside, so another of
// its vertices decides. The contact itself is a defect.
TEST(MeshCheck, CavityTouchingTheWallAtAVertexIsNestedRightAndAContact) {
  Mesh cavity;
  cavity.vertices = {{-2, 0, 0}, {-1, 1, 0}, {-1, 0, 1}, {-1, -1, -1}};
  cavity.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  if (signed_volume(cavity) > 0) cavity = flipped(cavity);
  const MeshCheck c = check_mesh(joined(cube({-2, -2, -2}, 5), cavity));
  EXPECT_EQ(c.components, 2u);
  EXPECT_EQ(c.inward_components, 0u);
  EXPECT_GT(c.contact_pairs, 0u);
  EXPECT_FALSE(c.valid());
  // Turned outward, the same shell is an inward component.
  EXPECT_EQ(check_mesh(joined(cube({-2, -2, -2}, 5), flipped(cavity))).inward_components, 1u);
}

// Far from the origin, a tiny cavity's volume summed about the origin is all rounding
// (terms of 1e9 for a volume of 1e-13): its sign must still come out right, exactly.
TEST(MeshCheck, TinyCavityFarFromTheOriginIsValid) {
  const Vec3 lo{1000.1, 1000.3, 999.7};
  const Mesh cavity = flipped(tetrahedron(lo + Vec3{0.31, 0.47, 0.53}, 1e-4));
  const MeshCheck c = check_mesh(joined(cube(lo, 1), cavity));
  EXPECT_EQ(c.components, 2u);
  EXPECT_EQ(c.inward_components, 0u);
  EXPECT_TRUE(c.valid());
  expect_consistent(c);
}

TEST(MeshCheck, TinyInsideOutShellFarFromTheOriginIsInward) {
  const Vec3 lo{1000.1, 1000.3, 999.7};
  const Mesh inside_out = flipped(tetrahedron(lo + Vec3{3.31, 0.47, 0.53}, 1e-4));  // outside the cube
  const MeshCheck c = check_mesh(joined(cube(lo, 1), inside_out));
  EXPECT_EQ(c.inward_components, 1u);
  EXPECT_FALSE(c.valid());
  expect_consistent(c);
}

TEST(MeshCheck, DegenerateFaces) {
  Mesh m = cube();
  m.faces.push_back({0, 0, 1});  // repeated index: left out of the topology
  MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.degenerate_faces, 1u);
  EXPECT_EQ(c.examples_degenerate, std::vector<std::size_t>{12});
  EXPECT_TRUE(c.closed());
  EXPECT_FALSE(c.valid());
  EXPECT_TRUE(mentions(c, "degenerate"));
  expect_consistent(c);

  // Collinear corners: a tetrahedron squashed so that one face is a line segment.
  Mesh flat = tetrahedron();
  flat.vertices[3] = {0.5, 0.5, 0};
  c = check_mesh(flat);
  EXPECT_GE(c.degenerate_faces, 1u);
  EXPECT_FALSE(c.valid());
}

TEST(MeshCheck, DuplicateFace) {
  Mesh m = tetrahedron();
  m.faces.push_back(m.faces[2]);
  const MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.duplicate_faces, 1u);
  EXPECT_FALSE(c.valid());
  EXPECT_TRUE(mentions(c, "duplicate"));
}

// Every edge has two faces, so duplicates are counted from the edge table: a closed
// two-face "pillow" (the faces facing apart, or the same way), beside a valid solid.
TEST(MeshCheck, DuplicateFacesWhereEveryEdgeHasTwoFaces) {
  Mesh pillow;
  pillow.vertices = {{5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
  pillow.faces = {{0, 1, 2}, {0, 2, 1}};
  MeshCheck c = check_mesh(joined(tetrahedron(), pillow));
  EXPECT_EQ(c.boundary_edges + c.nonmanifold_edges + c.misoriented_edges, 0u);
  EXPECT_EQ(c.duplicate_faces, 1u);
  EXPECT_FALSE(c.valid());
  EXPECT_TRUE(mentions(c, "duplicate"));

  pillow.faces[1] = pillow.faces[0];
  c = check_mesh(joined(tetrahedron(), pillow));
  EXPECT_EQ(c.misoriented_edges, 3u);
  EXPECT_EQ(c.duplicate_faces, 1u);

  // Two faces sharing two corners only: no duplicate.
  c = check_mesh(joined(tetrahedron(), cube({3, 3, 3})));
  EXPECT_EQ(c.duplicate_faces, 0u);
}

// Two closed cones whose apexes are one vertex: two fans there, found with few faces around
// the vertex (paired directly) and with many (sorted).
TEST(MeshCheck, TwoConesSharingTheirApex) {
  for (const int sides : {3, 5, 8, 12}) {
    Mesh m;
    m.vertices.push_back({0, 0, 0});  // the shared apex
    for (const double h : {1.0, -1.0}) {
      const auto base = static_cast<molsurf::Index>(m.vertices.size());
      for (int k = 0; k < sides; ++k) {
        const double a = 2 * 3.14159265358979 * k / sides;
        m.vertices.push_back({std::cos(a), std::sin(a), h});
      }
      const auto centre = static_cast<molsurf::Index>(m.vertices.size());
      m.vertices.push_back({0, 0, h});
      for (int k = 0; k < sides; ++k) {
        const molsurf::Index p = base + k, q = base + (k + 1) % sides;
        // Outward: seen from outside, counter-clockwise (the lower cone mirrored).
        if (h > 0) {
          m.faces.push_back({0, q, p});
          m.faces.push_back({centre, p, q});
        } else {
          m.faces.push_back({0, p, q});
          m.faces.push_back({centre, q, p});
        }
      }
    }
    const MeshCheck c = check_mesh(m);
    SCOPED_TRACE(sides);
    EXPECT_TRUE(c.closed());
    EXPECT_TRUE(c.oriented());
    EXPECT_EQ(c.nonmanifold_vertices, 1u);
    EXPECT_EQ(c.examples_nonmanifold_vertex, std::vector<std::size_t>{0});
    EXPECT_FALSE(c.valid());
  }
}

TEST(MeshCheck, UnusedVerticesAndBadIndices) {
  Mesh m = tetrahedron();
  m.vertices.push_back({9, 9, 9});
  const MeshCheck c = check_mesh(m);
  EXPECT_EQ(c.unused_vertices, 1u);
  EXPECT_TRUE(c.valid());
  m.faces.push_back({0, 1, 99});
  EXPECT_THROW(check_mesh(m), molsurf::Error);
}

// The check takes V - E + F from its own edge table when every face has three distinct
// corners: the same number as euler_characteristic() on closed, open, non-manifold,
// several-component meshes and with unused vertices; with a repeated corner, the
// function's own count.
TEST(MeshCheck, EulerCharacteristicAsTheMeshFunction) {
  std::vector<Mesh> meshes;
  meshes.push_back(cube());
  Mesh two = tetrahedron();
  for (const Vec3& v : cube({5, 0, 0}).vertices) two.vertices.push_back(v);
  for (auto t : cube({5, 0, 0}).faces) two.faces.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  meshes.push_back(two);
  Mesh open = cube();
  open.faces.pop_back();
  meshes.push_back(open);
  Mesh unused = tetrahedron();
  unused.vertices.push_back({9, 9, 9});
  meshes.push_back(unused);
  Mesh fin = cube();
  fin.vertices.push_back({0.5, 0.5, -1});
  fin.faces.push_back({0, 1, 8});  // a third face on edge 0-1
  meshes.push_back(fin);
  Mesh repeated = cube();
  repeated.faces.push_back({0, 0, 7});
  meshes.push_back(repeated);
  meshes.push_back(molsurf::make_icosphere({0, 0, 0}, 1.0, {.frequency = 3}));
  for (std::size_t k = 0; k < meshes.size(); ++k)
    EXPECT_EQ(check_mesh(meshes[k]).euler_characteristic, molsurf::euler_characteristic(meshes[k])) << k;
  EXPECT_EQ(check_mesh(meshes[0]).euler_characteristic, 2);
  EXPECT_EQ(check_mesh(meshes[1]).euler_characteristic, 4);
  EXPECT_EQ(check_mesh(meshes[2]).euler_characteristic, 1);
}

TEST(MeshCheck, SelfIntersectionsCanBeSkipped) {
  molsurf::MeshCheckOptions options;
  options.self_intersections = false;
  const MeshCheck c = check_mesh(joined(cube(), cube({0.5, 0.25, 0.3})), options);
  EXPECT_FALSE(c.self_intersections_checked);
  EXPECT_EQ(c.intersecting_pairs, 0u);
}

TEST(MeshCheck, IcospheresAreValid) {
  for (int n = 1; n <= 8; ++n) {
    molsurf::IcosphereOptions options;
    options.frequency = n;
    const Mesh m = molsurf::make_icosphere({1.5, -2, 0.25}, 1.7, options);
    const MeshCheck c = check_mesh(m);
    EXPECT_TRUE(c.valid()) << "frequency " << n << ": " << (c.defects().empty() ? "" : c.defects()[0]);
    EXPECT_EQ(c.faces, std::size_t(20 * n * n));
    EXPECT_EQ(c.euler_characteristic, 2);
    EXPECT_EQ(c.contact_pairs, 0u);
  }
}

// Many overlapping icospheres: crossings must be found; separated ones must be clean.
TEST(MeshCheck, ManyIcospheres) {
  molsurf::IcosphereOptions options;
  options.frequency = 6;
  Mesh apart, overlapping;
  for (int i = 0; i < 60; ++i) {
    apart.append(molsurf::make_icosphere({3.0 * (i % 8), 3.0 * (i / 8), 0}, 1.0, options));
    overlapping.append(molsurf::make_icosphere({1.5 * (i % 8), 1.5 * (i / 8), 0}, 1.0, options));
  }
  const MeshCheck a = check_mesh(apart);
  EXPECT_TRUE(a.valid());
  EXPECT_EQ(a.components, 60u);
  const MeshCheck o = check_mesh(overlapping);
  EXPECT_GT(o.intersecting_pairs, 0u);
  EXPECT_FALSE(o.valid());
}

// Nesting is decided by exact ray parity, not by bounding boxes: a sphere in the duct of a
// channel lies inside the channel's box but outside the solid.
TEST(MeshCheckNesting, InsideOutSphereInAChannelsDuctIsInward) {
  Mesh m = molsurf::make_channel(4, 2, 10, 4, 2);
  Mesh sphere = molsurf::make_icosphere({0, 0, 5}, 0.5, {.frequency = 2});
  for (molsurf::Triangle& t : sphere.faces) std::swap(t[1], t[2]);
  m.append(sphere);
  const molsurf::MeshCheck c = molsurf::check_mesh(m);
  EXPECT_EQ(c.inward_components, 1u);
  EXPECT_FALSE(c.valid());
}

TEST(MeshCheckNesting, IslandInACavityFacesOutward) {
  Mesh m = molsurf::make_icosphere({0, 0, 0}, 3, {.frequency = 4});
  Mesh cavity = molsurf::make_icosphere({0, 0, 0}, 2, {.frequency = 4});
  for (molsurf::Triangle& t : cavity.faces) std::swap(t[1], t[2]);
  m.append(cavity);
  m.append(molsurf::make_icosphere({0.1, 0, 0}, 1, {.frequency = 3}));  // solid again
  molsurf::MeshCheck c = molsurf::check_mesh(m);
  EXPECT_TRUE(c.valid()) << ::testing::PrintToString(c.defects());
  EXPECT_EQ(c.components, 3u);
  // The same island facing inward is wrong.
  for (std::size_t f = m.faces.size() - 20 * 9; f < m.faces.size(); ++f) std::swap(m.faces[f][1], m.faces[f][2]);
  c = molsurf::check_mesh(m);
  EXPECT_EQ(c.inward_components, 1u);
}

// Twenty thousand components, each nested correctly or not: small solid cubes beside a
// block, small cavities in the block's wall (between it and a large cavity), and in that
// cavity an island holding small cavities of its own. Every component is placed by the
// boxes that hold its box (found through a tree of the components' boxes).
TEST(MeshCheckNesting, ManyComponentsEachPlacedByTheBoxesHoldingIt) {
  Mesh m = cube({0, 0, 0}, 100);
  m = joined(m, flipped(cube({20, 20, 20}, 60)));  // the large cavity
  m = joined(m, cube({40, 40, 40}, 20));           // the island in it
  std::size_t small = 0;
  auto add_row = [&](const Vec3& from, double step, int count, bool cavity) {
    Mesh row;
    for (int i = 0; i < count; ++i) {
      const Vec3 at = from + Vec3{step * (i % 40), step * ((i / 40) % 40), step * (i / 1600)};
      row.append(cavity ? flipped(cube(at, step / 2)) : cube(at, step / 2));
    }
    m.append(row);
    small += static_cast<std::size_t>(count);
  };
  add_row({110, 0, 0}, 1, 8000, false);      // solid cubes beside the block
  add_row({2, 2, 2}, 0.4, 6000, true);       // cavities in the block's wall (x, y, z < 18)
  add_row({41, 41, 41}, 0.4, 6000, true);    // cavities in the island
  molsurf::MeshCheckOptions options;
  options.self_intersections = false;
  MeshCheck c = check_mesh(m, options);
  EXPECT_EQ(c.components, 3 + small);
  EXPECT_EQ(c.inward_components, 0u);
  EXPECT_TRUE(c.valid()) << ::testing::PrintToString(c.defects());
  // One of each kind turned the wrong way round.
  for (const std::size_t first : {std::size_t{36}, std::size_t{36 + 12 * 8000}, std::size_t{36 + 12 * 14000}})
    for (std::size_t f = first; f < first + 12; ++f) std::swap(m.faces[f][1], m.faces[f][2]);
  c = check_mesh(m, options);
  EXPECT_EQ(c.inward_components, 3u);
}

namespace molsurf {
namespace {

// Copies of one tetrahedron at one place: every pair of copies overlaps in 4 face pairs and
// touches in 12, so the defects grow quadratically. Counting stops at max_defect_pairs
// (the verdict needs one), and the counts are then lower bounds, said so.
Mesh coincident_tetrahedra(int copies) {
  Mesh pile;
  const Mesh one = fixtures::tetrahedron();
  for (int k = 0; k < copies; ++k) {
    const auto base = static_cast<Index>(pile.vertices.size());
    pile.vertices.insert(pile.vertices.end(), one.vertices.begin(), one.vertices.end());
    for (const Triangle& t : one.faces) pile.faces.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  return pile;
}

TEST(MeshCheck, CountingDefectPairsStopsAtTheCap) {
  const Mesh fifty = coincident_tetrahedra(50);
  MeshCheckOptions all;
  all.max_defect_pairs = 0;
  const MeshCheck counted = check_mesh(fifty, all);
  EXPECT_EQ(counted.intersecting_pairs, 4u * 1225);
  EXPECT_EQ(counted.contact_pairs, 12u * 1225);
  EXPECT_FALSE(counted.defect_pairs_capped);
  for (const std::string& d : counted.defects()) EXPECT_EQ(d.find("at least"), std::string::npos) << d;

  MeshCheckOptions capped;
  capped.max_defect_pairs = 1000;
  const MeshCheck stopped = check_mesh(fifty, capped);
  EXPECT_TRUE(stopped.defect_pairs_capped);
  EXPECT_FALSE(stopped.valid());
  EXPECT_GE(stopped.intersecting_pairs + stopped.contact_pairs, 1000u);
  EXPECT_LT(stopped.intersecting_pairs + stopped.contact_pairs, 16u * 1225);
  bool said = false;
  for (const std::string& d : stopped.defects()) said |= d.rfind("at least ", 0) == 0;
  EXPECT_TRUE(said);

  // A thousand copies (8 M defect pairs if all were counted) under the default cap.
  const MeshCheck pile = check_mesh(coincident_tetrahedra(1000));
  EXPECT_TRUE(pile.defect_pairs_capped);
  EXPECT_EQ(pile.verdict(), MeshCheck::Verdict::invalid);
  EXPECT_LT(pile.intersecting_pairs + pile.contact_pairs, 2 * MeshCheckOptions{}.max_defect_pairs);
}

}  // namespace
// Examples: the lowest distinct face indices at fault, sorted, whatever the limit; every
// one of them when the limit is unbounded (the SES draws its ridges from them), the same
// set as the lowest ones of a smaller limit.
TEST(MeshCheck, ExamplesAreTheLowestFacesAtFaultUpToTheLimit) {
  const Mesh pile = coincident_tetrahedra(50);  // every face of every copy meets another
  MeshCheckOptions every;
  every.max_defect_pairs = 0;
  every.max_examples = std::numeric_limits<std::size_t>::max();
  const MeshCheck all = check_mesh(pile, every);
  std::vector<std::size_t> faces_at_fault(pile.faces.size());
  for (std::size_t f = 0; f < faces_at_fault.size(); ++f) faces_at_fault[f] = f;
  EXPECT_EQ(all.examples_intersecting, faces_at_fault);
  MeshCheckOptions few = every;
  few.max_examples = 7;
  const MeshCheck lowest = check_mesh(pile, few);
  EXPECT_EQ(lowest.examples_intersecting,
            std::vector<std::size_t>(faces_at_fault.begin(), faces_at_fault.begin() + 7));
}

}  // namespace molsurf
