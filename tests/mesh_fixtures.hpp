#pragma once
// Small hand-made meshes shared by the tests.
#include "molsurf/mesh.hpp"

namespace molsurf::fixtures {

// Axis-aligned box [lo, hi], 12 outward triangles.
inline Mesh box(const Vec3& lo, const Vec3& hi) {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  m.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
             {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

inline Mesh unit_cube() { return box({0, 0, 0}, {1, 1, 1}); }

// Regular-ish tetrahedron with outward faces.
inline Mesh tetrahedron(const Vec3& offset = {}, double scale = 1) {
  Mesh m;
  m.vertices = {offset + Vec3{0, 0, 0} * scale, offset + Vec3{1, 0, 0} * scale,
                offset + Vec3{0, 1, 0} * scale, offset + Vec3{0, 0, 1} * scale};
  m.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

}  // namespace molsurf::fixtures
