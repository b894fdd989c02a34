#include "surface/one_pass/face_work.hpp"

#include <algorithm>

namespace molsurf::surface_detail::one_pass {

const geometry::ImplicitPoint& FaceWork::own_edge_point(const PointDefinition& d, const AtomPolyhedra& polyhedra) {
  if (const auto it = own_edge_points.find(d); it != own_edge_points.end()) return it->second;
  return own_edge_points.emplace(d, construct(d, polyhedra)).first->second;
}

std::uint32_t FaceWork::add(const PointDefinition& d, const AtomPolyhedra& polyhedra, Place place,
                            std::uint32_t neighbour) {
  auto merge = [&](std::uint32_t k) {
    // The simplest place wins (a corner over an edge over the interior).
    if (place.where < places[k].where) places[k] = place;
    auto& on = on_neighbour[k];
    if (neighbour != ~0u && std::find(on.begin(), on.end(), neighbour) == on.end()) on.push_back(neighbour);
    return k;
  };
  for (std::uint32_t k = 0; k < points.size(); ++k)
    if (definitions[k] == d) return merge(k);
  // A point is copied once, into `points` (it is large: its defining points and its box).
  auto add_new = [&](const geometry::ImplicitPoint& x) {
    for (std::uint32_t k = 0; k < points.size(); ++k)
      if (geometry::same_point(points[k], x)) return merge(k);
    points.push_back(x);
    definitions.push_back(d);
    places.push_back(place);
    if (on_neighbour.size() < points.size()) on_neighbour.emplace_back();
    auto& on = on_neighbour[points.size() - 1];
    on.clear();
    if (neighbour != ~0u) on.push_back(neighbour);
    return static_cast<std::uint32_t>(points.size() - 1);
  };
  if (d.kind == PointDefinition::Kind::line_plane && d.id[0] == atom) return add_new(own_edge_point(d, polyhedra));
  return add_new(construct(d, polyhedra));
}

}  // namespace molsurf::surface_detail::one_pass
