#include "boolean/classify.hpp"

#include <algorithm>

#include "mesh/topology.hpp"
#include <numeric>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "boolean/intersect.hpp"
#include "boolean/split.hpp"
#include "geometry/ray_parity.hpp"

namespace molsurf::boolean_engine {

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
  // An edge is on a curve only if both its ends are on both surfaces (cheap to test first).
  auto on_curve = [&](std::uint32_t a, std::uint32_t b) {
    if (!arr.on_both_surfaces[a] || !arr.on_both_surfaces[b]) return false;
    return std::binary_search(intersection_edges.begin(), intersection_edges.end(),
                              std::pair<std::uint32_t, std::uint32_t>(std::min(a, b), std::max(a, b)));
  };
  DisjointSets patches(n);
  auto unite = [&](std::uint32_t x, std::uint32_t y) { patches.unite(x, y); };
  // Pieces of cut faces meet along point-id edges: sorted (edge, operand, piece) records
  // pair them (few). Whole faces meet their neighbours across input edges: the operands'
  // edge table joins them directly.
  struct PieceEdge {
    std::uint64_t key;
    std::uint32_t operand_and_piece;  // operand in the top bit
    auto operator<=>(const PieceEdge&) const = default;
  };
  std::vector<PieceEdge> piece_edges;
  for (std::uint32_t f = 0; f < ops.face_count(); ++f) {
    if (!split.cut[f]) continue;
    const auto operand = static_cast<std::uint32_t>(ops.operand_of_face(f));
    for (std::uint32_t s = split.first_sub_face[f]; s < split.first_sub_face[f + 1]; ++s) {
      if (coincident[s]) continue;
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t a = subs[s].points[i], b = subs[s].points[(i + 1) % 3];
        if (on_curve(a, b)) continue;
        piece_edges.push_back({undirected_edge_key(a, b), operand << 31 | s});
      }
    }
  }
  std::sort(piece_edges.begin(), piece_edges.end());
  for (std::size_t k = 1; k < piece_edges.size(); ++k)
    if (piece_edges[k].key == piece_edges[k - 1].key &&
        piece_edges[k].operand_and_piece >> 31 == piece_edges[k - 1].operand_and_piece >> 31)
      unite(piece_edges[k].operand_and_piece & 0x7fffffffu, piece_edges[k - 1].operand_and_piece & 0x7fffffffu);
  auto piece_on_edge = [&](std::uint32_t operand, std::uint64_t key) -> std::uint32_t {
    const auto it = std::lower_bound(piece_edges.begin(), piece_edges.end(), PieceEdge{key, operand << 31});
    if (it == piece_edges.end() || it->key != key || it->operand_and_piece >> 31 != operand) return ~0u;
    return it->operand_and_piece & 0x7fffffffu;
  };
  for (std::uint32_t f = 0; f < ops.face_count(); ++f) {
    if (split.cut[f]) continue;
    const std::uint32_t s = split.first_sub_face[f];
    if (coincident[s]) continue;
    const auto operand = static_cast<std::uint32_t>(ops.operand_of_face(f));
    for (std::uint32_t e : ops.face_edges(f)) {
      const auto& two = ops.edge_faces(e);
      const std::uint32_t g = two[0] == f ? two[1] : two[0];
      if (g == kNoFace) continue;  // the rest of the solid, outside the other's box
      const auto& ends = ops.edge_vertices(e);
      const std::uint32_t a = arr.vertex_point[ends[0]], b = arr.vertex_point[ends[1]];
      if (on_curve(a, b)) continue;
      if (!split.cut[g]) {
        if (f < g && !coincident[split.first_sub_face[g]]) unite(s, split.first_sub_face[g]);
      } else if (const std::uint32_t piece = piece_on_edge(operand, undirected_edge_key(a, b)); piece != ~0u) {
        unite(s, piece);
      }
    }
  }

  // Members of each patch, patches in order of their lowest sub-face (deterministic).
  std::vector<std::uint32_t> root(n);
  for (std::uint32_t s = 0; s < n; ++s) root[s] = patches.find(s);
  // Sub-faces grouped by root, in increasing index within a group (a counting sort: the
  // roots are sub-face indices).
  std::vector<std::uint32_t> members(n), first_of_root(n + 1, 0);
  for (std::uint32_t s = 0; s < n; ++s) ++first_of_root[root[s] + 1];
  for (std::uint32_t r = 0; r < n; ++r) first_of_root[r + 1] += first_of_root[r];
  for (std::uint32_t s = 0; s < n; ++s) members[first_of_root[root[s]]++] = s;
  std::vector<std::uint32_t> patch_begin;  // patch k: members[patch_begin[k] .. patch_begin[k + 1])
  std::vector<std::uint32_t> patch_of(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    if (k == 0 || root[members[k]] != root[members[k - 1]]) patch_begin.push_back(k);
    patch_of[members[k]] = static_cast<std::uint32_t>(patch_begin.size() - 1);
  }
  const auto patch_count = static_cast<std::uint32_t>(patch_begin.size());
  patch_begin.push_back(n);

  // Verdicts: -1 unknown, 0 outside, 1 inside the other solid.
  std::vector<std::int8_t> verdict(patch_count, -1);
  // Seeds: an input vertex of the patch's own operand strictly outside the other solid's
  // box is outside the other solid (comparisons of doubles: exact).
  auto strictly_outside = [](const BoundingBox& box, const Vec3& p) {
    return p.x < box.min.x || p.x > box.max.x || p.y < box.min.y || p.y > box.max.y || p.z < box.min.z ||
           p.z > box.max.z;
  };
  for (std::uint32_t k = 0; k < patch_count; ++k) {
    const std::uint32_t first = members[patch_begin[k]];
    if (coincident[first]) continue;
    const int operand = ops.operand_of_face(subs[first].face);
    const BoundingBox& other_box = ops.solid_box(1 - operand);
    for (std::uint32_t m = patch_begin[k]; m < patch_begin[k + 1] && verdict[k] < 0; ++m)
      for (std::uint32_t p : subs[members[m]].points)
        if (p < ops.vertex_count() && ops.operand_of_vertex(p) == operand && strictly_outside(other_box, ops.vertex(p))) {
          verdict[k] = 0;
          break;
        }
  }

  // Patches on the two sides of a transversal crossing have opposite verdicts.
  std::vector<std::vector<std::uint32_t>> opposite(patch_count);
  for (auto [x, y] : split.opposite_sides) {
    if (coincident[x] || coincident[y]) continue;
    opposite[patch_of[x]].push_back(patch_of[y]);
    opposite[patch_of[y]].push_back(patch_of[x]);
  }

  // Exact ray parity against the other whole solid, for patches nothing else decides; the
  // search tree over that solid is built on first use only.
  std::optional<geometry::RayParity> rays[2];
  auto ray_verdict = [&](std::uint32_t k) -> std::int8_t {
    const std::uint32_t first = members[patch_begin[k]];
    const int operand = ops.operand_of_face(subs[first].face);
    if (!rays[operand]) rays[operand].emplace(ops.solid(1 - operand));
    ++result.ray_casts;
    // Fast path: an input vertex of this operand in the patch, not on the other surface.
    for (std::uint32_t m = patch_begin[k]; m < patch_begin[k + 1]; ++m)
      for (std::uint32_t p : subs[members[m]].points)
        if (p < ops.vertex_count() && !arr.on_both_surfaces[p] && ops.operand_of_vertex(p) == operand)
          return rays[operand]->inside(ops.vertex(p));
    const geometry::ExactPoint p0 = arr.points[subs[first].points[0]].exact();
    const geometry::ExactPoint p1 = arr.points[subs[first].points[1]].exact();
    const geometry::ExactPoint p2 = arr.points[subs[first].points[2]].exact();
    const geometry::ExactPoint centroid{(p0.x + p1.x + p2.x) / 3, (p0.y + p1.y + p2.y) / 3,
                                        (p0.z + p1.z + p2.z) / 3};
    ++result.exact_ray_casts;
    return rays[operand]->inside(centroid);
  };

  // One connected group of patches (joined by opposite-side relations) at a time: from
  // its seeds, or else from one ray, the verdicts alternate across each crossing. A
  // contradiction (possible only where the crossings are degenerate) sends every patch
  // of the group to its own ray.
  std::vector<std::uint8_t> visited(patch_count, 0);
  std::vector<std::uint32_t> group, queue;
  for (std::uint32_t k = 0; k < patch_count; ++k) {
    if (visited[k] || coincident[members[patch_begin[k]]]) continue;
    group.clear();
    group.push_back(k);
    visited[k] = 1;
    for (std::size_t i = 0; i < group.size(); ++i)
      for (std::uint32_t j : opposite[group[i]])
        if (!visited[j]) {
          visited[j] = 1;
          group.push_back(j);
        }
    std::sort(group.begin(), group.end());
    queue.clear();
    for (std::uint32_t j : group)
      if (verdict[j] >= 0) queue.push_back(j);
    if (queue.empty()) {
      verdict[group[0]] = ray_verdict(group[0]);
      queue.push_back(group[0]);
    }
    bool contradiction = false;
    for (std::size_t i = 0; i < queue.size() && !contradiction; ++i)
      for (std::uint32_t j : opposite[queue[i]]) {
        const auto flipped = static_cast<std::int8_t>(1 - verdict[queue[i]]);
        if (verdict[j] < 0) {
          verdict[j] = flipped;
          queue.push_back(j);
        } else if (verdict[j] != flipped) {
          contradiction = true;
          break;
        }
      }
    if (contradiction)
      for (std::uint32_t j : group) verdict[j] = ray_verdict(j);
  }
  for (std::uint32_t s = 0; s < n; ++s)
    if (!coincident[s]) result.side[s] = verdict[patch_of[s]] == 1 ? Side::inside : Side::outside;
  return result;
}

Keep select_sub_face(BooleanOp op, int operand, Side side) {
  // Regularised operations. A coincident piece keeps a's copy when the result has a
  // surface there, and both copies go when the solids meet face to face (the surface
  // vanishes inside the union, or there is no volume left between them).
  switch (op) {
    case BooleanOp::union_:
      if (side == Side::outside) return Keep::keep;
      if (side == Side::coincident_same && operand == 0) return Keep::keep;
      return Keep::drop;
    case BooleanOp::intersection:
      if (side == Side::inside) return Keep::keep;
      if (side == Side::coincident_same && operand == 0) return Keep::keep;
      return Keep::drop;
    case BooleanOp::difference:
      if (operand == 0) {
        if (side == Side::outside || side == Side::coincident_opposite) return Keep::keep;
        return Keep::drop;
      }
      return side == Side::inside ? Keep::keep_flipped : Keep::drop;
  }
  return Keep::drop;
}

}  // namespace molsurf::boolean_engine
