// Components of a drawn SES too small to hold an atom's or a probe's ball (src/ses/ses_specks.hpp).
#include <gtest/gtest.h>

#include <vector>

#include "mesh/icosphere.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"
#include "ses/ses_specks.hpp"

namespace molsurf {
namespace {

Mesh joined(const std::vector<Mesh>& parts) {
  Mesh out;
  for (const Mesh& m : parts) {
    const auto base = static_cast<Index>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), m.vertices.begin(), m.vertices.end());
    for (const Triangle& t : m.faces) {
      out.faces.push_back({t[0] + base, t[1] + base, t[2] + base});
      out.face_tags.push_back(static_cast<std::int32_t>(out.faces.size() % 3));
    }
  }
  return out;
}

Mesh inward(Mesh m) {
  for (Triangle& t : m.faces) std::swap(t[1], t[2]);
  return m;
}

TEST(SesSpecks, RemovesWhatCanHoldNeitherAnAtomNorAProbeAndKeepsTheRest) {
  Atom atom;
  atom.radius = 1.2;
  const std::vector<Atom> atoms = {atom};
  const Mesh body = make_icosphere({0, 0, 0}, 6, {.frequency = 4});
  const Mesh cavity = inward(make_icosphere({0.5, 0, 0}, 1.4, {.frequency = 1}));      // just a probe's ball, coarse
  const Mesh speck = make_icosphere({20, 0, 0}, 0.02, {.frequency = 1});               // 0.04 A across
  const Mesh inner_speck = inward(make_icosphere({-3, 0, 0}, 0.5, {.frequency = 2}));  // 1 A: under 1.2
  Mesh mesh = joined({body, cavity, speck, inner_speck});
  EXPECT_EQ(ses_detail::remove_specks(mesh, atoms, 1.4), 2u);
  const Mesh kept = joined({body, cavity});
  EXPECT_EQ(mesh.faces.size(), kept.faces.size());
  EXPECT_EQ(mesh.vertices.size(), kept.vertices.size());
  EXPECT_EQ(mesh.face_tags.size(), mesh.faces.size());
  EXPECT_NEAR(signed_volume(mesh), signed_volume(kept), 1e-9);
  // Nothing to remove: the mesh untouched, vertex order included.
  const Mesh before = mesh;
  EXPECT_EQ(ses_detail::remove_specks(mesh, atoms, 1.4), 0u);
  EXPECT_EQ(mesh.vertices, before.vertices);
  EXPECT_EQ(mesh.faces, before.faces);
}

}  // namespace
}  // namespace molsurf
