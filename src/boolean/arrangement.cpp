#include "boolean/arrangement.hpp"

#include "mesh/topology.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace molsurf::boolean_engine {

namespace {


void sort_unique(std::vector<std::uint32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

bool Arrangement::face_is_cut(const Operands& ops, std::uint32_t f) const {
  if (!face_points[f].empty() || !face_segments[f].empty()) return true;
  for (std::uint32_t e : ops.face_edges(f))
    if (!edge_points[e].empty()) return true;
  return false;
}

Arrangement build_arrangement(const Operands& ops, std::span<const PairIntersection> pairs) {
  Arrangement arr;
  const std::uint32_t vertex_count = ops.vertex_count();

  // Coincident vertices of a and b become one point: the lowest index (a's) stands for all.
  DisjointSets same_position(vertex_count);
  for (const PairIntersection& pair : pairs)
    for (auto [va, vb] : pair.coincident_vertices) same_position.unite(va, vb);
  arr.vertex_point.resize(vertex_count);
  arr.points.reserve(vertex_count);
  for (std::uint32_t v = 0; v < vertex_count; ++v) {
    arr.vertex_point[v] = same_position.find(v);
    arr.points.push_back(geometry::ImplicitPoint::explicit_point(ops.vertex(v)));
  }

  std::unordered_map<PointKey, std::uint32_t, PointKeyHash> id_of_key;
  auto point_id = [&](const PointKey& key) -> std::uint32_t {
    if (key.kind == PointKind::vertex) return arr.vertex_point[key.i];
    auto [it, inserted] = id_of_key.try_emplace(key, static_cast<std::uint32_t>(arr.points.size()));
    if (inserted) arr.points.push_back(make_point(ops, key));
    return it->second;
  };

  arr.edge_points.resize(ops.edge_count());
  arr.face_points.resize(ops.face_count());
  arr.face_segments.resize(ops.face_count());
  arr.transversal_segments.resize(ops.face_count());
  arr.segment_planes.resize(ops.face_count());
  arr.coplanar_partners.resize(ops.face_count());
  std::vector<std::uint32_t> on_both, touch;
  auto place = [&](std::uint32_t face, const Location& loc, std::uint32_t id) {
    if (loc.where == Where::edge)
      arr.edge_points.list(ops.face_edges(face)[loc.index]).push_back(id);
    else if (loc.where == Where::interior)
      arr.face_points.list(face).push_back(id);
  };
  for (const PairIntersection& pair : pairs) {
    if (pair.empty()) continue;
    for (const PairPoint& p : pair.points) {
      const std::uint32_t id = point_id(p.key);
      on_both.push_back(id);
      if (p.key.kind != PointKind::edge_face) touch.push_back(id);
      place(pair.face_a, p.on_a, id);
      place(pair.face_b, p.on_b, id);
    }
    auto add_segments = [&](std::uint32_t face, const auto& segments) {
      const std::uint32_t other = face == pair.face_a ? pair.face_b : pair.face_a;
      for (const auto& [k1, k2] : segments) {
        const std::uint32_t i = point_id(k1), j = point_id(k2);
        if (i == j) continue;
        arr.face_segments.list(face).emplace_back(std::min(i, j), std::max(i, j));
        if (!pair.coplanar) arr.segment_planes.list(face).push_back({{std::min(i, j), std::max(i, j)}, other});
        if (pair.transversal) arr.transversal_segments.list(face).emplace_back(std::min(i, j), std::max(i, j));
      }
    };
    add_segments(pair.face_a, pair.segments_a);
    add_segments(pair.face_b, pair.segments_b);
    if (pair.coplanar) {
      arr.coplanar_partners.list(pair.face_a).push_back({pair.face_b, pair.same_orientation});
      arr.coplanar_partners.list(pair.face_b).push_back({pair.face_a, pair.same_orientation});
    }
  }
  arr.intersection_point_count = id_of_key.size();
  arr.on_both_surfaces.assign(arr.points.size(), 0);
  for (std::uint32_t id : on_both) arr.on_both_surfaces[id] = 1;
  arr.may_touch.assign(arr.points.size(), 0);
  for (std::uint32_t id : touch) arr.may_touch[id] = 1;
  for (auto& list : arr.edge_points.lists()) sort_unique(list);
  for (auto& list : arr.face_points.lists()) sort_unique(list);
  for (auto& list : arr.segment_planes.lists()) std::sort(list.begin(), list.end());
  for (auto& list : arr.transversal_segments.lists()) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  for (auto& list : arr.face_segments.lists()) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return arr;
}

}  // namespace molsurf::boolean_engine
