// Stars proved embedded, and the check that skips their pairs: it must find every crossing
// and contact that testing all pairs finds.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "geometry/triangle_intersection.hpp"
#include "mesh/embedded_stars.hpp"
#include "mesh/icosphere.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/surface.hpp"
#include "surface/solvent_accessible_surface.hpp"

namespace molsurf {
namespace {

VertexFaces faces_around(const Mesh& m) {
  VertexFaces around;
  around.start.assign(m.vertices.size() + 1, 0);
  for (const Triangle& t : m.faces)
    for (const Index v : t) ++around.start[v + 1];
  for (std::size_t v = 0; v < m.vertices.size(); ++v) around.start[v + 1] += around.start[v];
  around.faces.resize(around.start.back());
  std::vector<std::uint32_t> fill(around.start.begin(), around.start.end() - 1);
  for (std::uint32_t f = 0; f < m.faces.size(); ++f)
    for (const Index v : m.faces[f]) around.faces[fill[v]++] = f;
  return around;
}

// A star around vertex 0: link vertices at the given angles (turns of 2 pi) and heights,
// one face from each to the next, counter-clockwise seen from +z.
Mesh star(const std::vector<double>& turns, const std::vector<double>& heights) {
  Mesh m;
  m.vertices.push_back({0, 0, 0});
  for (std::size_t k = 0; k < turns.size(); ++k) {
    const double a = 2 * std::numbers::pi * turns[k];
    m.vertices.push_back({std::cos(a), std::sin(a), heights[k]});
  }
  const auto n = static_cast<Index>(turns.size());
  for (Index k = 0; k < n; ++k) m.faces.push_back({0, 1 + k, 1 + (k + 1) % n});
  return m;
}

bool centre_embedded(const Mesh& m) { return embedded_stars(m, faces_around(m))[0] == 1; }

TEST(EmbeddedStars, OneTurnIsProved) {
  EXPECT_TRUE(centre_embedded(star({0, 1.0 / 6, 2.0 / 6, 3.0 / 6, 4.0 / 6, 5.0 / 6}, {0.1, -0.2, 0.3, 0, 0.2, -0.1})));
  // Seen from below: every face turns clockwise, still once.
  Mesh flipped = star({0, 0.2, 0.4, 0.6, 0.8}, {0, 0, 0, 0, 0});
  for (Triangle& t : flipped.faces) std::swap(t[1], t[2]);
  EXPECT_TRUE(centre_embedded(flipped));
  // A steep cone, seen best along its axis, and the same cone lying along x.
  Mesh cone = star({0, 0.25, 0.5, 0.75}, {-3, -3, -3, -3});
  EXPECT_TRUE(centre_embedded(cone));
  for (Vec3& p : cone.vertices) p = {p.z, p.x, p.y};
  EXPECT_TRUE(centre_embedded(cone));
}

TEST(EmbeddedStars, WhatIsNotProvedIsNotMarked) {
  // Five faces turning 2/5 of a turn each: twice around (a pentagram), every face counter-
  // clockwise. A branched surface, not an embedded disk.
  EXPECT_FALSE(centre_embedded(star({0, 0.4, 0.8, 1.2, 1.6}, {0, 0.1, 0.2, 0.3, 0.4})));
  // One face turned back: a fold.
  EXPECT_FALSE(centre_embedded(star({0, 0.3, 0.2, 0.5, 0.75}, {0, 0, 0, 0, 0})));
  // A face that is a segment seen from every axis (its link edge through the vertex).
  Mesh flat = star({0, 0.25, 0.5, 0.75}, {0, 0, 0, 0});
  flat.vertices[2] = {2, 0, 0};  // on the line through the centre and vertex 1
  EXPECT_FALSE(centre_embedded(flat));
  // Fewer than three faces.
  EXPECT_FALSE(centre_embedded(star({0, 0.5}, {0, 0})));
}

// Random stars, with the link's angles in order (a disk), out of order (folds) or going
// round twice, seen along any direction, and on a small integer grid (exact ties: link
// points level with the vertex, faces seen edge-on). Whenever a star is proved, every pair
// of its faces meets only where they share corners.
TEST(EmbeddedStars, AProvedStarsFacesNeverCross) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  std::size_t proved = 0, unproved = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int n = 3 + static_cast<int>(unit(rng) * 8);
    const int kind = trial % 4;  // 0, 1: in order; 2: any order; 3: integer grid
    Mesh m;
    m.vertices.push_back({0, 0, 0});
    double angle = unit(rng);
    const double step = (kind == 1 ? 2.0 : 1.0) / n;
    for (int k = 0; k < n; ++k) {
      angle = kind == 2 ? unit(rng) : angle + step * (0.5 + unit(rng));
      const double a = 2 * std::numbers::pi * angle, r = 0.2 + unit(rng);
      m.vertices.push_back({r * std::cos(a), r * std::sin(a), unit(rng) - 0.5});
    }
    if (kind == 3)
      for (Vec3& p : m.vertices) p = {std::round(3 * p.x), std::round(3 * p.y), std::round(3 * p.z)};
    // Seen along a random direction: the coordinates permuted and mirrored at random.
    const int shift = static_cast<int>(unit(rng) * 3);
    for (Vec3& p : m.vertices) {
      p = shift == 0 ? p : (shift == 1 ? Vec3{p.z, p.x, p.y} : Vec3{p.y, p.z, p.x});
      if (trial % 3 == 0) p.x = -p.x;
    }
    for (int k = 0; k < n; ++k)
      m.faces.push_back({0, static_cast<Index>(1 + k), static_cast<Index>(1 + (k + 1) % n)});
    if (!centre_embedded(m)) {
      ++unproved;
      continue;
    }
    ++proved;
    for (std::size_t i = 0; i < m.faces.size(); ++i)
      for (std::size_t j = i + 1; j < m.faces.size(); ++j)
        ASSERT_EQ(geometry::classify_triangle_pair(m, i, j), geometry::TrianglePairRelation::apart)
            << "trial " << trial << " faces " << i << " " << j;
  }
  EXPECT_GT(proved, 2000u);
  EXPECT_GT(unproved, 2000u);
}

// Every pair of faces classified, without any tree or proof.
void count_all_pairs(const Mesh& m, std::size_t& intersecting, std::size_t& contacts) {
  intersecting = contacts = 0;
  for (std::size_t i = 0; i < m.faces.size(); ++i)
    for (std::size_t j = i + 1; j < m.faces.size(); ++j) {
      const auto r = geometry::classify_triangle_pair(m, i, j);
      intersecting += r == geometry::TrianglePairRelation::intersecting;
      contacts += r == geometry::TrianglePairRelation::contact;
    }
}

// Icospheres with their vertices moved at random, from a little to far beyond a face's
// size, so that stars fold and faces around a vertex cross: the check counts the same
// crossings and contacts as classifying every pair.
TEST(EmbeddedStars, CheckFindsWhatAllPairsFind) {
  std::mt19937_64 rng(20261126);
  std::size_t folded = 0;
  for (const double amount : {0.01, 0.1, 0.3, 0.6})
    for (int trial = 0; trial < 6; ++trial) {
      Mesh m = make_icosphere({0, 0, 0}, 1.0, {.frequency = 2, .area_corrected = false});
      std::uniform_real_distribution<double> move(-amount, amount);
      std::uniform_int_distribution<int> few(0, 2);
      for (Vec3& p : m.vertices)
        if (few(rng) == 0) p += Vec3{move(rng), move(rng), move(rng)};
      std::size_t intersecting = 0, contacts = 0;
      count_all_pairs(m, intersecting, contacts);
      const MeshCheck c = check_mesh(m, {});
      if (c.degenerate_faces > 0) continue;  // degenerate faces are not tested for crossings
      EXPECT_EQ(c.intersecting_pairs, intersecting) << amount << " " << trial;
      EXPECT_EQ(c.contact_pairs, contacts) << amount << " " << trial;
      folded += intersecting > 0;
    }
  EXPECT_GT(folded, 3u);  // the family does reach meshes that cross themselves
}

// A vertex pushed past one of its neighbours, in its surface: its star folds over, and
// faces around the two vertices cross each other.
TEST(EmbeddedStars, CheckFindsAFoldedStar) {
  std::size_t folded = 0;
  for (const Index v : {0u, 5u, 17u})
    for (const double beyond : {0.5, 1.0, 2.0}) {
      Mesh m = make_icosphere({0, 0, 0}, 1.0, {.frequency = 2, .area_corrected = false});
      Index w = 0;
      for (const Triangle& t : m.faces)
        if (t[0] == v) w = t[1];
      m.vertices[v] = m.vertices[w] + beyond * (m.vertices[w] - m.vertices[v]);
      std::size_t intersecting = 0, contacts = 0;
      count_all_pairs(m, intersecting, contacts);
      const MeshCheck c = check_mesh(m, {});
      EXPECT_EQ(c.intersecting_pairs, intersecting) << v << " " << beyond;
      EXPECT_EQ(c.contact_pairs, contacts) << v << " " << beyond;
      folded += intersecting > 0;
    }
  EXPECT_EQ(folded, 9u);
}

// On a molecular surface (as the union gives it, slivers and all) nine in ten stars are
// proved (a star across a sharp crease can fold over whichever axis it is seen along).
TEST(EmbeddedStars, MostStarsOfASurfaceAreProved) {
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  const Mesh m = solvent_accessible_surface(s.atoms, SphereUnionOptions{}).mesh;
  const std::vector<std::uint8_t> embedded = embedded_stars(m, faces_around(m));
  std::size_t proved = 0;
  for (const std::uint8_t e : embedded) proved += e;
  EXPECT_GT(proved, 0.9 * static_cast<double>(m.vertices.size()));
}

}  // namespace
}  // namespace molsurf
