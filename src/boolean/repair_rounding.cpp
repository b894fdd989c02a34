#include "boolean/repair_rounding.hpp"

#include <algorithm>
#include <limits>
#include <initializer_list>
#include <array>
#include <tuple>
#include <cmath>

#include "geometry/predicates.hpp"
#include "geometry/triangle_intersection.hpp"
#include "mesh/mesh_editor.hpp"
#include "mesh/topology.hpp"

namespace molsurf::boolean_engine {

namespace {

// Rounding a point to doubles moves it by up to half an ulp of its coordinates (about 1e-16
// relative). Only two kinds of faces can be turned over by that: slivers, whose smallest
// angle is below kSliverDeg, and tiny faces, whose height is within kTinyUlps ulps of their
// coordinates (where two solids' nearly coincident vertices meet, e.g. two crossing
// cylinders whose rings meet at a point). Both select which faces get the exact crossing
// test; they decide nothing.
constexpr double kSliverDeg = 0.1;
constexpr double kTinyUlps = 64;

// Smallest angle below kSliverDeg, without trigonometry: the smallest angle lies opposite
// the shortest edge, and its sine is |cross| over the
// product of the two longer edges. Only selects faces for exact tests.
bool is_sliver(const Mesh& m, const Triangle& t) {
  const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
  double l[3] = {dot(b - a, b - a), dot(c - b, c - b), dot(a - c, a - c)};
  std::sort(l, l + 3);
  const Vec3 n = cross(b - a, c - a);
  const double cross2 = dot(n, n);
  static const double sine = std::sin(kSliverDeg * 3.141592653589793 / 180);
  return cross2 < sine * sine * l[1] * l[2] * (1 + 1e-9);
}

bool is_tiny(const Mesh& m, const Triangle& t) {
  const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
  double scale = 0;
  for (const Vec3* p : {&a, &b, &c}) scale = std::max({scale, std::fabs(p->x), std::fabs(p->y), std::fabs(p->z)});
  const double ulp = scale * std::numeric_limits<double>::epsilon(), reach = kTinyUlps * ulp;
  const double longest2 = std::max({dot(b - a, b - a), dot(c - b, c - b), dot(a - c, a - c)});
  const Vec3 n = cross(b - a, c - a);
  return dot(n, n) < reach * reach * longest2;  // height = |n| / longest edge
}


bool degenerate(const Mesh& m, const Triangle& t) {
  if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
  return geometry::collinear3d(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
}

// Strictly between a and b on their common line (collinearity assumed).
bool strictly_between(const Vec3& a, const Vec3& x, const Vec3& b) {
  for (int axis = 0; axis < 3; ++axis) {
    if (a[axis] == b[axis]) continue;
    return (a[axis] < x[axis] && x[axis] < b[axis]) || (b[axis] < x[axis] && x[axis] < a[axis]);
  }
  return false;
}

// What rounding can have broken: a face with a rounded corner that is degenerate or that
// rounding can have turned over (a face of input corners only is a piece of a valid input
// face).
bool needs_repair(const Mesh& m, const Triangle& t, const std::vector<std::uint8_t>& rounded) {
  if (!rounded[t[0]] && !rounded[t[1]] && !rounded[t[2]]) return false;
  return may_turn_over(m, t) || degenerate(m, t);
}

// The repair, on the editing layer (src/mesh/mesh_editor.hpp): what it finds broken and
// which edit it tries for each; the layer makes, checks and undoes the edits.
class Repairer {
 public:
  // Indexes only the faces that rounding can have touched: those with a rounded corner,
  // and every face around their corners (what collapses, flips and crossing tests read).
  Repairer(Mesh& m, std::vector<std::uint8_t>& operand, std::vector<std::uint32_t>& source,
           const std::vector<std::uint8_t>& needs_repair, const std::vector<std::uint8_t>& frozen,
           const RepairOptions& options)
      : m_(m), operand_(operand), source_(source), options_(options), editable_(m, frozen), editor_(editable_) {
    // Only faces near the ones rounding can have broken (degenerate faces, and slivers
    // with a rounded corner) are indexed: three rings of faces around them, so the link
    // condition, the moves of a collapse and the crossing counts around it (two rings)
    // all see every face they read. The rings grow face-parallel: a face joins when a
    // corner is marked, then its corners are marked.
    const auto nf = static_cast<std::int64_t>(m.faces.size());
    std::vector<std::uint8_t> mark(m.vertices.size(), 0), in_ring(m.faces.size(), 0);
    for (std::size_t f = 0; f < m.faces.size(); ++f)
      if (needs_repair[f])
        for (Index v : m.faces[f]) mark[v] = 1;
    for (int ring = 0; ring < 3; ++ring) {
#pragma omp parallel for schedule(static)
      for (std::int64_t f = 0; f < nf; ++f) {
        const Triangle& t = m.faces[f];
        in_ring[f] = mark[t[0]] || mark[t[1]] || mark[t[2]];
      }
      for (std::size_t f = 0; f < m.faces.size(); ++f)
        if (in_ring[f])
          for (Index v : m.faces[f]) mark[v] = 1;
    }
    for (std::uint32_t f = 0; f < m.faces.size(); ++f) {
      const Triangle& t = m.faces[f];
      if (mark[t[0]] || mark[t[1]] || mark[t[2]]) indexed_.push_back(f);
    }
    for (std::uint32_t f : indexed_) editable_.index(f);
    editor_.count_flat_folds(options.flat_folds);
  }

  RepairOutcome run(const std::vector<std::uint8_t>& rounded) {
    for (int pass = 0; pass < 8; ++pass) {
      bool changed = false;
      for (std::uint32_t f : candidates())
        if (editor_.alive(f) && degenerate(m_, m_.faces[f])) changed |= repair(f);
      if (!changed) break;
    }
    if (options_.nudge_every_fold) nudge_folds(rounded);
    // Folds: a face with a rounded corner that crosses a face sharing a corner with it, or
    // a sliver whose neighbours cross the face across its longest edge.
    for (int pass = 0; pass < 8; ++pass) {
      bool changed = false;
      for (std::uint32_t f : candidates()) {
        if (!editor_.alive(f)) continue;
        const Triangle& t = m_.faces[f];
        if (!rounded[t[0]] && !rounded[t[1]] && !rounded[t[2]]) continue;
        if (!may_turn_over(m_, t)) continue;  // rounding (~1e-16) cannot turn it over
        if (crosses_a_neighbour(f) || sides_cross_across(f, rounded)) changed |= unfold(f, rounded);
      }
      if (!changed) break;
    }
    if (options_.collapse_tiny_edges) collapse_tiny_edges(rounded);
    std::size_t left = 0;
    for (std::uint32_t f : candidates()) left += editor_.alive(f) && degenerate(m_, m_.faces[f]);
    compact();
    return {left, editor_.refused_frozen(), std::move(collapsed_)};
  }

  // A face with a rounded corner that crosses a face sharing a corner with it, whatever
  // its shape. In a merge of the pairwise surface method an edge between two rounded
  // points can lie exactly in the plane of a face of the other operand that earlier
  // roundings tilted by 1e-16, and rounding moves the edge through that face although
  // neither face is a sliver (the fold pass in run() looks at slivers and tiny faces only).
  // Each rounded corner of such a face is rounded again (checked_nudge: a neighbouring
  // double, kept only when that leaves fewer exact crossings around it), before the folds
  // of slivers get the larger changes.
  void nudge_folds(const std::vector<std::uint8_t>& rounded) {
    for (int pass = 0; pass < 8; ++pass) {
      bool changed = false;
      for (std::uint32_t f : candidates()) {
        if (!editor_.alive(f)) continue;
        const Triangle& t = m_.faces[f];
        if ((!rounded[t[0]] && !rounded[t[1]] && !rounded[t[2]]) || !crosses_a_neighbour(f)) continue;
        for (Index v : t)
          if (rounded[v] && checked_nudge(v)) {
            changed = true;
            break;
          }
      }
      if (!changed) break;
    }
  }

  // Edges within a rounding error of zero length at a rounded point (kTinyUlps ulps of
  // their coordinates: the length only selects). After a merge of the pairwise surface
  // method, points that were one point of the input (exact x = 0 on a lattice) can be
  // found a rounding error apart, because the operands were rounded by earlier merges: a
  // run of vertices 1e-18 apart on one line, a cluster a few ulps wide with a fan of
  // nearly collinear edges to it. The result is valid, but the next merge cuts those
  // slivers into pieces that its own rounding cannot keep apart (crossings, collinear
  // faces), or meets two sheets touching along them (two points at one place). Once the
  // result is valid, each such edge is collapsed, the rounded end merged into the other
  // (an input vertex stays), when the collapse is valid (link condition, no face made
  // degenerate or turned over) and leaves no exact crossing around the kept vertex; the
  // surface moves by the edge's length. Passes until nothing changes, shortest edges first.
  void collapse_tiny_edges(const std::vector<std::uint8_t>& rounded) {
    for (int pass = 0; pass < 8; ++pass) {
      std::vector<std::tuple<double, Index, Index>> tiny;
      for (std::uint32_t f : candidates()) {
        if (!editor_.alive(f)) continue;
        const Triangle& t = m_.faces[f];
        for (int i = 0; i < 3; ++i) {
          const Index u = t[i], v = t[(i + 1) % 3];
          if (u > v || (!rounded[u] && !rounded[v])) continue;  // each edge once, from its lower end
          const Vec3 &a = m_.vertices[u], &b = m_.vertices[v];
          const double scale = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z), std::fabs(b.x),
                                         std::fabs(b.y), std::fabs(b.z)});
          const double length = norm(b - a), reach = kTinyUlps * scale * std::numeric_limits<double>::epsilon();
          if (length <= reach) tiny.emplace_back(length, u, v);
        }
      }
      std::sort(tiny.begin(), tiny.end());
      tiny.erase(std::unique(tiny.begin(), tiny.end()), tiny.end());
      bool changed = false;
      for (const auto& [length, u, v] : tiny) {
        if (editor_.faces_of(u).empty() || editor_.faces_of(v).empty()) continue;  // merged away in this pass
        // Keep an input vertex where there is one: it is exact.
        const bool keep_u = !rounded[u] || rounded[v];
        if (checked_collapse(keep_u ? u : v, keep_u ? v : u, /*optional=*/true) ||
            (rounded[u] && rounded[v] && checked_collapse(keep_u ? v : u, keep_u ? u : v, /*optional=*/true)))
          changed = true;
      }
      if (!changed) break;
    }
  }

  // Indexed faces and faces added since (flips), in order.
  std::vector<std::uint32_t> candidates() const {
    std::vector<std::uint32_t> out = indexed_;
    for (std::uint32_t f = editable_.first_added(); f < m_.faces.size(); ++f) out.push_back(f);
    return out;
  }

 private:
  bool repair(std::uint32_t f) {
    const Triangle t = m_.faces[f];
    for (int i = 0; i < 3; ++i) {
      const Index u = t[i], v = t[(i + 1) % 3];
      if (u != v && m_.vertices[u] == m_.vertices[v]) return collapse(u, v) || unblocked_collapse(u, v);
    }
    for (int i = 0; i < 3; ++i) {
      const Index c = t[i], a = t[(i + 1) % 3], b = t[(i + 2) % 3];
      if (strictly_between(m_.vertices[a], m_.vertices[c], m_.vertices[b])) return flip(f, a, b, c);
    }
    return false;
  }

  // The corner of the face on edge ab other than a and b (`none` if it has none).
  Index third_corner(std::uint32_t g, Index a, Index b, Index none) const {
    Index x = none;
    for (Index w : m_.faces[g])
      if (w != a && w != b) x = w;
    return x;
  }

  // A zero-length edge uv whose collapse fails the link condition only because u and v
  // have a common neighbour w beyond the edge's two faces (a vertex with four faces whose
  // position equals its neighbour's): edge vw or uw is flipped out of the way first, when
  // that makes no face degenerate and leaves no more exact crossings around it, then uv
  // collapses. If it still cannot, the flips are undone.
  bool unblocked_collapse(Index u, Index v) {
    editor_.open_journal();
    for (int step = 0; step < 3; ++step) {
      const std::vector<Index> blocking = editor_.blocking_vertices(u, v);
      if (blocking.empty()) break;
      bool flipped = false;
      for (std::size_t k = 0; k < blocking.size() && !flipped; ++k)
        for (const Index end : {v, u}) {
          const Index w = blocking[k];
          const std::vector<std::uint32_t> on = editor_.faces_on_edge(end, w);
          if (on.size() != 2 || editor_.touches_frozen({end, w})) continue;
          const Index c = third_corner(on[0], end, w, end), d = third_corner(on[1], end, w, end);
          if (c == end || d == end || c == d || !editor_.faces_on_edge(c, d).empty() || editor_.touches_frozen({c, d}))
            continue;
          if (geometry::collinear3d(m_.vertices[end], m_.vertices[c], m_.vertices[d]) ||
              geometry::collinear3d(m_.vertices[w], m_.vertices[c], m_.vertices[d]))
            continue;
          const std::size_t before = editor_.crossings_around({end, w, c, d});
          editor_.commit(editor_.flip_appending(on[0], on[1], c, d));
          if (editor_.crossings_around({end, w, c, d}) <= before) {
            flipped = true;
            break;
          }
          editor_.undo_last();
        }
      if (!flipped) break;
    }
    const bool collapsed = !editor_.journal_empty() && collapse(u, v);
    if (!collapsed)
      while (!editor_.journal_empty()) editor_.undo_last();
    editor_.close_journal();
    return collapsed;
  }

  geometry::TrianglePairRelation relation(const Triangle& a, const Triangle& b) const {
    return geometry::classify_triangle_pair(m_, a, b);
  }

  // Crossing a face that shares a corner with f; for a sliver (smallest angle under 0.1
  // degree: rounding can turn it over) also a face two rings away. The angle only selects
  // what is tested; the test itself is exact.
  bool crosses_a_neighbour(std::uint32_t f) const {
    const Triangle& t = m_.faces[f];
    const bool sliver = may_turn_over(m_, t);
    std::vector<std::uint32_t> ring;
    auto faces_around = [&](Index v, std::vector<std::uint32_t>& out) {
      const auto around = editor_.faces_of(v);
      out.insert(out.end(), around.begin(), around.end());
    };
    for (Index v : t) faces_around(v, ring);
    if (sliver) {
      const std::size_t first_ring = ring.size();
      for (std::size_t k = 0; k < first_ring; ++k)
        for (Index v : m_.faces[ring[k]]) faces_around(v, ring);
    }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    for (std::uint32_t g : ring)
      if (g != f && editor_.alive(g) && editor_.folds(t, m_.faces[g])) return true;
    return false;
  }

  // A sliver along a crease, turned over by rounding its apex (the corner opposite its
  // longest edge): it crosses nothing itself, but the faces across its two short edges now
  // poke through the face across its longest edge, 1e-16 from that edge. Exact.
  bool sides_cross_across(std::uint32_t f, const std::vector<std::uint8_t>& rounded) const {
    const auto [a, b, c] = longest_edge(m_.faces[f]);
    if (!rounded[c]) return false;
    auto across = [&](Index u, Index v) -> std::uint32_t {
      const std::vector<std::uint32_t> on = editor_.faces_on_edge(u, v);
      if (on.size() != 2) return ~0u;
      return on[0] == f ? on[1] : on[0];
    };
    const std::uint32_t g = across(a, b);
    if (g == ~0u || !editor_.alive(g)) return false;
    for (const std::uint32_t h : {across(b, c), across(c, a)})
      if (h != ~0u && h != g && editor_.alive(h) &&
          relation(m_.faces[h], m_.faces[g]) == geometry::TrianglePairRelation::intersecting)
        return true;
    return false;
  }

  // Removes the fold at face f, by the smallest change that works. A folded face is a
  // sliver or a tiny face: its corner opposite the longest edge is within a rounding error
  // of that edge. Another rounding of a rounded corner moves the surface by an ulp;
  // flipping the longest edge with the neighbouring face moves no vertex and changes the
  // surface by the fold's own height. Only then an edge of f is collapsed, shortest first,
  // when the faces then around the kept vertex turn none over and cross nothing around
  // them (exact); a collapse moves a vertex by the edge's length, which on a sliver whose
  // short edge is not tiny (a rounded point an ulp from an edge of the other operand,
  // where one of its faces is nearly coplanar with a face of this one) would move the
  // surface by far more than rounding did.
  bool unfold(std::uint32_t f, const std::vector<std::uint8_t>& rounded) {
    const Triangle t = m_.faces[f];
    for (Index v : t)
      if (rounded[v] && checked_nudge(v)) return true;
    if (checked_flip_longest_edge(f)) return true;
    std::array<std::pair<double, int>, 3> edges;
    for (int i = 0; i < 3; ++i) edges[i] = {norm(m_.vertices[t[(i + 1) % 3]] - m_.vertices[t[i]]), i};
    std::sort(edges.begin(), edges.end());
    for (const auto& [length, i] : edges)
      for (bool keep_first : {true, false}) {
        const Index u = keep_first ? t[i] : t[(i + 1) % 3], v = keep_first ? t[(i + 1) % 3] : t[i];
        if (checked_collapse(u, v)) return true;
      }
    return false;
  }

  // Moves rounded point v to one of the 26 doubles next to it (one ulp in some
  // coordinates, in a fixed order) when that leaves fewer crossings around it, the fewest
  // found; another rounding of the same exact point, so the surface moves by an ulp.
  bool checked_nudge(Index v) {
    if (editor_.frozen(v)) return false;
    const Vec3 original = m_.vertices[v];
    const std::size_t before = editor_.crossings_around({v});
    std::size_t best = before;
    Vec3 best_position = original;
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (int dx = -1; dx <= 1 && best > 0; ++dx)
      for (int dy = -1; dy <= 1 && best > 0; ++dy)
        for (int dz = -1; dz <= 1 && best > 0; ++dz) {
          if (dx == 0 && dy == 0 && dz == 0) continue;
          const int step[3] = {dx, dy, dz};
          Vec3 moved = original;
          for (int axis = 0; axis < 3; ++axis)
            if (step[axis] != 0)
              (axis == 0 ? moved.x : axis == 1 ? moved.y : moved.z) = std::nextafter(original[axis], step[axis] * inf);
          editor_.reposition(v, moved);
          bool flat = false;
          for (std::uint32_t g : editor_.faces_of(v)) flat |= editor_.alive(g) && degenerate(m_, m_.faces[g]);
          if (flat) continue;
          if (const std::size_t count = editor_.crossings_around({v}); count < best) {
            best = count;
            best_position = moved;
          }
        }
    editor_.reposition(v, best_position);
    return best < before;
  }

  // The corners a, b of t's longest edge and its opposite corner c.
  std::array<Index, 3> longest_edge(const Triangle& t) const {
    int longest = 0;
    double length = -1;
    for (int i = 0; i < 3; ++i)
      if (const double l = norm(m_.vertices[t[(i + 1) % 3]] - m_.vertices[t[i]]); l > length) {
        length = l;
        longest = i;
      }
    return {t[longest], t[(longest + 1) % 3], t[(longest + 2) % 3]};
  }

  // Flips the longest edge of f with the face across it when that leaves fewer crossings
  // around the four corners than there were (exactly counted); otherwise changes nothing.
  bool checked_flip_longest_edge(std::uint32_t f) {
    const auto [a, b, c] = longest_edge(m_.faces[f]);
    const std::vector<std::uint32_t> around = editor_.faces_on_edge(a, b);
    if (around.size() != 2) return false;
    const std::uint32_t g = around[0] == f ? around[1] : around[0];
    const Index d = third_corner(g, a, b, a);
    if (d == a || d == c || !editor_.faces_on_edge(c, d).empty()) return false;
    if (geometry::collinear3d(m_.vertices[a], m_.vertices[c], m_.vertices[d]) ||
        geometry::collinear3d(m_.vertices[b], m_.vertices[c], m_.vertices[d]))
      return false;
    const std::size_t before = editor_.crossings_around({a, b, c, d});
    // No vertex moves and edge ab has both its faces here, so the open edges where
    // passive faces join (at frozen vertices) stay as they are.
    return commit_if(editor_.flip_appending(f, g, c, d), [&] { return editor_.crossings_around({a, b, c, d}) < before; });
  }

  // Makes the edit and keeps it if `better()` then holds; otherwise undoes it.
  template <class Better>
  bool commit_if(const MeshEdit& e, Better&& better) {
    editor_.open_journal();
    editor_.commit(e);
    const bool kept = better();
    if (!kept) editor_.undo_last();
    editor_.close_journal();
    return kept;
  }

  // A collapse that leaves fewer crossings around it than there were (exactly counted);
  // clusters of near-coincident points clear over several passes. An `optional` collapse
  // (not needed for validity: collapse_tiny_edges) must leave no crossing around it, and
  // is not counted as refused at a frozen vertex (that would redo the Boolean whole).
  bool checked_collapse(Index u, Index v, bool optional = false) {
    if (optional ? editor_.frozen(u) || editor_.frozen(v) : editor_.touches_frozen({u, v})) return false;
    const std::vector<std::uint32_t> on_edge = editor_.faces_on_edge(u, v);
    if (on_edge.size() != 2 || !editor_.link_condition(u, v, on_edge)) return false;
    const MeshEdit e = editor_.merge(u, v, on_edge);
    // A real face moving to u must not turn over. A sliver (rounding may already have
    // turned it) has no direction of its own: it is judged by the crossing count, unless
    // the collapse makes it a real face, which must then face as the real faces around
    // it do (else it lies folded flat over its neighbours, a flap the exact test cannot
    // see when rounding keeps the sheets an ulp apart).
    Vec3 around{};
    for (std::size_t k = 0; k < e.faces.size(); ++k)
      if (!may_turn_over(m_, m_.faces[e.faces[k]])) around = around + e.reference[k];
    for (std::size_t k = 0; k < e.faces.size(); ++k) {
      if (e.removes(k)) continue;
      const Triangle& t = e.after[k];
      const Vec3 &a = m_.vertices[t[0]], &b = m_.vertices[t[1]], &c = m_.vertices[t[2]];
      if (may_turn_over(m_, m_.faces[e.faces[k]])) {
        if (geometry::collinear3d(a, b, c)) return false;
        if (!may_turn_over(m_, t) && dot(around, around) > 0 && !MeshEditor::keeps_facing(a, b, c, around, 0))
          return false;
      } else if (!MeshEditor::keeps_facing(a, b, c, e.reference[k], 0)) {
        return false;
      }
    }
    const std::size_t before = editor_.crossings_around({u, v});
    const bool kept = commit_if(e, [&] {
      const std::size_t after = editor_.crossings_around({u});
      return optional ? after == 0 : after < before;
    });
    if (kept) collapsed_.emplace_back(v, u);
    return kept;
  }

  // Merges v into u (same position) when the link condition holds.
  bool collapse(Index u, Index v) {
    if (editor_.touches_frozen({u, v})) return false;
    const std::vector<std::uint32_t> on_edge = editor_.faces_on_edge(u, v);
    if (!editor_.link_condition(u, v, on_edge)) return false;
    editor_.commit(editor_.merge(u, v, on_edge));
    collapsed_.emplace_back(v, u);
    return true;
  }

  // Face f = (.., a, b, .. with corner c strictly inside edge ab): flip ab with the other face.
  bool flip(std::uint32_t f, Index a, Index b, Index c) {
    const std::vector<std::uint32_t> around = editor_.faces_on_edge(a, b);
    if (around.size() != 2) return false;
    const std::uint32_t g = around[0] == f ? around[1] : around[0];
    const Index d = third_corner(g, a, b, 0);
    if (!editor_.faces_on_edge(c, d).empty()) return false;
    // Frozen vertices join faces outside this result: no repair may move, merge or re-link
    // them (the caller redoes the Boolean on the whole solids when one was needed).
    if (editor_.touches_frozen({a, b, c, d})) return false;
    editor_.commit(editor_.flip_appending(f, g, c, d));
    return true;
  }

  // Drops the dead faces; the faces flips appended take their operand and source from
  // the face they are tagged like.
  void compact() {
    for (std::uint32_t f = editable_.first_added(); f < m_.faces.size(); ++f) {
      operand_.push_back(operand_[editable_.added_like(f)]);
      source_.push_back(source_[editable_.added_like(f)]);
    }
    keep_alive_faces(m_, editable_.alive_faces(), operand_, source_);
  }

  Mesh& m_;
  std::vector<std::uint8_t>& operand_;
  std::vector<std::uint32_t>& source_;
  RepairOptions options_;
  std::vector<std::uint32_t> indexed_;
  EditableMesh editable_;
  MeshEditor editor_;
  std::vector<std::pair<Index, Index>> collapsed_;  // (removed, kept), in order
};

}  // namespace

bool may_turn_over(const Mesh& m, const Triangle& t) { return is_sliver(m, t) || is_tiny(m, t); }

RepairOutcome repair_rounding(Mesh& mesh, std::vector<std::uint8_t>& face_operand,
                              std::vector<std::uint32_t>& face_source, const std::vector<std::uint8_t>& rounded,
                              const std::vector<std::uint8_t>& frozen, const RepairOptions& options) {
  // Most results have no degenerate face and no sliver at a rounded point: then nothing
  // is indexed at all. The faces to repair are found in parallel (exact collinearity).
  const auto nf = static_cast<std::int64_t>(mesh.faces.size());
  std::vector<std::uint8_t> needs(mesh.faces.size(), 0);
  std::size_t any = 0;
#pragma omp parallel for schedule(static) reduction(+ : any)
  for (std::int64_t f = 0; f < nf; ++f) {
    needs[f] = needs_repair(mesh, mesh.faces[f], rounded);
    any += needs[f];
  }
  if (any == 0) return {};
  return Repairer(mesh, face_operand, face_source, needs, frozen, options).run(rounded);
}

}  // namespace molsurf::boolean_engine
