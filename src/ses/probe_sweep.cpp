#include "ses/probe_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace molsurf::ses_detail {

namespace {

// v rotated by `angle` about the unit axis n (Rodrigues).
Vec3 rotated(const Vec3& v, const Vec3& n, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(n, v) * s + n * (dot(n, v) * (1 - c));
}

}  // namespace

std::vector<ProbeCentre> probe_sweep(const SphereArrangement& arrangement, const std::vector<Vec3>& centres,
                                     const std::vector<double>& radii, double spacing) {
  std::vector<ProbeCentre> out;
  out.reserve(arrangement.vertices.size() * 4);
  for (const ArrangementVertex& v : arrangement.vertices) out.push_back({v.point, v.spheres});
  for (const ArrangementArc& arc : arrangement.arcs) {
    // Each arc is listed on both its spheres; the lower one places the probes.
    if (arc.sphere > arc.other) continue;
    const Vec3 a = centres[arc.sphere], b = centres[arc.other];
    const double d = norm(b - a);
    if (!(d > 0)) continue;
    const Vec3 n = (b - a) / d;
    const double ra = radii[arc.sphere], rb = radii[arc.other];
    const double t = (d * d + ra * ra - rb * rb) / (2 * d);
    const double rho = std::sqrt(std::max(0.0, ra * ra - t * t));
    const Vec3 o = a + n * t;
    double sweep = arc.angle;
    Vec3 start;
    if (arc.from < 0) {
      // A whole circle: start anywhere on it.
      const Vec3 any = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
      Vec3 u = cross(n, any);
      start = o + u / norm(u) * rho;
      sweep = 2 * std::numbers::pi;
    } else {
      start = arrangement.vertices[static_cast<std::size_t>(arc.from)].point;
    }
    const double length = sweep * rho;
    auto segments = static_cast<std::size_t>(std::ceil(length / spacing));
    if (arc.from < 0) segments = std::max<std::size_t>(segments, rho > 0 ? 3 : 1);
    // The exposed side lies on the arc's left seen from outside `sphere`: the arc turns
    // clockwise about n, the axis from `sphere` towards `other`.
    const Vec3 radial = start - o;
    // A whole circle gets points all round; an arc only between its end vertices.
    const std::size_t first = arc.from < 0 ? 0 : 1;
    for (std::size_t k = first; k < segments; ++k) {
      const double angle = -sweep * static_cast<double>(k) / static_cast<double>(segments);
      out.push_back({o + rotated(radial, n, angle), {arc.sphere, arc.other, arc.other}});
    }
  }
  return out;
}

}  // namespace molsurf::ses_detail
