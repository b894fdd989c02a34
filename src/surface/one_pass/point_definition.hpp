#pragma once
// A point of the one-pass union named by the input elements that define it (issue: "every
// new point is keyed by the input elements that define it"): a vertex of an atom's
// polyhedron, an atom's edge crossing another atom's face plane, or three atoms' face
// planes meeting. 28 bytes instead of an ImplicitPoint's 272: the trim keeps every piece's
// points until the join, and on a capsid that is tens of millions of points. The implicit
// point is rebuilt from the polyhedra whenever arithmetic is needed, always by the same
// expression, so every atom that meets a point builds the same doubles.
#include <array>
#include <cstdint>
#include <cstring>

#include "geometry/implicit_point.hpp"
#include "surface/atom_polyhedra.hpp"

namespace molsurf::surface_detail {

struct PointDefinition {
  using Kind = geometry::ImplicitPoint::Kind;
  // explicit_point: atom, vertex. line_plane: the edge's atom, its lower and higher vertex,
  // the plane's atom and face. three_planes: (atom, face) three times, in increasing order.
  // Unused ids are zero, so equal definitions are equal bytes.
  std::array<std::uint32_t, 6> id{};
  Kind kind = Kind::explicit_point;

  static PointDefinition vertex(std::uint32_t atom, std::uint32_t v) {
    PointDefinition d;
    d.id = {atom, v, 0, 0, 0, 0};
    return d;
  }
  static PointDefinition edge_plane(std::uint32_t edge_atom, std::uint32_t v0, std::uint32_t v1,
                                    std::uint32_t plane_atom, std::uint32_t face);
  static PointDefinition three_planes(std::array<std::array<std::uint32_t, 2>, 3> planes);

  bool is_explicit() const { return kind == Kind::explicit_point; }
  bool operator==(const PointDefinition& o) const { return kind == o.kind && id == o.id; }
  std::uint64_t hash() const;
};

// The implicit point the definition names, on these polyhedra.
geometry::ImplicitPoint construct(const PointDefinition& d, const AtomPolyhedra& polyhedra);

}  // namespace molsurf::surface_detail
