#include "surface/one_pass/neighbour.hpp"

#include <stdexcept>

namespace molsurf::surface_detail::one_pass {

bool inside_closed(const geometry::ImplicitPoint& x, const Neighbour& n) {
  if (const auto settled = settled_by_balls({x.coordinate(0), x.coordinate(1), x.coordinate(2)}, n.centre,
                                            n.inradius, n.circumradius))
    return *settled;
  const Vec3 m{x.coordinate(0).mid(), x.coordinate(1).mid(), x.coordinate(2).mid()};
  const Vec3 d = m - n.centre;
  auto try_face = [&](std::uint32_t g, bool& inside) {
    const auto t = n.face(g);
    if (!in_cone(n.centre, t, x)) return false;
    inside = geometry::orient3d(t[0], t[1], t[2], x) <= 0;
    return true;
  };
  // The face towards x is found directly; rounding can only move that guess to a face
  // around it, and the full search is a last resort that the exact test keeps correct.
  bool inside = false;
  const PolyhedronTemplate& shape = *n.shape;
  const std::uint32_t guess = shape.face_towards(d);
  if (try_face(guess, inside)) return inside;
  for (Index v : shape.unit.faces[guess])
    for (std::uint32_t k = shape.vertex_faces_first[v]; k < shape.vertex_faces_first[v + 1]; ++k)
      if (shape.vertex_faces[k] != guess && try_face(shape.vertex_faces[k], inside)) return inside;
  for (std::uint32_t g = 0; g < shape.unit.faces.size(); ++g)
    if (try_face(g, inside)) return inside;
  throw std::logic_error("one-pass union: a point in no face's cone");
}

}  // namespace molsurf::surface_detail::one_pass
