// Vertices moved onto the true surface (include/molsurf/true_points.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/true_points.hpp"

namespace molsurf {
namespace {

TEST(TruePoints, CrambinsVerticesLieOnTheTrueSurfaceAndTheMeshStaysValid) {
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  ComputeSurfaceOptions options;
  options.true_points = true;
  const ComputedSurface c = compute_surface(s.atoms, options);
  ASSERT_TRUE(c.true_points);
  const TruePointStats& t = *c.true_points;
  EXPECT_TRUE(c.check.valid());  // compute_surface throws otherwise; said here for the reader
  EXPECT_EQ(t.on_true_point + t.partly + t.not_moved, t.vertices);
  EXPECT_GT(t.on_true_point, 0.95 * t.vertices);
  // The vertices of one atom's faces: on that atom's sphere, to rounding, for as many as
  // were moved; the facets then inscribe the true surface.
  std::vector<std::set<std::int32_t>> atoms_of(c.mesh.vertices.size());
  for (std::size_t f = 0; f < c.mesh.faces.size(); ++f)
    for (const Index v : c.mesh.faces[f]) atoms_of[v].insert(c.mesh.tag(f));
  std::size_t one_atom = 0, on_sphere = 0;
  for (std::size_t v = 0; v < atoms_of.size(); ++v) {
    if (atoms_of[v].size() != 1) continue;
    ++one_atom;
    const Atom& a = s.atoms[*atoms_of[v].begin()];
    const double r = a.radius + options.spheres.probe;
    on_sphere += std::abs(norm(c.mesh.vertices[v] - a.centre) - r) < 1e-12 * r;
  }
  EXPECT_GT(on_sphere, 0.95 * one_atom);
  EXPECT_LT(c.measures.area, c.exact.area);
  EXPECT_GT(c.measures.area, 0.98 * c.exact.area);
}

TEST(TruePoints, OffByDefault) {
  const Structure s = read_structure(std::string(MOLSURF_DATA_DIR) + "/pdb/1crn.pdb");
  const ComputedSurface c = compute_surface(s.atoms);
  EXPECT_FALSE(c.true_points);
}

}  // namespace
}  // namespace molsurf
