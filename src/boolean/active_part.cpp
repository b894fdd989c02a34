#include "boolean/active_part.hpp"

#include <algorithm>

#include "geometry/face_bvh.hpp"
#include "geometry/ray_parity.hpp"
#include "mesh/topology.hpp"

namespace molsurf::boolean_engine {

namespace {

ActivePart split_active(const Mesh& solid, std::vector<std::uint32_t> active, std::vector<std::uint32_t> passive);

}  // namespace

ActivePart active_part(const Mesh& solid, const BoundingBox& other_box) {
  const auto face_count = static_cast<std::uint32_t>(solid.faces.size());
  std::vector<std::uint32_t> active, passive;
  active.reserve(face_count);
  for (std::uint32_t f = 0; f < face_count; ++f) {
    // Closed-box overlap on doubles: exact, and conservative (touching boxes count).
    const BoundingBox box = bounding_box(solid, f);
    if (box.overlaps(other_box))
      active.push_back(f);
    else
      passive.push_back(f);
  }
  return split_active(solid, std::move(active), std::move(passive));
}

ActivePart active_part_near(const Mesh& solid, const Mesh& other) {
  const geometry::BoxBvh tree = geometry::BoxBvh::for_faces(other);
  const auto face_count = static_cast<std::int64_t>(solid.faces.size());
  std::vector<std::uint8_t> near(solid.faces.size(), 0);
#pragma omp parallel for schedule(dynamic, 4096) if (face_count > 16384)
  for (std::int64_t f = 0; f < face_count; ++f) {
    bool hit = false;
    tree.for_each_overlap(bounding_box(solid, static_cast<std::size_t>(f)), [&](std::uint32_t) { hit = true; });
    near[f] = hit;
  }
  std::vector<std::uint32_t> active, passive;
  for (std::uint32_t f = 0; f < near.size(); ++f) (near[f] ? active : passive).push_back(f);
  return split_active(solid, std::move(active), std::move(passive));
}

std::vector<std::uint8_t> passive_sides(const Mesh& solid, const ActivePart& part, const Mesh& other) {
  std::vector<std::uint8_t> side(part.passive_faces.size(), 0);
  if (part.passive_faces.empty() || other.faces.empty()) return side;
  // Runs of passive faces joined across edges: no face of `other` comes near one, so each
  // run is on one side of it.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edges;  // (undirected edge, position)
  edges.reserve(3 * part.passive_faces.size());
  for (std::uint32_t k = 0; k < part.passive_faces.size(); ++k) {
    const Triangle& t = solid.faces[part.passive_faces[k]];
    for (int e = 0; e < 3; ++e) edges.emplace_back(undirected_edge_key(t[e], t[(e + 1) % 3]), k);
  }
  std::sort(edges.begin(), edges.end());
  DisjointSets runs(part.passive_faces.size());
  for (std::size_t k = 1; k < edges.size(); ++k)
    if (edges[k].first == edges[k - 1].first) runs.unite(edges[k].second, edges[k - 1].second);
  const geometry::RayParity parity(other);
  std::vector<std::int8_t> run_side(part.passive_faces.size(), -1);
  for (std::uint32_t k = 0; k < part.passive_faces.size(); ++k) {
    const std::uint32_t root = runs.find(k);
    if (run_side[root] < 0) {
      // A corner of a passive face lies in its box, which meets no face of `other`.
      run_side[root] = parity.inside(solid.vertices[solid.faces[part.passive_faces[k]][0]]) ? 1 : 0;
    }
    side[k] = static_cast<std::uint8_t>(run_side[root]);
  }
  return side;
}

namespace {

ActivePart split_active(const Mesh& solid, std::vector<std::uint32_t> active, std::vector<std::uint32_t> passive) {
  ActivePart part;
  part.passive_faces = std::move(passive);
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

}  // namespace

}  // namespace molsurf::boolean_engine
