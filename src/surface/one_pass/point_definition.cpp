#include "surface/one_pass/point_definition.hpp"

#include <algorithm>
#include <utility>

namespace molsurf::surface_detail {

PointDefinition PointDefinition::edge_plane(std::uint32_t edge_atom, std::uint32_t v0, std::uint32_t v1,
                                            std::uint32_t plane_atom, std::uint32_t face) {
  PointDefinition d;
  d.kind = Kind::line_plane;
  // The edge in one direction, so both faces along it (and both atoms) name it alike.
  d.id = {edge_atom, std::min(v0, v1), std::max(v0, v1), plane_atom, face, 0};
  return d;
}

PointDefinition PointDefinition::three_planes(std::array<std::array<std::uint32_t, 2>, 3> planes) {
  std::sort(planes.begin(), planes.end());
  PointDefinition d;
  d.kind = Kind::three_planes;
  d.id = {planes[0][0], planes[0][1], planes[1][0], planes[1][1], planes[2][0], planes[2][1]};
  return d;
}

std::uint64_t PointDefinition::hash() const {
  std::uint64_t h = static_cast<std::uint64_t>(kind) + 1;
  for (std::uint32_t x : id) {
    h = (h ^ x) * 0x9E3779B97F4A7C15ull;
    h ^= h >> 29;
  }
  return h;
}

namespace {

std::array<Vec3, 3> face_plane(const AtomPolyhedra& polyhedra, std::uint32_t atom, std::uint32_t face) {
  const Triangle& t = polyhedra.shape(atom).unit.faces[face];
  return {polyhedra.vertex(atom, t[0]), polyhedra.vertex(atom, t[1]), polyhedra.vertex(atom, t[2])};
}

}  // namespace

geometry::ImplicitPoint construct(const PointDefinition& d, const AtomPolyhedra& polyhedra) {
  using geometry::ImplicitPoint;
  const auto& id = d.id;
  switch (d.kind) {
    case PointDefinition::Kind::explicit_point:
      return ImplicitPoint::explicit_point(polyhedra.vertex(id[0], id[1]));
    case PointDefinition::Kind::line_plane: {
      const auto plane = face_plane(polyhedra, id[3], id[4]);
      return ImplicitPoint::line_plane(polyhedra.vertex(id[0], id[1]), polyhedra.vertex(id[0], id[2]), plane[0],
                                       plane[1], plane[2]);
    }
    case PointDefinition::Kind::three_planes: {
      const auto a = face_plane(polyhedra, id[0], id[1]), b = face_plane(polyhedra, id[2], id[3]),
                 c = face_plane(polyhedra, id[4], id[5]);
      return ImplicitPoint::three_planes({a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]});
    }
  }
  return ImplicitPoint::explicit_point(polyhedra.vertex(id[0], id[1]));
}

}  // namespace molsurf::surface_detail
