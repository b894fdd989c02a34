#include "geometry/triangle_distance.hpp"

#include <initializer_list>

namespace molsurf::geometry {

// By the Voronoi regions of the triangle's vertices, edges and interior, tested in turn
// with barycentric coordinates (Ericson, Real-Time Collision Detection, 5.1.5). Every
// region's test reads signs of dot products only, so a degenerate triangle falls into a
// vertex or edge region and never divides by zero.
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return a + t * ab;
  }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return a + t * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return b + t * (c - b);
  }
  const double sum = va + vb + vc;
  if (!(sum > 0)) {
    // Degenerate (collinear) triangle that no region above took: the nearest of its edges.
    auto on_segment = [&](const Vec3& s, const Vec3& e) {
      const Vec3 d = e - s;
      const double len2 = dot(d, d);
      double t = len2 > 0 ? dot(p - s, d) / len2 : 0;
      t = t < 0 ? 0 : (t > 1 ? 1 : t);
      return s + t * d;
    };
    Vec3 best = on_segment(a, b);
    for (const Vec3& q : {on_segment(b, c), on_segment(c, a)})
      if (dot(q - p, q - p) < dot(best - p, best - p)) best = q;
    return best;
  }
  const double v = vb / sum, w = vc / sum;
  return a + v * ab + w * ac;
}

double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return norm(closest_point_on_triangle(p, a, b, c) - p);
}

}  // namespace molsurf::geometry
