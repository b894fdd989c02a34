#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "common/thread_count_scope.hpp"
#include "mesh/icosphere.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/surface.hpp"
#include "support/shapes.hpp"
#include "surface/cleanup.hpp"
#include "surface/solvent_accessible_surface.hpp"

namespace molsurf {
namespace {

// The faces on edge ab.
std::vector<std::size_t> faces_on(const Mesh& m, Index a, Index b) {
  std::vector<std::size_t> on;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const Triangle& t = m.faces[f];
    if (std::count(t.begin(), t.end(), a) && std::count(t.begin(), t.end(), b)) on.push_back(f);
  }
  return on;
}

// Adds a vertex at p and splits both faces on edge ab there (p on or near the edge).
Index split_edge(Mesh& m, Index a, Index b, const Vec3& p) {
  const Index x = static_cast<Index>(m.vertices.size());
  m.vertices.push_back(p);
  for (std::size_t f : faces_on(m, a, b)) {
    const Triangle t = m.faces[f];
    int i = 0;
    while (!((t[i] == a && t[(i + 1) % 3] == b) || (t[i] == b && t[(i + 1) % 3] == a))) ++i;
    const Index u = t[i], v = t[(i + 1) % 3], w = t[(i + 2) % 3];
    m.faces[f] = {u, x, w};
    m.faces.push_back({x, v, w});
    m.face_tags.push_back(m.face_tags[f]);
  }
  return x;
}

// Replaces face f by the faces `inner` (indices into f's corners 0..2, then new vertices
// 3.. at `points`), all with f's tag.
void refine_face(Mesh& m, std::size_t f, const std::vector<Vec3>& points, const std::vector<Triangle>& inner) {
  std::vector<Index> index(m.faces[f].begin(), m.faces[f].end());
  for (const Vec3& p : points) {
    index.push_back(static_cast<Index>(m.vertices.size()));
    m.vertices.push_back(p);
  }
  const std::int32_t tag = m.face_tags[f];
  for (std::size_t k = 0; k < inner.size(); ++k) {
    const Triangle t{index[inner[k][0]], index[inner[k][1]], index[inner[k][2]]};
    if (k == 0) {
      m.faces[f] = t;
    } else {
      m.faces.push_back(t);
      m.face_tags.push_back(tag);
    }
  }
}

Vec3 centroid(const Mesh& m, std::size_t f) {
  const Triangle& t = m.faces[f];
  return (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
}

// The face whose centroid points most along `direction`.
std::size_t face_toward(const Mesh& m, const Vec3& direction) {
  std::size_t best = 0;
  for (std::size_t f = 1; f < m.faces.size(); ++f)
    if (dot(centroid(m, f), direction) > dot(centroid(m, best), direction)) best = f;
  return best;
}

// The seam edge (its two faces of different tags) whose midpoint points most along `direction`.
std::pair<Index, Index> seam_edge_toward(const Mesh& m, const Vec3& direction) {
  std::pair<Index, Index> best{0, 0};
  double best_dot = -1e300;
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      const Index a = m.faces[f][i], b = m.faces[f][(i + 1) % 3];
      const std::vector<std::size_t> on = faces_on(m, a, b);
      if (on.size() != 2 || m.face_tags[on[0]] == m.face_tags[on[1]]) continue;
      const double d = dot(m.vertices[a] + m.vertices[b], direction);
      if (d > best_dot) {
        best_dot = d;
        best = {a, b};
      }
    }
  return best;
}

// A sphere whose two halves have different tags (a seam along the equator, as where two
// atoms' spheres meet), with typical slivers of a union: two needles across the seam, a
// cap on the seam, and a cluster of four vertices much closer to each other than to the
// rest, where no single edge collapse keeps the link condition. At a cluster size of
// 1e-8 every face of the cluster's neighbourhood is thinner than a thousandth of a degree,
// and stays so after any one collapse: only the merge judged as a whole improves it.
Mesh sphere_with_slivers(double cluster_size = 1e-4) {
  Mesh m = make_icosphere({}, 3, {.frequency = 8, .tag = 0});
  for (std::size_t f = 0; f < m.faces.size(); ++f) m.face_tags[f] = centroid(m, f).z > 0 ? 1 : 0;
  // Needles: the seam edge ab split 1e-4 of its length from a.
  const auto [a, b] = seam_edge_toward(m, {1, 0, 0});
  split_edge(m, a, b, m.vertices[a] + 1e-4 * (m.vertices[b] - m.vertices[a]));
  // Cap: a face on the seam split at a point 1e-3 off the middle of its seam edge.
  const auto [c, d] = seam_edge_toward(m, {-1, 0, 0});
  const std::size_t f = faces_on(m, c, d)[0];
  const Triangle t = m.faces[f];
  int i = 0;
  while (!(t[i] != c && t[i] != d)) ++i;
  const Vec3 middle = 0.5 * (m.vertices[t[(i + 1) % 3]] + m.vertices[t[(i + 2) % 3]]);
  refine_face(m, f, {middle + 1e-3 * (m.vertices[t[i]] - middle)},
              {Triangle{0, 1, 3}, Triangle{1, 2, 3}, Triangle{2, 0, 3}});
  // Cluster: a centre T (3) with A, B, C (4, 5, 6) 1e-4 away toward the face's corners.
  const std::size_t g = face_toward(m, {0, 0.3, 1});
  const Vec3 centre = centroid(m, g);
  std::vector<Vec3> points{centre};
  for (Index corner : m.faces[g])
    points.push_back(centre + cluster_size * normalized(m.vertices[corner] - centre));
  refine_face(m, g, points,
              {Triangle{3, 4, 5}, Triangle{3, 5, 6}, Triangle{3, 6, 4}, Triangle{0, 1, 5}, Triangle{0, 5, 4},
               Triangle{1, 2, 6}, Triangle{1, 6, 5}, Triangle{2, 0, 4}, Triangle{2, 4, 6}});
  return m;
}

TEST(Cleanup, LeavesAGoodMeshAlone) {
  Mesh sphere = make_icosphere({}, 2, {.frequency = 4, .tag = 0});
  const Mesh original = sphere;
  const CleanupStats s = improve_surface(sphere);
  EXPECT_EQ(s.collapses + s.flips + s.moves, 0u);
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

TEST(Cleanup, FixesNeedlesCapsAndClustersAcrossSeams) {
  Mesh m = sphere_with_slivers();
  ASSERT_TRUE(check_mesh(m).valid());
  const Quality before = mesh_quality(m);
  ASSERT_GE(before.below_1deg, 6u);  // 2 needles, 1 cap, 3 in the cluster
  const double area = surface_area(m), volume = signed_volume(m);
  Mesh again = m;
  const CleanupStats s = improve_surface(m);
  EXPECT_TRUE(check_mesh(m).valid());
  EXPECT_EQ(s.after.below_5deg, 0u);
  EXPECT_GE(s.after.min_angle_deg, 5);
  EXPECT_LT(std::abs(surface_area(m) - area), 1e-4 * area);
  EXPECT_LT(std::abs(signed_volume(m) - volume), 1e-4 * volume);
  // The seam is still there: both tags remain, on one face each at least.
  EXPECT_EQ(m.face_tags.size(), m.faces.size());
  EXPECT_TRUE(std::count(m.face_tags.begin(), m.face_tags.end(), 0) > 0 &&
              std::count(m.face_tags.begin(), m.face_tags.end(), 1) > 0);
  improve_surface(again);  // deterministic
  EXPECT_TRUE(again.faces == m.faces);
  EXPECT_TRUE(again.vertices == m.vertices);
  EXPECT_TRUE(again.face_tags == m.face_tags);
}

TEST(Cleanup, MergesAClusterTooSmallForAnySingleCollapse) {
  Mesh m = sphere_with_slivers(1e-8);
  ASSERT_TRUE(check_mesh(m).valid());
  ASSERT_LT(mesh_quality(m).min_angle_deg, 1e-3);
  const double volume = signed_volume(m);
  const CleanupStats s = improve_surface(m);
  EXPECT_TRUE(check_mesh(m).valid());
  EXPECT_EQ(s.after.below_1deg, 0u);
  EXPECT_GE(s.after.min_angle_deg, 5);
  EXPECT_LT(std::abs(signed_volume(m) - volume), 1e-4 * volume);
}

// A cube standing on a corner that pokes 1e-4 into a slab: their union has a neck whose
// cross-section is a triangle some 2e-4 across, with needles all around it. Each edge of
// that triangle has the third corner as a common neighbour of its ends, so no collapse
// keeps the link condition; the neck has to widen.
TEST(Cleanup, WidensANeckThatNoCollapseMayPinch) {
  const Mesh cube = make_box({-1, -1, -1}, {0, 0, 0}, 4, 4, 4);  // corner (0, 0, 0) toward (1, 1, 1)
  const double tilt = std::acos(1 / std::sqrt(3.0));  // (1, 1, 1) onto the z axis
  Mesh standing = transformed(cube, {.axis = {1, -1, 0}, .angle = tilt, .translation = {0, 0, 1e-4}});
  double top = -1e300;
  for (const Vec3& v : standing.vertices) top = std::max(top, v.z);
  if (top > 1e-3) standing = transformed(cube, {.axis = {1, -1, 0}, .angle = -tilt, .translation = {0, 0, 1e-4}});
  const Mesh slab = make_box({-2, -2, 0}, {2, 2, 1}, 8, 8, 2);
  Mesh m = boolean(standing, slab, BooleanOp::union_).mesh;
  ASSERT_TRUE(check_mesh(m).valid());
  ASSERT_GT(mesh_quality(m).below_1deg, 0u);
  const double area = surface_area(m), volume = signed_volume(m);
  const CleanupStats s = improve_surface(m);
  EXPECT_TRUE(check_mesh(m).valid());
  EXPECT_EQ(s.after.below_1deg, 0u);
  EXPECT_LT(std::abs(surface_area(m) - area), 1e-3 * area);
  EXPECT_LT(std::abs(signed_volume(m) - volume), 1e-3 * volume);
}

// A needle abx on the top of a box, with a steep spike w over its middle (w has three
// faces, on ab, bx and xa). Edge ab is the short one, but x is a common neighbour of a and
// b off the edge's two faces: no collapse of ab keeps the link condition. Every collapse
// of w, or into w, turns a face by more than 60 degrees, and the spike's creases allow no
// flip: w has to go first, its three faces becoming abx, and then ab can collapse, the
// two judged as one edit.
TEST(Cleanup, TakesAVertexOutOfTheWayOfACollapse) {
  Mesh m = make_box({0, 0, 0}, {8, 8, 8}, 32, 32, 32);
  m.face_tags.assign(m.faces.size(), 0);
  Index a = 0;
  while (!(m.vertices[a] == Vec3{4, 4, 8})) ++a;
  Index q = 0;
  while (!(m.vertices[q] == Vec3{4.25, 4, 8})) ++q;
  ASSERT_EQ(faces_on(m, a, q).size(), 2u);
  const Index b = split_edge(m, a, q, m.vertices[a] + 1e-3 * (m.vertices[q] - m.vertices[a]));
  const std::size_t needle = faces_on(m, a, b)[0];
  refine_face(m, needle, {centroid(m, needle) + Vec3{0, 0, 0.4}},
              {Triangle{0, 1, 3}, Triangle{1, 2, 3}, Triangle{2, 0, 3}});
  ASSERT_TRUE(check_mesh(m).valid());
  ASSERT_GT(mesh_quality(m).below_1deg, 0u);
  const CleanupStats s = improve_surface(m);
  EXPECT_TRUE(check_mesh(m).valid());
  EXPECT_EQ(s.after.below_1deg, 0u);
  EXPECT_EQ(s.after.below_5deg, 0u);
  // The spike is gone and the box is as it was.
  EXPECT_NEAR(surface_area(m), 6 * 64, 1e-9);
  EXPECT_NEAR(signed_volume(m), 512, 1e-9);
}

// A cavity of 14 faces and 6e-6 cubic angstrom from 4yvs's raw surface (density 2, probe
// 1.4), inside a box. Edit by edit, each face keeping its orientation within the turn the
// cleanup allows, it used to end as a tetrahedron turned inside out: a valid-looking
// component with positive volume where a cavity was. A component's volume keeps its sign
// (and at least half its size).
TEST(Cleanup, NeverTurnsASmallCavityInsideOut) {
  Mesh cavity = read_mesh(std::string(MOLSURF_DATA_DIR) + "/../tests/data/cleanup/4yvs_small_cavity.off");
  ASSERT_LT(signed_volume(cavity), 0);
  Mesh m = make_box({136.3, -64.5, -3.4}, {136.7, -63.8, -2.8}, 2, 2, 2);
  // The atoms the cavity's faces come from (renumbered in order).
  cavity.face_tags = {3, 3, 3, 3, 3, 1, 1, 1, 1, 4, 2, 2, 2, 2};
  m.face_tags.assign(m.faces.size(), 0);
  m.append(cavity);
  ASSERT_TRUE(check_mesh(m).valid());
  const double volume = signed_volume(m);
  improve_surface(m);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.valid()) << ::testing::PrintToString(c.defects());
  EXPECT_EQ(c.components, 2u);
  EXPECT_NEAR(signed_volume(m), volume, 3e-6);
}

TEST(Cleanup, FixesACapInAPlaneWithoutLeavingIt) {
  // A box with gridded sides; one vertex of the top side pushed almost onto the far edge
  // of one of its faces: a cap (angles near 0, 0, 180). Whatever fixes it (flip, move,
  // collapse) must stay in the plane: area and volume unchanged.
  Mesh m = make_box({0, 0, 0}, {1, 1, 1}, 4, 4, 4);
  Index v = 0;
  while (!(m.vertices[v] == Vec3{0.5, 0.5, 1})) ++v;
  std::size_t f = 0;
  while (std::count(m.faces[f].begin(), m.faces[f].end(), v) == 0) ++f;
  const Triangle t = m.faces[f];
  int i = 0;
  while (t[i] != v) ++i;
  const Vec3 middle = 0.5 * (m.vertices[t[(i + 1) % 3]] + m.vertices[t[(i + 2) % 3]]);
  m.vertices[v] = middle + 1e-3 * (m.vertices[v] - middle);
  ASSERT_TRUE(check_mesh(m).valid());
  ASSERT_EQ(mesh_quality(m).below_1deg, 1u);
  const CleanupStats s = improve_surface(m);
  EXPECT_GE(s.collapses + s.flips + s.moves, 1u);
  EXPECT_EQ(s.after.below_5deg, 0u);
  EXPECT_TRUE(check_mesh(m).valid());
  EXPECT_NEAR(surface_area(m), 6, 1e-12);
  EXPECT_NEAR(signed_volume(m), 1, 1e-12);
  for (const Vec3& p : m.vertices)  // every vertex still on the box
    EXPECT_TRUE(p.x == 0 || p.x == 1 || p.y == 0 || p.y == 1 || p.z == 0 || p.z == 1);
}

TEST(Cleanup, MeetsTheQualityTargetsOnCrambin) {
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  SphereUnion r = solvent_accessible_surface(s.atoms, {});
  Mesh again = r.mesh;
  const CleanupStats stats = improve_surface(r.mesh);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  EXPECT_GT(stats.before.below_1deg, 100u);  // there was something to do
  EXPECT_EQ(stats.after.below_1deg, 0u);
  EXPECT_LE(stats.after.below_5deg * 1000, stats.after.faces);  // 99.9 % at or above 5 degrees
  EXPECT_LT(std::abs(stats.area_after - stats.area_before), 1e-3 * stats.area_before);
  CleanupOptions unmeasured;
  unmeasured.measure_after = false;
  const CleanupStats again_stats = improve_surface(again, unmeasured);  // deterministic, measured or not
  EXPECT_TRUE(again.faces == r.mesh.faces);
  EXPECT_TRUE(again.vertices == r.mesh.vertices);
  EXPECT_EQ(again_stats.after.faces, 0u);  // left to the caller
  EXPECT_EQ(again_stats.collapses, stats.collapses);
}

// The sharpest edge of a mesh: the smallest angle, in degrees, between the two faces on an
// edge, measured inside the solid (180: flat; 0: a knife-edge fold).
double sharpest_opening_deg(const Mesh& m) {
  std::map<std::pair<Index, Index>, std::size_t> first;
  double sharpest = 180;
  auto normal = [&](std::size_t f) {
    const Triangle& t = m.faces[f];
    const Vec3 n = cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]]);
    return n / norm(n);
  };
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      const Index a = m.faces[f][i], b = m.faces[f][(i + 1) % 3];
      const auto key = std::minmax(a, b);
      if (auto it = first.find(key); it != first.end()) {
        const double c = std::clamp(dot(normal(f), normal(it->second)), -1.0, 1.0);
        sharpest = std::min(sharpest, 180 - std::acos(c) * 180 / std::numbers::pi);
      } else {
        first.emplace(key, f);
      }
    }
  return sharpest;
}

// An edit may turn a face onto the unchanged face across one of its edges: exactly valid,
// but a mesher's floating-point boundary recovery takes the two faces for overlapping
// (gmsh: "overlapping facets"). Crambin's van der Waals surface got such a fold (under
// 0.1 degree) when only each face's own turn was bounded.
TEST(Cleanup, FoldsNoTwoFacesOntoEachOther) {
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  SphereUnionOptions o;
  o.spheres.probe = 0;
  Mesh m = solvent_accessible_surface(s.atoms, o).mesh;
  ASSERT_GE(sharpest_opening_deg(m), 1.0);  // the union has none
  improve_surface(m);
  EXPECT_TRUE(check_mesh(m).valid());
  EXPECT_GE(sharpest_opening_deg(m), 1.0);
}

// The cleaned surface does not depend on the thread count (the scan for distorted faces,
// the index's boxes and the edits, region by region, run in parallel).
TEST(Cleanup, GivesTheSameSurfaceOnOneAndTwoThreads) {
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  const Mesh raw = solvent_accessible_surface(s.atoms, {}).mesh;
  std::vector<Mesh> cleaned;
  std::vector<CleanupStats> stats;
  for (int threads : {1, 2}) {
    const ThreadCountScope scope(threads);
    cleaned.push_back(raw);
    stats.push_back(improve_surface(cleaned.back()));
  }
  EXPECT_TRUE(cleaned[0].faces == cleaned[1].faces);
  EXPECT_TRUE(cleaned[0].vertices == cleaned[1].vertices);
  EXPECT_TRUE(cleaned[0].face_tags == cleaned[1].face_tags);
  EXPECT_EQ(stats[0].collapses, stats[1].collapses);
  EXPECT_EQ(stats[0].flips, stats[1].flips);
  EXPECT_EQ(stats[0].moves, stats[1].moves);
  EXPECT_EQ(stats[0].refused, stats[1].refused);
}

// The short edges are collapsed by cells of space in parallel (as the distorted faces are):
// the same surface on any thread count.
TEST(Cleanup, CollapsesShortEdgesToTheSameSurfaceOnOneAndTwoThreads) {
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  const Mesh raw = solvent_accessible_surface(s.atoms, {}).mesh;
  CleanupOptions options;
  options.min_edge_length = 0.3;
  options.max_volume_change = 1e-3;
  std::vector<Mesh> cleaned;
  std::vector<CleanupStats> stats;
  for (int threads : {1, 2}) {
    const ThreadCountScope scope(threads);
    cleaned.push_back(raw);
    stats.push_back(improve_surface(cleaned.back(), options));
  }
  EXPECT_GT(stats[0].short_edges_before, 1000u);
  EXPECT_LT(stats[0].short_edges_after, stats[0].short_edges_before / 10);
  EXPECT_TRUE(cleaned[0].faces == cleaned[1].faces);
  EXPECT_TRUE(cleaned[0].vertices == cleaned[1].vertices);
  EXPECT_EQ(stats[0].collapses, stats[1].collapses);
  EXPECT_EQ(stats[0].short_edges_after, stats[1].short_edges_after);
  EXPECT_TRUE(check_mesh(cleaned[1]).valid());
}

std::vector<double> edge_lengths(const Mesh& m) {
  std::vector<double> out;
  for (const Triangle& t : m.faces)
    for (int i = 0; i < 3; ++i)
      if (t[i] < t[(i + 1) % 3]) out.push_back(norm(m.vertices[t[(i + 1) % 3]] - m.vertices[t[i]]));
  return out;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}


// Edges far shorter than the rest break meshers' floating-point boundary recovery (gmsh,
// tetgen) and BEM readers' area cut-offs even where no angle is small: the cleanup's last
// pass collapses them, within the rules every edit keeps.
TEST(Cleanup, CollapsesEdgesFarShorterThanTheMedian) {
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  const Mesh raw = solvent_accessible_surface(s.atoms, {}).mesh;
  Mesh without = raw, with = raw;
  CleanupOptions off;
  off.min_edge_fraction = 0;
  const CleanupStats stats_off = improve_surface(without, off);
  EXPECT_EQ(stats_off.short_edges_before, 0u);  // not counted when the pass is off
  const std::vector<double> before = edge_lengths(without);
  const double floor = 0.02 * median(before);
  EXPECT_GT(std::count_if(before.begin(), before.end(), [&](double l) { return l < floor; }), 0)
      << "the angle passes alone leave short edges: the test needs them";

  const CleanupStats stats = improve_surface(with);
  EXPECT_GT(stats.short_edges_before, 0u);
  // The pass starts from the mesh the angle passes leave, against the median it finds.
  EXPECT_EQ(stats.short_edges_before,
            static_cast<std::size_t>(std::count_if(before.begin(), before.end(), [&](double l) { return l < floor; })));
  EXPECT_EQ(stats.short_edges_after, 0u);
  const std::vector<double> after = edge_lengths(with);
  const double floor_after = 0.02 * median(after);
  EXPECT_EQ(std::count_if(after.begin(), after.end(), [&](double l) { return l < floor_after; }), 0);
  EXPECT_TRUE(check_mesh(with).valid());
  EXPECT_EQ(stats.after.below_1deg, 0u);
  EXPECT_LE(stats.after.below_5deg, stats_off.after.below_5deg);  // no angle given up for it
  EXPECT_LT(std::abs(stats.area_after - stats.area_before), 1e-3 * stats.area_before);
}

}  // namespace
}  // namespace molsurf

namespace molsurf {
namespace {

// An absolute floor, for a surface whose median edge is itself far below what its density
// asks: edges under it are collapsed as the median's fraction would, and the surface stays valid.
TEST(Cleanup, CollapsesEdgesUnderAnAbsoluteLength) {
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  Mesh mesh = solvent_accessible_surface(s.atoms, {}).mesh;
  const double area = surface_area(mesh);
  CleanupOptions options;
  options.min_edge_length = 0.3;
  const CleanupStats stats = improve_surface(mesh, options);
  EXPECT_GT(stats.short_edges_before, stats.short_edges_after);
  const MeshCheck check = check_mesh(mesh);
  EXPECT_TRUE(check.valid());
  EXPECT_NEAR(surface_area(mesh), area, 1e-3 * area);
}

// Collapses on a convex surface take volume off it; a volume budget bounds what they take,
// each component's, either way (the SES's cleanup: collapses across the ridges where
// overlapping probes meet cut them off).
TEST(Cleanup, KeepsEachComponentsVolumeWithinItsBudget) {
  const Mesh fine = make_icosphere({0.1, -0.2, 0.3}, 2.0, {.frequency = 24, .area_corrected = true});
  const double volume = signed_volume(fine);
  CleanupOptions options;
  options.max_area_change = 1;  // the area may follow the volume: only the volume binds
  options.min_edge_length = 0.4;
  Mesh unbounded = fine;
  improve_surface(unbounded, options);
  EXPECT_LT(signed_volume(unbounded), volume * (1 - 2e-3));  // without it, collapses take more
  options.max_volume_change = 1e-3;
  Mesh bounded = fine;
  const CleanupStats stats = improve_surface(bounded, options);
  EXPECT_GT(stats.collapses, 0u);
  EXPECT_LE(std::abs(signed_volume(bounded) - volume), 1e-3 * volume);
  EXPECT_TRUE(check_mesh(bounded).valid());
}

}  // namespace
}  // namespace molsurf
