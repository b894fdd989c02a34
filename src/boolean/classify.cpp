#include "boolean/classify.hpp"

#include <algorithm>

#include "mesh/topology.hpp"
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "boolean/intersect.hpp"
#include "boolean/split.hpp"
#include "geometry/ray_parity.hpp"

namespace molsurf::boolean_engine {

namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) { return undirected_edge_key(a, b); }


// A sub-face lies in coplanar face g of the other operand when its three corners are in
// the closed triangle g (the constraints include g's boundary, so a piece is either
// inside g or has no interior point in common with it).
bool inside_partner(const Operands& ops, const Arrangement& arr, const SubFace& s, std::uint32_t g) {
  const auto& f = ops.face(s.face);
  const Projection pr = face_projection(ops.vertex(f[0]), ops.vertex(f[1]), ops.vertex(f[2]));
  const auto& gv = ops.face(g);
  std::array<geometry::ImplicitPoint, 3> corner;
  for (int i = 0; i < 3; ++i) corner[i] = geometry::ImplicitPoint::explicit_point(ops.vertex(gv[i]));
  const int orientation = geometry::orient2d(corner[0], corner[1], corner[2], pr.u, pr.v);
  for (std::uint32_t p : s.points)
    for (int i = 0; i < 3; ++i)
      if (geometry::orient2d(corner[i], corner[(i + 1) % 3], arr.points[p], pr.u, pr.v) * orientation < 0)
        return false;
  return true;
}

}  // namespace

Classification classify_sub_faces(const Operands& ops, const Arrangement& arr, const SplitResult& split) {
  const std::vector<SubFace>& subs = split.sub_faces;
  const auto& intersection_edges = split.intersection_edges;
  Classification result;
  const auto n = static_cast<std::uint32_t>(subs.size());
  result.side.assign(n, Side::outside);
  std::vector<std::uint8_t> coincident(n, 0);
  for (std::uint32_t s = 0; s < n; ++s)
    for (const Arrangement::Partner& partner : arr.coplanar_partners[subs[s].face])
      if (inside_partner(ops, arr, subs[s], partner.face)) {
        coincident[s] = 1;
        result.side[s] = partner.same_orientation ? Side::coincident_same : Side::coincident_opposite;
        break;
      }

  // Patches: sub-faces of one operand joined across edges that are not on an
  // intersection curve.
  std::unordered_set<std::uint64_t> curve;
  curve.reserve(intersection_edges.size() * 2);
  for (auto [a, b] : intersection_edges) curve.insert(edge_key(a, b));
  DisjointSets patches(n);
  auto unite = [&](std::uint32_t x, std::uint32_t y) { patches.unite(x, y); };
  // Pieces of cut faces meet along point-id edges: hash those (few). Whole faces meet
  // their neighbours across input edges: the operands' edge table joins them directly.
  std::unordered_map<std::uint64_t, std::uint32_t> piece_on_edge[2];
  for (std::uint32_t f = 0; f < ops.face_count(); ++f) {
    if (!split.cut[f]) continue;
    const int operand = ops.operand_of_face(f);
    for (std::uint32_t s = split.first_sub_face[f]; s < split.first_sub_face[f + 1]; ++s) {
      if (coincident[s]) continue;
      for (int i = 0; i < 3; ++i) {
        const std::uint64_t key = edge_key(subs[s].points[i], subs[s].points[(i + 1) % 3]);
        if (curve.count(key)) continue;
        auto [it, inserted] = piece_on_edge[operand].try_emplace(key, s);
        if (!inserted) unite(it->second, s);
      }
    }
  }
  for (std::uint32_t f = 0; f < ops.face_count(); ++f) {
    if (split.cut[f]) continue;
    const std::uint32_t s = split.first_sub_face[f];
    if (coincident[s]) continue;
    const int operand = ops.operand_of_face(f);
    for (std::uint32_t e : ops.face_edges(f)) {
      const auto& two = ops.edge_faces(e);
      const std::uint32_t g = two[0] == f ? two[1] : two[0];
      const auto& ends = ops.edge_vertices(e);
      const std::uint64_t key = edge_key(arr.vertex_point[ends[0]], arr.vertex_point[ends[1]]);
      if (curve.count(key)) continue;
      if (!split.cut[g]) {
        if (f < g && !coincident[split.first_sub_face[g]]) unite(s, split.first_sub_face[g]);
      } else if (auto it = piece_on_edge[operand].find(key); it != piece_on_edge[operand].end()) {
        unite(s, it->second);
      }
    }
  }

  // Members of each patch, patches in order of their lowest sub-face (deterministic).
  std::vector<std::uint32_t> root(n);
  for (std::uint32_t s = 0; s < n; ++s) root[s] = patches.find(s);
  std::vector<std::uint32_t> members(n);
  std::iota(members.begin(), members.end(), 0u);
  std::stable_sort(members.begin(), members.end(), [&](std::uint32_t x, std::uint32_t y) { return root[x] < root[y]; });

  const geometry::RayParity rays[2] = {geometry::RayParity(ops.mesh(1)), geometry::RayParity(ops.mesh(0))};  // against the other operand
  std::vector<std::uint8_t> inside_patch(n, 0);
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin;
    while (end < n && root[members[end]] == root[members[begin]]) ++end;
    const std::uint32_t first = members[begin];
    if (!coincident[first]) {
      const int operand = ops.operand_of_face(subs[first].face);
      bool decided = false, inside = false;
      // Fast path: an input vertex of this operand in the patch, not on the other surface.
      for (std::size_t k = begin; k < end && !decided; ++k)
        for (std::uint32_t p : subs[members[k]].points)
          if (p < ops.vertex_count() && !arr.on_both_surfaces[p] && ops.operand_of_vertex(p) == operand) {
            inside = rays[operand].inside(ops.vertex(p));
            decided = true;
            break;
          }
      if (!decided) {
        const geometry::ExactPoint p0 = arr.points[subs[first].points[0]].exact();
        const geometry::ExactPoint p1 = arr.points[subs[first].points[1]].exact();
        const geometry::ExactPoint p2 = arr.points[subs[first].points[2]].exact();
        const geometry::ExactPoint centroid{(p0.x + p1.x + p2.x) / 3, (p0.y + p1.y + p2.y) / 3,
                                            (p0.z + p1.z + p2.z) / 3};
        inside = rays[operand].inside(centroid);
        ++result.exact_ray_casts;
      }
      inside_patch[root[first]] = inside;
    }
    begin = end;
  }
  for (std::uint32_t s = 0; s < n; ++s)
    if (!coincident[s]) result.side[s] = inside_patch[root[s]] ? Side::inside : Side::outside;
  return result;
}

}  // namespace molsurf::boolean_engine
