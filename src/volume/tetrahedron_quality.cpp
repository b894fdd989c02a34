#include "volume/tetrahedron_quality.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace molsurf::volume_detail {

TetrahedronShape tetrahedron_shape(const std::array<Vec3, 4>& p) {
  TetrahedronShape s;
  const Vec3 a = p[0] - p[3], b = p[1] - p[3], c = p[2] - p[3];
  const double six_volume = dot(a, cross(b, c));
  s.volume = std::abs(six_volume) / 6;
  if (six_volume == 0) return s;
  // Face k is opposite corner k; its normal, pointing away from corner k.
  constexpr int face[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  std::array<Vec3, 4> normal;
  double area_sum = 0;
  for (int k = 0; k < 4; ++k) {
    Vec3 n = cross(p[face[k][1]] - p[face[k][0]], p[face[k][2]] - p[face[k][0]]);
    const double length = norm(n);
    area_sum += length / 2;
    if (dot(n, p[k] - p[face[k][0]]) > 0) n = -1.0 * n;
    normal[k] = (1 / length) * n;
  }
  // The dihedral angle along the edge shared by faces i and j is pi minus the angle
  // between their outward normals.
  double smallest = std::numbers::pi;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const double cosine = std::clamp(dot(normal[i], normal[j]), -1.0, 1.0);
      smallest = std::min(smallest, std::numbers::pi - std::acos(cosine));
    }
  s.min_dihedral_deg = smallest * 180 / std::numbers::pi;
  const double inradius = 3 * s.volume / area_sum;
  const Vec3 centre = (1 / (2 * six_volume)) * (dot(a, a) * cross(b, c) + dot(b, b) * cross(c, a) + dot(c, c) * cross(a, b));
  s.radius_ratio = 3 * inradius / norm(centre);
  return s;
}

}  // namespace molsurf::volume_detail
