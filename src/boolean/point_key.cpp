#include "boolean/point_key.hpp"

#include <cmath>
#include <stdexcept>

#include "geometry/predicates.hpp"

namespace molsurf::boolean_engine {

using geometry::ImplicitPoint;
using geometry::orient3d;

ImplicitPoint make_point(const Operands& operands, const PointKey& key) {
  switch (key.kind) {
    case PointKind::vertex:
      return ImplicitPoint::explicit_point(operands.vertex(key.i));
    case PointKind::edge_face: {
      const auto& e = operands.edge_vertices(key.i);
      const auto& f = operands.face(key.j);
      return ImplicitPoint::line_plane(operands.vertex(e[0]), operands.vertex(e[1]), operands.vertex(f[0]),
                                       operands.vertex(f[1]), operands.vertex(f[2]));
    }
    case PointKind::edge_edge: {
      // The line of edge i crosses edge j at one point: take a plane through edge j that
      // the line crosses: one of j's faces if the line is not parallel to it, otherwise
      // the plane through j along a coordinate axis.
      const auto& e = operands.edge_vertices(key.i);
      const Vec3 &p = operands.vertex(e[0]), &q = operands.vertex(e[1]);
      for (std::uint32_t g : operands.edge_faces(key.j)) {
        if (g == kNoFace) continue;
        const auto& f = operands.face(g);
        const Vec3 &a = operands.vertex(f[0]), &b = operands.vertex(f[1]), &c = operands.vertex(f[2]);
        if (orient3d(a, b, c, p) != orient3d(a, b, c, q)) return ImplicitPoint::line_plane(p, q, a, b, c);
      }
      const auto& ej = operands.edge_vertices(key.j);
      const Vec3 &a = operands.vertex(ej[0]), &b = operands.vertex(ej[1]);
      for (int axis = 0; axis < 3; ++axis) {
        Vec3 c = a;
        const double shift = a[axis] != 0 ? std::fabs(a[axis]) : 1.0;
        (axis == 0 ? c.x : axis == 1 ? c.y : c.z) += shift;
        if (geometry::collinear3d(a, b, c)) continue;
        if (orient3d(a, b, c, p) != orient3d(a, b, c, q)) return ImplicitPoint::line_plane(p, q, a, b, c);
      }
      throw std::logic_error("boolean: an edge-edge point whose edges do not cross");
    }
  }
  throw std::logic_error("boolean: unknown point kind");
}

}  // namespace molsurf::boolean_engine
