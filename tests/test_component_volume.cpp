// Each component's volume and its exact sign (mesh/component_volume.hpp): the sign agrees
// with exact rational arithmetic, flat components are 0, and floating point settles the
// sign wherever its error bound allows, without integers.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "mesh/component_volume.hpp"
#include "molsurf/mesh.hpp"
#include "support/shapes.hpp"

namespace molsurf {
namespace {

// The sign of six times the mesh's component c's volume, in rationals.
int rational_sign(const Mesh& m, const Components& parts, std::uint32_t c) {
  mpq_class sum = 0;
  for (std::uint32_t f = 0; f < m.faces.size(); ++f) {
    if (parts.face_component[f] != c) continue;
    const Vec3 &a = m.vertices[m.faces[f][0]], &b = m.vertices[m.faces[f][1]], &d = m.vertices[m.faces[f][2]];
    const mpq_class ax(a.x), ay(a.y), az(a.z), bx(b.x), by(b.y), bz(b.z), dx(d.x), dy(d.y), dz(d.z);
    sum += ax * (by * dz - bz * dy) + ay * (bz * dx - bx * dz) + az * (bx * dy - by * dx);
  }
  return sgn(sum);
}

// A tetrahedron on p0..p3 (outward when p3 is above p0 p1 p2, counter-clockwise seen from p3).
void add_tetrahedron(Mesh& m, const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const auto base = static_cast<Index>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), {p0, p1, p2, p3});
  m.faces.push_back({base + 0, base + 2, base + 1});
  m.faces.push_back({base + 0, base + 1, base + 3});
  m.faces.push_back({base + 1, base + 2, base + 3});
  m.faces.push_back({base + 2, base + 0, base + 3});
}

// Hundreds of small tetrahedra far from the origin, either way round: some nearly or
// exactly flat (their fourth corner a hair off, or on, their base's plane), and some whose
// fourth corner is a point of a tilted base's plane rounded to doubles, so that it lies
// off the plane by less than rounding, to either side or on it (where a floating-point
// sum alone gets signs wrong).
TEST(ComponentVolumes, SignsAgreeWithRationalArithmetic) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  Mesh m;
  for (int k = 0; k < 600; ++k) {
    const Vec3 corner{150 + unit(random), -140 + unit(random), 130 + unit(random)};
    Vec3 p0 = corner, p1 = corner + Vec3{1e-3, 0, 0}, p2 = corner + Vec3{0, 1e-3, 0};
    const double height = k % 3 == 0 ? 0.0 : (k % 3 == 1 ? 1e-13 : 1e-4) * unit(random);
    Vec3 p3 = corner + Vec3{2.5e-4, 2.5e-4, height};
    if (k % 4 == 3) {  // tilted and larger, the fourth corner rounded onto the plane
      p0 = Vec3{0.5, 0.3, 0.7} + Vec3{unit(random), unit(random), unit(random)} * 0.1;
      p1 = p0 + Vec3{1, 0.3 * unit(random), 0.7 * unit(random)};
      p2 = p0 + Vec3{0.3 * unit(random), 1, 0.7 * unit(random)};
      const double s = 0.25 + 0.1 * unit(random), t = 0.25 + 0.1 * unit(random);
      p3 = p0 + (p1 - p0) * s + (p2 - p0) * t;
    }
    if (k % 2 == 0)
      add_tetrahedron(m, p0, p1, p2, p3);
    else
      add_tetrahedron(m, p1, p0, p2, p3);
  }
  const Components parts = connected_components(m);
  ASSERT_EQ(parts.count, 600u);
  const ComponentVolumes volumes = component_volumes(m, parts);
  int flat = 0, negative = 0, positive = 0;
  for (std::uint32_t c = 0; c < parts.count; ++c) {
    const int expected = rational_sign(m, parts, c);
    EXPECT_EQ(volumes.sign[c], expected) << c;
    EXPECT_TRUE(volumes.volume[c] == 0 || (volumes.volume[c] > 0) == (expected > 0)) << c;
    (expected == 0 ? flat : expected < 0 ? negative : positive)++;
  }
  EXPECT_GT(flat, 0);
  EXPECT_GT(negative, 100);
  EXPECT_GT(positive, 100);
  EXPECT_GT(volumes.exact_signs, 0u);  // the near-flat ones needed integers
  EXPECT_LT(volumes.exact_signs, 600u);
}

// A thin slab of 190 000 faces (100 x 100 x 1e-5 A, far from the origin): its volume is
// tiny against its terms' magnitudes, yet well above the bound of a compensated sum. A
// plain sum's bound, which grows with the number of faces, could not settle it.
TEST(ComponentVolumes, FloatingPointSettlesAThinSlabOfManyFaces) {
  Mesh slab = make_box({300, 300, 300}, {400, 400, 300.00001}, 220, 220, 1);
  ASSERT_GT(slab.faces.size(), 190'000u);
  Components parts = connected_components(slab);
  ASSERT_EQ(parts.count, 1u);
  ComponentVolumes volumes = component_volumes(slab, parts);
  EXPECT_EQ(volumes.sign[0], 1);
  EXPECT_EQ(volumes.exact_signs, 0u);
  EXPECT_NEAR(volumes.volume[0], 0.1, 1e-6);
  for (Triangle& t : slab.faces) std::swap(t[1], t[2]);  // inside out: a cavity
  volumes = component_volumes(slab, parts);
  EXPECT_EQ(volumes.sign[0], -1);
  EXPECT_EQ(volumes.exact_signs, 0u);
}

}  // namespace
}  // namespace molsurf
