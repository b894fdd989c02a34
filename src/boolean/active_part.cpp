#include "boolean/active_part.hpp"

namespace molsurf::boolean_engine {

ActivePart active_part(const Mesh& solid, const BoundingBox& other_box) {
  ActivePart part;
  const auto face_count = static_cast<std::uint32_t>(solid.faces.size());
  std::vector<std::uint32_t> active;
  active.reserve(face_count);
  for (std::uint32_t f = 0; f < face_count; ++f) {
    // Closed-box overlap on doubles: exact, and conservative (touching boxes count).
    const BoundingBox box = bounding_box(solid, f);
    if (box.overlaps(other_box))
      active.push_back(f);
    else
      part.passive_faces.push_back(f);
  }
  if (part.passive_faces.empty()) {
    part.whole = true;
    return part;
  }
  constexpr std::uint32_t unused = ~std::uint32_t{0};
  std::vector<std::uint32_t> renumber(solid.vertices.size(), unused);
  for (std::uint32_t f : active)
    for (Index v : solid.faces[f]) renumber[v] = 0;
  for (std::uint32_t v = 0; v < renumber.size(); ++v)
    if (renumber[v] != unused) {
      renumber[v] = static_cast<std::uint32_t>(part.vertex_origin.size());
      part.vertex_origin.push_back(v);
      part.mesh.vertices.push_back(solid.vertices[v]);
    }
  part.mesh.faces.reserve(active.size());
  const bool tagged = solid.has_tags();
  if (tagged) part.mesh.face_tags.reserve(active.size());
  for (std::uint32_t f : active) {
    const Triangle& t = solid.faces[f];
    part.mesh.faces.push_back({renumber[t[0]], renumber[t[1]], renumber[t[2]]});
    if (tagged) part.mesh.face_tags.push_back(solid.face_tags[f]);
  }
  part.face_origin = std::move(active);
  return part;
}

}  // namespace molsurf::boolean_engine
