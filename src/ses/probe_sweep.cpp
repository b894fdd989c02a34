#include "ses/probe_sweep.hpp"

#include "geometry/point_grid.hpp"

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
  // Spheres by cell of a grid as wide as the largest sphere's radius: a ball holding a point
  // has its centre within that radius of it.
  double reach = 0;
  for (double r : radii) reach = std::max(reach, r);
  const geometry::PointGrid grid(centres, reach);
  auto held_by_another = [&](const Vec3& c, std::uint32_t a, std::uint32_t b) {
    bool held = false;
    grid.for_each_near(c, [&](std::uint32_t k) {
      held = held || (k != a && k != b && norm(c - centres[k]) < radii[k] * (1 - 1e-9));
    });
    return held;
  };
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
    // The arc turns clockwise about n; where it ends at its `to` vertex the other way round
    // (rounding of a nearly whole turn), that way. A point that another ball holds is no
    // probe position: it is left out.
    double turn = -1;
    if (arc.to >= 0) {
      const Vec3 end = arrangement.vertices[static_cast<std::size_t>(arc.to)].point;
      if (norm(o + rotated(radial, n, sweep) - end) < norm(o + rotated(radial, n, -sweep) - end)) turn = 1;
    }
    // A whole circle gets points all round; an arc only between its end vertices.
    const std::size_t first = arc.from < 0 ? 0 : 1;
    for (std::size_t k = first; k < segments; ++k) {
      const double angle = turn * sweep * static_cast<double>(k) / static_cast<double>(segments);
      const Vec3 c = o + rotated(radial, n, angle);
      if (!held_by_another(c, arc.sphere, arc.other)) out.push_back({c, {arc.sphere, arc.other, arc.other}});
    }
  }
  return out;
}

}  // namespace molsurf::ses_detail
