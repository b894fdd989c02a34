#include "boolean/classify.hpp"

#include <algorithm>

#include "mesh/topology.hpp"
#include <numeric>
#include <optional>
#include <span>
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

namespace {

// Each sub-face that lies in a coplanar face of the other operand is coincident with it:
// its side is set in `side`; the returned flags mark those sub-faces.
std::vector<std::uint8_t> mark_coincident(const Operands& ops, const Arrangement& arr, std::span<const SubFace> subs,
                                          std::vector<Side>& side) {
  const auto n = static_cast<std::uint32_t>(subs.size());
  std::vector<std::uint8_t> coincident(n, 0);
  for (std::uint32_t s = 0; s < n; ++s)
    for (const Arrangement::Partner& partner : arr.coplanar_partners[subs[s].face])
      if (inside_partner(ops, arr, subs[s], partner.face)) {
        coincident[s] = 1;
        side[s] = partner.same_orientation ? Side::coincident_same : Side::coincident_opposite;
        break;
      }
  return coincident;
}

// An edge is on an intersection curve only if both its ends are on both surfaces (cheap
// to test first).
bool on_intersection_curve(const Arrangement& arr, const SplitResult& split, std::uint32_t a, std::uint32_t b) {
  if (!arr.on_both_surfaces[a] || !arr.on_both_surfaces[b]) return false;
  return std::binary_search(split.intersection_edges.begin(), split.intersection_edges.end(),
                            std::pair<std::uint32_t, std::uint32_t>(std::min(a, b), std::max(a, b)));
}

// An edge of a piece of a cut face, off the intersection curves.
struct PieceEdge {
  std::uint64_t key;
  std::uint32_t operand_and_piece;  // operand in the top bit
  auto operator<=>(const PieceEdge&) const = default;
};

// Pieces of cut faces meet along point-id edges: sorted (edge, operand, piece) records
// pair them (few). Unites the pieces of one operand that share such an edge, and returns
// the records for the whole faces to find their neighbouring pieces in.
std::vector<PieceEdge> unite_cut_pieces(const Operands& ops, const Arrangement& arr, const SplitResult& split,
                                        std::span<const std::uint8_t> coincident, DisjointSets& patches) {
  const std::vector<SubFace>& subs = split.sub_faces;
  std::vector<PieceEdge> piece_edges;
  for (std::uint32_t f = 0; f < ops.face_count(); ++f) {
    if (!split.cut[f]) continue;
    const auto operand = static_cast<std::uint32_t>(ops.operand_of_face(f));
    for (std::uint32_t s = split.first_sub_face[f]; s < split.first_sub_face[f + 1]; ++s) {
      if (coincident[s]) continue;
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t a = subs[s].points[i], b = subs[s].points[(i + 1) % 3];
        if (on_intersection_curve(arr, split, a, b)) continue;
        piece_edges.push_back({undirected_edge_key(a, b), operand << 31 | s});
      }
    }
  }
  std::sort(piece_edges.begin(), piece_edges.end());
  for (std::size_t k = 1; k < piece_edges.size(); ++k)
    if (piece_edges[k].key == piece_edges[k - 1].key &&
        piece_edges[k].operand_and_piece >> 31 == piece_edges[k - 1].operand_and_piece >> 31)
      patches.unite(piece_edges[k].operand_and_piece & 0x7fffffffu, piece_edges[k - 1].operand_and_piece & 0x7fffffffu);
  return piece_edges;
}

// Whole faces meet their neighbours across input edges: the operands' edge table joins
// them directly, to a whole neighbour or to the piece of a cut one on that edge.
void unite_whole_faces(const Operands& ops, const Arrangement& arr, const SplitResult& split,
                       std::span<const std::uint8_t> coincident, std::span<const PieceEdge> piece_edges,
                       DisjointSets& patches) {
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
      if (on_intersection_curve(arr, split, a, b)) continue;
      if (!split.cut[g]) {
        if (f < g && !coincident[split.first_sub_face[g]]) patches.unite(s, split.first_sub_face[g]);
      } else if (const std::uint32_t piece = piece_on_edge(operand, undirected_edge_key(a, b)); piece != ~0u) {
        patches.unite(s, piece);
      }
    }
  }
}

// Sub-faces grouped into patches, patches in order of their lowest sub-face (deterministic).
struct Patches {
  std::vector<std::uint32_t> members;   // the sub-faces, patch by patch, increasing within a patch
  std::vector<std::uint32_t> begin;     // patch k: members[begin[k] .. begin[k + 1])
  std::vector<std::uint32_t> patch_of;  // per sub-face

  std::uint32_t count() const { return static_cast<std::uint32_t>(begin.size() - 1); }
  std::uint32_t first_member(std::uint32_t k) const { return members[begin[k]]; }
};

// Patches: sub-faces of one operand joined across edges that are not on an intersection
// curve.
Patches find_patches(const Operands& ops, const Arrangement& arr, const SplitResult& split,
                     std::span<const std::uint8_t> coincident) {
  const auto n = static_cast<std::uint32_t>(split.sub_faces.size());
  DisjointSets sets(n);
  const std::vector<PieceEdge> piece_edges = unite_cut_pieces(ops, arr, split, coincident, sets);
  unite_whole_faces(ops, arr, split, coincident, piece_edges, sets);

  std::vector<std::uint32_t> root(n);
  for (std::uint32_t s = 0; s < n; ++s) root[s] = sets.find(s);
  // Sub-faces grouped by root, in increasing index within a group (a counting sort: the
  // roots are sub-face indices).
  Patches patches;
  patches.members.resize(n);
  patches.patch_of.resize(n);
  std::vector<std::uint32_t> first_of_root(n + 1, 0);
  for (std::uint32_t s = 0; s < n; ++s) ++first_of_root[root[s] + 1];
  for (std::uint32_t r = 0; r < n; ++r) first_of_root[r + 1] += first_of_root[r];
  for (std::uint32_t s = 0; s < n; ++s) patches.members[first_of_root[root[s]]++] = s;
  for (std::uint32_t k = 0; k < n; ++k) {
    if (k == 0 || root[patches.members[k]] != root[patches.members[k - 1]]) patches.begin.push_back(k);
    patches.patch_of[patches.members[k]] = static_cast<std::uint32_t>(patches.begin.size() - 1);
  }
  patches.begin.push_back(n);
  return patches;
}

// Verdicts: -1 unknown, 0 outside, 1 inside the other solid.
using Verdict = std::int8_t;

// Seeds: an input vertex of the patch's own operand strictly outside the other solid's
// box is outside the other solid (comparisons of doubles: exact).
std::vector<Verdict> seed_verdicts(const Operands& ops, std::span<const SubFace> subs, const Patches& patches,
                                   std::span<const std::uint8_t> coincident) {
  auto strictly_outside = [](const BoundingBox& box, const Vec3& p) {
    return p.x < box.min.x || p.x > box.max.x || p.y < box.min.y || p.y > box.max.y || p.z < box.min.z ||
           p.z > box.max.z;
  };
  std::vector<Verdict> verdict(patches.count(), -1);
  for (std::uint32_t k = 0; k < patches.count(); ++k) {
    const std::uint32_t first = patches.first_member(k);
    if (coincident[first]) continue;
    const int operand = ops.operand_of_face(subs[first].face);
    const BoundingBox& other_box = ops.solid_box(1 - operand);
    for (std::uint32_t m = patches.begin[k]; m < patches.begin[k + 1] && verdict[k] < 0; ++m)
      for (std::uint32_t p : subs[patches.members[m]].points)
        if (p < ops.vertex_count() && ops.operand_of_vertex(p) == operand && strictly_outside(other_box, ops.vertex(p))) {
          verdict[k] = 0;
          break;
        }
  }
  return verdict;
}

// Patches on the two sides of a transversal crossing have opposite verdicts: per patch,
// the patches across from it.
std::vector<std::vector<std::uint32_t>> opposite_patches(const SplitResult& split, const Patches& patches,
                                                         std::span<const std::uint8_t> coincident) {
  std::vector<std::vector<std::uint32_t>> opposite(patches.count());
  for (auto [x, y] : split.opposite_sides) {
    if (coincident[x] || coincident[y]) continue;
    opposite[patches.patch_of[x]].push_back(patches.patch_of[y]);
    opposite[patches.patch_of[y]].push_back(patches.patch_of[x]);
  }
  return opposite;
}

// Exact ray parity against the other whole solid, for patches nothing else decides; the
// search tree over that solid is built on first use only. Counts its casts in `result`.
class PatchRays {
 public:
  PatchRays(const Operands& ops, const Arrangement& arr, std::span<const SubFace> subs, const Patches& patches,
            Classification& result)
      : ops_(ops), arr_(arr), subs_(subs), patches_(patches), result_(result) {}

  Verdict verdict(std::uint32_t k) {
    const std::uint32_t first = patches_.first_member(k);
    const int operand = ops_.operand_of_face(subs_[first].face);
    if (!rays_[operand]) rays_[operand].emplace(ops_.solid(1 - operand));
    ++result_.ray_casts;
    // Fast path: an input vertex of this operand in the patch, not on the other surface.
    for (std::uint32_t m = patches_.begin[k]; m < patches_.begin[k + 1]; ++m)
      for (std::uint32_t p : subs_[patches_.members[m]].points)
        if (p < ops_.vertex_count() && !arr_.on_both_surfaces[p] && ops_.operand_of_vertex(p) == operand)
          return rays_[operand]->inside(ops_.vertex(p));
    const geometry::ExactPoint p0 = arr_.points[subs_[first].points[0]].exact();
    const geometry::ExactPoint p1 = arr_.points[subs_[first].points[1]].exact();
    const geometry::ExactPoint p2 = arr_.points[subs_[first].points[2]].exact();
    const geometry::ExactPoint centroid{(p0.x + p1.x + p2.x) / 3, (p0.y + p1.y + p2.y) / 3,
                                        (p0.z + p1.z + p2.z) / 3};
    ++result_.exact_ray_casts;
    return rays_[operand]->inside(centroid);
  }

 private:
  const Operands& ops_;
  const Arrangement& arr_;
  std::span<const SubFace> subs_;
  const Patches& patches_;
  Classification& result_;
  std::optional<geometry::RayParity> rays_[2];
};

// One connected group of patches (joined by opposite-side relations) at a time: from
// its seeds, or else from one ray, the verdicts alternate across each crossing. A
// contradiction (possible only where the crossings are degenerate) sends every patch
// of the group to its own ray.
void propagate_verdicts(const Patches& patches, std::span<const std::uint8_t> coincident,
                        std::span<const std::vector<std::uint32_t>> opposite, PatchRays& rays,
                        std::vector<Verdict>& verdict) {
  const std::uint32_t patch_count = patches.count();
  std::vector<std::uint8_t> visited(patch_count, 0);
  std::vector<std::uint32_t> group, queue;
  for (std::uint32_t k = 0; k < patch_count; ++k) {
    if (visited[k] || coincident[patches.first_member(k)]) continue;
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
      verdict[group[0]] = rays.verdict(group[0]);
      queue.push_back(group[0]);
    }
    bool contradiction = false;
    for (std::size_t i = 0; i < queue.size() && !contradiction; ++i)
      for (std::uint32_t j : opposite[queue[i]]) {
        const auto flipped = static_cast<Verdict>(1 - verdict[queue[i]]);
        if (verdict[j] < 0) {
          verdict[j] = flipped;
          queue.push_back(j);
        } else if (verdict[j] != flipped) {
          contradiction = true;
          break;
        }
      }
    if (contradiction)
      for (std::uint32_t j : group) verdict[j] = rays.verdict(j);
  }
}

}  // namespace

Classification classify_sub_faces(const Operands& ops, const Arrangement& arr, const SplitResult& split) {
  const std::vector<SubFace>& subs = split.sub_faces;
  Classification result;
  const auto n = static_cast<std::uint32_t>(subs.size());
  result.side.assign(n, Side::outside);
  const std::vector<std::uint8_t> coincident = mark_coincident(ops, arr, subs, result.side);
  const Patches patches = find_patches(ops, arr, split, coincident);
  std::vector<Verdict> verdict = seed_verdicts(ops, subs, patches, coincident);
  const std::vector<std::vector<std::uint32_t>> opposite = opposite_patches(split, patches, coincident);
  PatchRays rays(ops, arr, subs, patches, result);
  propagate_verdicts(patches, coincident, opposite, rays, verdict);
  for (std::uint32_t s = 0; s < n; ++s)
    if (!coincident[s]) result.side[s] = verdict[patches.patch_of[s]] == 1 ? Side::inside : Side::outside;
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
