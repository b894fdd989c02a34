// Spheres held by another ball (the smaller of concentric atoms, copies): found exactly and
// in O(n log n), and left out of the union, the pairwise union and the arrangement alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "arrangement/contained_spheres.hpp"
#include "atom_fixtures.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/surface.hpp"
#include "surface/solvent_accessible_surface.hpp"

namespace molsurf {
namespace {

using testing::atom_at;

TEST(SphereContainers, ConcentricCopiesAndInnerTangentsKeepTheHolder) {
  const std::vector<Vec3> c{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0.5, 0, 0}, {0.5000001, 0, 0}, {9, 0, 0}, {0, 0, 0}};
  const std::vector<double> r{1, 2, 2, 1.5, 1.5, 1, 2};
  const std::vector<std::uint32_t> holder = arrangement::sphere_containers(c, r);
  EXPECT_EQ(holder, (std::vector<std::uint32_t>{1, 1, 1, 1, 4, 5, 1}));
  // Decided on the doubles as given, exactly: 0.1 + 0.2 (as doubles, summed exactly) is
  // above 0.3's double and below the next double up. Long double sums these exactly.
  const double above = std::nextafter(0.3, 1.0);
  ASSERT_FALSE(static_cast<long double>(0.1) + static_cast<long double>(0.2) <= static_cast<long double>(0.3));
  ASSERT_TRUE(static_cast<long double>(0.1) + static_cast<long double>(0.2) <= static_cast<long double>(above));
  const std::vector<Vec3> pair{{0, 0, 0}, {0.1, 0, 0}};
  EXPECT_EQ(arrangement::sphere_containers(pair, std::vector<double>{0.3, 0.2})[1], 1u);
  EXPECT_EQ(arrangement::sphere_containers(pair, std::vector<double>{above, 0.2})[1], 0u);
}

// Issue 34: atoms at one centre cost the square of their number (each was every other's
// neighbour: 10 000 took 104 s and 1 GB at probe 0, and were refused as too complex at
// probe 1.4). Only the largest counts: the surface is that one sphere's, found with no
// neighbour pair at all.
std::vector<Atom> concentric_atoms(std::size_t& largest) {
  const Vec3 centre{1.25, -3.5, 0.375};
  std::vector<Atom> atoms;
  for (std::size_t k = 0; k < 10'000; ++k)
    atoms.push_back(atom_at(centre, 1 + 2.0 * static_cast<double>((k * 7919) % 10007) / 10007));
  largest = static_cast<std::size_t>(
      std::max_element(atoms.begin(), atoms.end(), [](const Atom& a, const Atom& b) { return a.radius < b.radius; }) -
      atoms.begin());
  atoms.push_back(atoms[largest]);  // copies after it: the lowest index stands for them
  atoms.insert(atoms.begin() + static_cast<std::ptrdiff_t>(largest) + 1, atoms[largest]);
  return atoms;
}

TEST(ContainedAtoms, TenThousandConcentricAtomsGiveOneSphereAtEveryProbe) {
  std::size_t largest = 0;
  const std::vector<Atom> atoms = concentric_atoms(largest);
  for (const double probe : {0.0, 1.4}) {
    SCOPED_TRACE(probe);
    ComputeSurfaceOptions options;
    options.spheres.probe = probe;
    const ComputedSurface all = compute_surface(atoms, options);
    const ComputedSurface one = compute_surface(std::span(atoms).subspan(largest, 1), options);
    ASSERT_EQ(all.mesh.faces, one.mesh.faces);
    ASSERT_EQ(all.mesh.vertices.size(), one.mesh.vertices.size());
    for (std::size_t v = 0; v < one.mesh.vertices.size(); ++v) {
      EXPECT_EQ(all.mesh.vertices[v].x, one.mesh.vertices[v].x);
      EXPECT_EQ(all.mesh.vertices[v].y, one.mesh.vertices[v].y);
      EXPECT_EQ(all.mesh.vertices[v].z, one.mesh.vertices[v].z);
    }
    for (const std::int32_t tag : all.mesh.face_tags) EXPECT_EQ(tag, static_cast<std::int32_t>(largest));
    const double radius = atoms[largest].radius + probe;
    EXPECT_NEAR(all.exact.area, 4 * std::numbers::pi * radius * radius, 1e-12 * radius * radius);
    EXPECT_NEAR(all.exact.volume, 4 * std::numbers::pi * radius * radius * radius / 3, 1e-12 * radius * radius * radius);
    EXPECT_EQ(all.exact.stats.buried, atoms.size() - 1);
    EXPECT_EQ(all.exact.stats.duplicate, 2u);
    for (std::size_t i = 0; i < atoms.size(); ++i) {
      if (i == largest) continue;
      ASSERT_EQ(all.exact.area_per_sphere[i], 0) << i;
      ASSERT_EQ(all.measures.atom_area[i], 0) << i;
    }
    EXPECT_EQ(all.measures.atom_area[largest], one.measures.atom_area[0]);

    SphereUnionOptions pass;
    pass.spheres = options.spheres;
    const SphereUnion trimmed = solvent_accessible_surface(atoms, pass);
    EXPECT_EQ(trimmed.one_pass.contained_atoms, atoms.size() - 1);
    EXPECT_EQ(trimmed.one_pass.neighbour_pairs, 0u);
  }
}

TEST(ContainedAtoms, ThePairwiseUnionDropsTheSameAtoms) {
  std::size_t largest = 0;
  std::vector<Atom> atoms = concentric_atoms(largest);
  atoms.resize(400);
  atoms.push_back(atom_at({4, -3.5, 0.375}, 1.7));  // one atom apart, overlapping the pile
  SphereUnionOptions options;
  const SphereUnion one_pass = solvent_accessible_surface(atoms, options);
  options.method = SurfaceMethod::pairwise;
  const SphereUnion pairwise = solvent_accessible_surface(atoms, options);
  EXPECT_EQ(pairwise.merges, 1u);  // the pile's largest and the atom apart
  std::vector<std::int32_t> a = one_pass.mesh.face_tags, b = pairwise.mesh.face_tags;
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.size(), 2u);
}

}  // namespace
}  // namespace molsurf
