// The cleanup's strategies (paper §2.5): each proposes edits around a distorted face and
// makes the best that passes the rules (cleanup_worker.cpp), or, for a compound edit,
// makes its steps and keeps them only as a whole. improve_face tries them in order.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <tuple>
#include <type_traits>

#include "common/binned_median.hpp"
#include "common/parallel_threshold.hpp"
#include "surface/cleanup_rules.hpp"
#include "surface/cleanup_worker.hpp"

namespace molsurf::surface_cleanup {

namespace {

// Whether every tag of x is one of y's (both sorted).
bool within(const std::vector<std::int32_t>& x, const std::vector<std::int32_t>& y) {
  return std::includes(y.begin(), y.end(), x.begin(), x.end());
}

// take(a, b) for every edge (a, b) of every living face, in its face's direction, in
// parallel; what it returns (an optional) gathered from all threads, in an order that
// depends on them: the caller sorts it.
template <class Take>
auto gather_edges(const Mesh& m, const MeshEditor& editor, Take take) {
  using Value = typename std::invoke_result_t<Take, Index, Index>::value_type;
  std::vector<Value> out;
  const auto nf = static_cast<std::int64_t>(m.faces.size());
#pragma omp parallel if (nf >= kParallelMinItems)
  {
    std::vector<Value> part;
#pragma omp for schedule(static) nowait
    for (std::int64_t f = 0; f < nf; ++f) {
      if (!editor.alive(static_cast<std::uint32_t>(f))) continue;
      const Triangle& t = m.faces[f];
      for (int i = 0; i < 3; ++i)
        if (auto value = take(t[i], t[(i + 1) % 3])) part.push_back(*value);
    }
#pragma omp critical(molsurf_cleanup_edges)
    out.insert(out.end(), part.begin(), part.end());
  }
  return out;
}

std::array<double, 3> edge_lengths(const Mesh& m, const Triangle& t) {
  std::array<double, 3> length;
  for (int i = 0; i < 3; ++i) length[i] = norm(m.vertices[t[(i + 1) % 3]] - m.vertices[t[i]]);
  return length;
}

}  // namespace

// One distorted face: the strategies in turn, until one makes an edit. Single edits
// first (the collapses of its short edges and the flips of its edges, best first); then
// the compound ones (a cluster of vertices merged, a neck widened, a collapse cleared of
// what blocks it); last, a move of one of its corners.
bool Cleaner::improve_face(std::uint32_t f) {
  using Strategy = bool (Cleaner::*)(std::uint32_t);
  static constexpr std::array<Strategy, 5> kStrategies{&Cleaner::collapse_or_flip, &Cleaner::merge_cluster,
                                                       &Cleaner::widen_neck, &Cleaner::unblock_collapse,
                                                       &Cleaner::move_corner};
  for (const Strategy strategy : kStrategies)
    if ((this->*strategy)(f)) return true;
  return false;
}

// The tags of the faces around v, sorted and unique (one tag: not on a seam).
std::vector<std::int32_t> Cleaner::tags_of(Index v) const {
  std::vector<std::int32_t> tags;
  for (std::uint32_t f : editor_.faces_of(v)) tags.push_back(m_.tag(f));
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  return tags;
}

// The collapses of edge ab (faces `on_edge`, link condition checked): onto a, onto b and
// to the midpoint, ranked by whether the seams stay; those `keep` accepts (after
// measuring them) go to `out`.
template <class Keep>
void Cleaner::collapse_options(Index a, Index b, const std::vector<std::uint32_t>& on_edge, std::vector<Option>& out,
                               Keep&& keep) const {
  const std::vector<std::int32_t> tags_a = tags_of(a), tags_b = tags_of(b);
  const Vec3 pa = m_.vertices[a], pb = m_.vertices[b];
  auto add = [&](Index u, Index v, const Vec3& target, int rank) {
    Option o{editor_.collapse(u, v, on_edge, target)};
    o.rank = rank;
    if (keep(o)) out.push_back(std::move(o));
  };
  add(a, b, pa, within(tags_b, tags_a) ? 0 : 1);
  add(b, a, pb, within(tags_a, tags_b) ? 0 : 1);
  add(a, b, 0.5 * (pa + pb), tags_a == tags_b ? 0 : 1);
}

// The collapses of the face's short edges (to either end or the midpoint) and the flips
// of its edges: the best that passes.
bool Cleaner::collapse_or_flip(std::uint32_t f) {
  const Triangle t = m_.faces[f];
  const std::array<double, 3> length = edge_lengths(m_, t);
  const int longest = static_cast<int>(std::max_element(length.begin(), length.end()) - length.begin());
  std::vector<Option> options;
  for (int i = 0; i < 3; ++i) {
    if (i != longest && length[i] <= kShortEdgeFraction * length[longest]) {
      const Index a = t[i], b = t[(i + 1) % 3];
      const std::vector<std::uint32_t> on_edge = editor_.faces_on_edge(a, b);
      if (on_edge.size() != 2 || !editor_.link_condition(a, b, on_edge)) continue;
      collapse_options(a, b, on_edge, options, [&](Option& o) { return evaluate(o); });
    }
  }
  for (int i = 0; i < 3; ++i) {
    Option o = flip(f, t[i], t[(i + 1) % 3]);
    if (!o.edit.empty() && evaluate(o)) options.push_back(std::move(o));
  }
  return try_best(options);
}

// A sliver whose short edge belongs to a cluster of vertices much closer to each other
// than to the rest (typically around a point where three spheres meet) often has no
// single collapse that keeps the link condition or improves the angles: the cluster
// merges into one vertex, edge by edge (each step under every validity check), and the
// whole is kept only if the worst angle among the faces it touched got better.
bool Cleaner::merge_cluster(std::uint32_t f) {
  const Triangle t = m_.faces[f];
  const std::array<double, 3> length = edge_lengths(m_, t);
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int x, int y) { return length[x] < length[y]; });
  const double tiny = kClusterFraction * length[order[1]];
  if (!(length[order[0]] <= tiny)) return false;
  std::vector<Index> cluster{t[order[0]]};
  for (std::size_t k = 0; k < cluster.size() && cluster.size() <= kMaxCluster; ++k)
    for (Index w : editor_.neighbours(cluster[k]))
      if (std::find(cluster.begin(), cluster.end(), w) == cluster.end() &&
          norm(m_.vertices[w] - m_.vertices[cluster[k]]) <= tiny)
        cluster.push_back(w);
  if (cluster.size() < 2 || cluster.size() > kMaxCluster) return false;
  // Everything merges into the vertex on the most seams (the junction), which stays.
  Index keep = cluster[0];
  std::size_t most = 0;
  for (Index v : cluster)
    if (const std::size_t n = tags_of(v).size(); n > most) {
      most = n;
      keep = v;
    }
  std::vector<Index> rest;
  for (Index v : cluster)
    if (v != keep) rest.push_back(v);
  std::stable_sort(rest.begin(), rest.end(), [&](Index x, Index y) {
    return norm(m_.vertices[x] - m_.vertices[keep]) < norm(m_.vertices[y] - m_.vertices[keep]);
  });

  open_compound();
  bool any = false;
  for (bool progress = true; progress && !rest.empty();) {
    progress = false;
    for (auto it = rest.begin(); it != rest.end(); ++it) {
      const std::vector<std::uint32_t> on_edge = editor_.faces_on_edge(keep, *it);
      if (on_edge.size() != 2 || !editor_.link_condition(keep, *it, on_edge)) continue;
      Option o{editor_.collapse(keep, *it, on_edge, m_.vertices[keep])};
      if (!evaluate(o, false) || !fits(o)) continue;
      commit(o);
      any = true;
      rest.erase(it);
      progress = true;
      break;
    }
  }
  return keep_if_better(any);
}

// A sliver on a neck. Where two spheres barely overlap, the surface runs through a loop
// of three edges far shorter than the faces around it (a 3-cycle that is not a face),
// and the faces on the loop are needles that no collapse may shorten (each would pinch
// the neck: the link condition fails) and no flip may fix. The loop widens about its
// centre until its edges are half as long as the edges leaving it, one corner at a time
// under every validity check, and the whole is kept only if the worst angle among the
// faces it touched got better.
bool Cleaner::widen_neck(std::uint32_t f) {
  const Triangle t = m_.faces[f];
  double longest = 0;
  for (int i = 0; i < 3; ++i) longest = std::max(longest, norm(m_.vertices[t[(i + 1) % 3]] - m_.vertices[t[i]]));
  const double short_edge = kNeckFraction * longest;
  for (int i = 0; i < 3; ++i) {
    const Index a = t[i], b = t[(i + 1) % 3];
    if (!(norm(m_.vertices[b] - m_.vertices[a]) <= short_edge)) continue;
    std::vector<Index> opposite;
    for (std::uint32_t g : editor_.faces_on_edge(a, b))
      for (Index w : m_.faces[g])
        if (w != a && w != b) opposite.push_back(w);
    const std::vector<Index> around_a = editor_.neighbours(a);
    const std::vector<Index> around_b = editor_.neighbours(b);
    for (Index w : around_a) {
      if (std::find(opposite.begin(), opposite.end(), w) != opposite.end() ||
          !std::binary_search(around_b.begin(), around_b.end(), w))
        continue;
      if (norm(m_.vertices[w] - m_.vertices[a]) <= short_edge && norm(m_.vertices[w] - m_.vertices[b]) <= short_edge &&
          widen_loop({a, b, w}))
        return true;
    }
  }
  return false;
}

bool Cleaner::widen_loop(const std::array<Index, 3>& loop) {
  Vec3 centre;
  double size = 0, leaving = 0;
  std::size_t leaving_count = 0;
  for (int k = 0; k < 3; ++k) {
    centre += m_.vertices[loop[k]] / 3.0;
    size = std::max(size, norm(m_.vertices[loop[(k + 1) % 3]] - m_.vertices[loop[k]]));
    for (Index w : editor_.neighbours(loop[k]))
      if (std::find(loop.begin(), loop.end(), w) == loop.end()) {
        leaving += norm(m_.vertices[w] - m_.vertices[loop[k]]);
        ++leaving_count;
      }
  }
  if (leaving_count == 0 || !(size > 0)) return false;
  const double full = kNeckWidth * leaving / static_cast<double>(leaving_count) / size;
  // Less widening where the full width turns a face too far or meets another.
  for (const double factor : {full, full / 3, full / 10}) {
    if (!(factor > 1)) return false;
    open_compound();
    bool ok = true;
    for (Index v : loop) {
      Option o{editor_.move(v, centre + factor * (m_.vertices[v] - centre))};
      if (!evaluate(o, false) || !fits(o)) {
        ok = false;
        break;
      }
      commit(o);
    }
    if (keep_if_better(ok)) return true;
  }
  return false;
}

// A sliver whose short edge ab fails the link condition only because a and b have a
// common neighbour beyond the edge's two faces (a fold, or a small tetrahedral pocket
// around a point where spheres meet: the usual case at scale). The obstacle is first
// taken out of the way, one step at a time: a vertex with three faces, across the edge
// or in the way, is removed (its three faces become one); else edge aw or bw to a
// vertex w in the way flips. Then ab collapses. Every step is under every validity
// check, and the whole is kept only if the worst angle among the faces it touched got
// better.
bool Cleaner::unblock_collapse(std::uint32_t f) {
  const Triangle t = m_.faces[f];
  const std::array<double, 3> length = edge_lengths(m_, t);
  const int longest = static_cast<int>(std::max_element(length.begin(), length.end()) - length.begin());
  for (int i = 0; i < 3; ++i) {
    if (i == longest || !(length[i] <= kShortEdgeFraction * length[longest])) continue;
    const Index a = t[i], b = t[(i + 1) % 3];
    if (editor_.blocking_vertices(a, b).empty()) continue;
    open_compound();
    const bool ok = clear_collapse(a, b) && collapse_cleared(a, b);
    if (keep_if_better(ok)) return true;
  }
  return false;
}

// The steps that take what blocks edge ab's collapse out of the way; whether they
// cleared it.
bool Cleaner::clear_collapse(Index a, Index b) {
  for (std::size_t step = 0;; ++step) {
    const std::vector<Index> blocking = editor_.blocking_vertices(a, b);
    if (blocking.empty()) return true;
    if (step == kMaxUnblockSteps || blocking.size() > kMaxUnblockSteps) return false;
    std::vector<Option> steps;
    for (std::uint32_t g : editor_.faces_on_edge(a, b))
      for (Index o : m_.faces[g])
        if (o != a && o != b && editor_.faces_of(o).size() == 3) steps.push_back({editor_.remove_valence_three(o)});
    for (Index w : blocking) {
      if (editor_.faces_of(w).size() == 3) steps.push_back({editor_.remove_valence_three(w)});
      for (Index end : {a, b})
        if (const std::vector<std::uint32_t> on = editor_.faces_on_edge(end, w); on.size() == 2)
          steps.push_back(flip(on[0], end, w));
    }
    bool stepped = false;
    for (Option& o : steps)
      if (!o.edit.empty() && evaluate(o, false) && fits(o)) {
        commit(o);
        stepped = true;
        break;
      }
    if (!stepped) return false;
  }
}

// The collapse of edge ab once nothing blocks it: onto either end or the midpoint, the
// best angle that passes.
bool Cleaner::collapse_cleared(Index a, Index b) {
  const std::vector<std::uint32_t> on_edge = editor_.faces_on_edge(a, b);
  if (on_edge.size() != 2 || !editor_.link_condition(a, b, on_edge)) return false;
  const Vec3 pa = m_.vertices[a], pb = m_.vertices[b];
  std::vector<Option> collapses;
  for (auto [u, v, target] : {std::tuple{a, b, pa}, std::tuple{b, a, pb}, std::tuple{a, b, 0.5 * (pa + pb)}}) {
    Option o{editor_.collapse(u, v, on_edge, target)};
    if (evaluate(o, false)) collapses.push_back(std::move(o));
  }
  std::stable_sort(collapses.begin(), collapses.end(), [](const Option& x, const Option& y) { return x.after > y.after; });
  for (const Option& o : collapses)
    if (fits(o)) {
      commit(o);
      return true;
    }
  return false;
}

// Flip of edge ab of face f: f and the face g across it become the two faces on the
// other diagonal cd. Empty (no edit) when the edge cannot flip.
Option Cleaner::flip(std::uint32_t f, Index a, Index b) const {
  Option o;
  const std::vector<std::uint32_t> on = editor_.faces_on_edge(a, b);
  if (on.size() != 2) return o;
  const std::uint32_t g = on[0] == f ? on[1] : on[0];
  const Triangle tf = m_.faces[f], tg = m_.faces[g];
  Index c = 0, d = 0;
  for (Index w : tf)
    if (w != a && w != b) c = w;
  for (Index w : tg)
    if (w != a && w != b) d = w;
  if (editor_.joined(c, d)) return o;  // the new edge cd must not exist yet
  // Nearly coplanar faces only; across a seam (different tags) nearer still. A cap on
  // the edge (c within a sliver's height of ab, between a and b) has no meaningful
  // normal of its own: the new faces lie along g's plane and keep to g's normal.
  const bool same_tag = m_.tag(f) == m_.tag(g);
  const double min_cos = same_tag ? kSameTagFlipCos : kCrossTagFlipCos;
  const Vec3 old_f = editor_.normal(tf), old_g = editor_.normal(tg);
  const Vec3 ab = m_.vertices[b] - m_.vertices[a], ac = m_.vertices[c] - m_.vertices[a];
  const double ab2 = dot(ab, ab), along = dot(ac, ab);
  const bool cap = norm(old_f) < kCapHeight * ab2 && along > 0 && along < ab2;
  if (!cap && !(dot(old_f, old_g) > min_cos * norm(old_f) * norm(old_g))) return o;
  const Vec3 mean = cap ? old_g : old_f / std::max(norm(old_f), 1e-300) + old_g / std::max(norm(old_g), 1e-300);
  o.edit = editor_.flip(f, g, c, d, mean);
  o.rank = same_tag ? 0 : 1;
  return o;
}

// A move of one of the face's corners: the best that passes.
bool Cleaner::move_corner(std::uint32_t f) {
  const Triangle t = m_.faces[f];
  std::vector<Option> options;
  for (Index v : t) move_candidates(v, options);
  return try_best(options);
}

// Where v may go to improve its faces: toward the centre of its neighbours, within the
// plane tangent to the surface there; a seam vertex only along its seam.
void Cleaner::move_candidates(Index v, std::vector<Option>& out) const {
  const std::vector<std::int32_t> tags = tags_of(v);
  if (tags.size() > 2) return;  // where three spheres meet: stays
  const Vec3 p = m_.vertices[v];
  Vec3 step;
  if (tags.size() == 1) {
    Vec3 n, centre;
    const std::vector<Index> ring = editor_.neighbours(v);
    for (std::uint32_t g : editor_.faces_of(v)) n += editor_.normal(m_.faces[g]);
    for (Index w : ring) centre += m_.vertices[w];
    centre = centre / static_cast<double>(ring.size());
    const double nn = dot(n, n);
    if (!(nn > 0)) return;
    // Only where the surface is smooth: a corner or crease (of an untagged mesh) stays.
    for (std::uint32_t g : editor_.faces_of(v)) {
      const Vec3 ng = editor_.normal(m_.faces[g]);
      if (!(dot(ng, n) > kSmoothCos * norm(ng) * std::sqrt(nn))) return;
    }
    step = centre - p;
    step -= n * (dot(step, n) / nn);
  } else {
    // The two neighbours along the seam: edges whose two faces have different tags.
    std::vector<Index> along;
    for (Index w : editor_.neighbours(v)) {
      const std::vector<std::uint32_t> on = editor_.faces_on_edge(v, w);
      if (on.size() == 2 && m_.tag(on[0]) != m_.tag(on[1])) along.push_back(w);
    }
    if (along.size() != 2) return;
    const Vec3 s = m_.vertices[along[1]] - m_.vertices[along[0]];
    const Vec3 centre = 0.5 * (m_.vertices[along[0]] + m_.vertices[along[1]]);
    const double ss = dot(s, s);
    if (!(ss > 0)) return;
    step = s * (dot(centre - p, s) / ss);
  }
  for (double fraction : {1.0, 0.5, 0.25}) {
    Option o{editor_.move(v, p + fraction * step)};
    o.rank = tags.size() == 1 ? 0 : 1;
    if (!(o.edit.target == p) && evaluate(o)) out.push_back(std::move(o));
  }
}

// Edges far shorter than the surface's typical edge (under min_edge_fraction of the
// median) are collapsed, shortest first, even where their faces' angles are fine: a
// mesher's boundary recovery (gmsh's, tetgen's) works in floating point and takes the
// faces around such an edge for overlapping. A collapse here may not make the worst
// angle it touches worse than it was or than the angle target; every other rule of an
// edit holds (link condition, no face turned, budgets, the exact crossing test).
std::vector<ShortEdge> Cleaner::short_edges(double floor) const {
  // Each edge once, from the face that runs it upward; squared lengths first (the root
  // only below the floor's square, widened past its rounding), sorted after.
  const double floor2 = floor * floor * (1 + 1e-12);
  auto out = gather_edges(m_, editor_, [&](Index a, Index b) -> std::optional<ShortEdge> {
    // Between two frozen vertices no collapse can be made: not listed, so a block's SES
    // piece, frozen but for its own atoms' faces, does not try each of them in vain.
    if (a > b || (editor_.frozen(a) && editor_.frozen(b))) return std::nullopt;
    const Vec3 d = m_.vertices[b] - m_.vertices[a];
    if (!(dot(d, d) < floor2)) return std::nullopt;
    if (const double length = norm(d); length < floor) return std::pair{length, std::array<Index, 2>{a, b}};
    return std::nullopt;
  });
  std::sort(out.begin(), out.end());
  return out;
}

double Cleaner::short_edge_floor() const {
  // The median edge from squared lengths (the root of the median square is the median
  // length): the same in any order. Each edge once, from the face that runs it upward.
  const double median2 =
      binned_median(static_cast<std::int64_t>(m_.faces.size()), [&](std::int64_t f, auto&& visit) {
        if (!editor_.alive(static_cast<std::uint32_t>(f))) return;
        const Triangle& t = m_.faces[f];
        for (int i = 0; i < 3; ++i)
          if (const Index a = t[i], b = t[(i + 1) % 3]; a < b) {
            const Vec3 d = m_.vertices[b] - m_.vertices[a];
            visit(dot(d, d));
          }
      });
  if (std::isnan(median2)) return 0;
  return std::max(options_.min_edge_fraction * std::sqrt(median2), options_.min_edge_length);
}

void Cleaner::shorten(Index a, Index b, double floor, std::uint32_t position) {
  if (!(norm(m_.vertices[b] - m_.vertices[a]) < floor)) return;  // an earlier collapse moved it
  const std::vector<std::uint32_t> on_edge = editor_.faces_on_edge(a, b);
  if (on_edge.size() != 2 || !editor_.link_condition(a, b, on_edge)) return;
  deferred_ = false;
  std::vector<Option> options;
  collapse_options(a, b, on_edge, options, [&](Option& o) {
    return evaluate(o, false) && o.after >= std::min(o.before, options_.min_angle_deg) && o.after > kSmallestNewAngle;
  });
  if (try_best(options))
    ++result_.done;
  else if (deferred_)
    result_.deferred.push_back(position);
  else
    ++result_.refused;
}

}  // namespace molsurf::surface_cleanup
