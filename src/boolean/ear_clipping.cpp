#include "boolean/ear_clipping.hpp"

#include "geometry/exact_integers.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>


namespace molsurf::boolean_engine {

using geometry::ImplicitPoint;

namespace {

// Cosine of the angle at p between the directions to q and to r (approximate: quality only).
double angle_cosine(const std::array<double, 2>& p, const std::array<double, 2>& q, const std::array<double, 2>& r) {
  const double ux = q[0] - p[0], uy = q[1] - p[1], wx = r[0] - p[0], wy = r[1] - p[1];
  return (ux * wx + uy * wy) / std::sqrt((ux * ux + uy * uy) * (wx * wx + wy * wy));
}

// The largest cosine of the triangle's three angles: the larger, the smaller its smallest angle.
double smallest_angle_cosine(std::span<const std::array<double, 2>> at, int a, int b, int c) {
  double worst = -1;
  const int corner[3] = {a, b, c};
  for (int i = 0; i < 3; ++i)
    worst = std::max(worst, angle_cosine(at[corner[i]], at[corner[(i + 1) % 3]], at[corner[(i + 2) % 3]]));
  return worst;
}

}  // namespace

std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulate_chords(
    std::span<const std::uint32_t> boundary, std::span<const std::vector<std::uint32_t>> edge_runs,
    std::span<const std::pair<std::uint32_t, std::uint32_t>> chords, std::span<const ImplicitPoint> points,
    Projection projection) {
  const int m = static_cast<int>(boundary.size());
  auto index_of = [&](std::uint32_t id) {
    for (int k = 0; k < m; ++k)
      if (boundary[k] == id) return k;
    return -1;
  };
  std::vector<std::uint8_t> runs(m, 0);  // bit r: on edge r (corners are on two)
  for (std::size_t r = 0; r < edge_runs.size(); ++r)
    for (std::uint32_t id : edge_runs[r]) {
      const int k = index_of(id);
      if (k < 0) return std::nullopt;
      runs[k] |= static_cast<std::uint8_t>(1u << r);
    }
  std::vector<std::vector<int>> chords_from(m);  // higher ends of the chords at each index
  for (auto [s, t] : chords) {
    int i = index_of(s), j = index_of(t);
    if (i < 0 || j < 0 || i == j || (runs[i] & runs[j])) return std::nullopt;
    if (i > j) std::swap(i, j);
    chords_from[i].push_back(j);
  }
  // Pieces: the boundary from i to j closed by the chord j -> i; inside it, each chord
  // (k, l) met on the way is a shortcut, and the part it cuts off is a piece of its own.
  std::vector<std::vector<int>> pieces;
  auto trace = [&](auto&& self, int i, int j) -> void {
    std::vector<int> piece{i};
    for (int k = i; k != j;) {
      int next = k + 1;
      for (int l : chords_from[k % m])
        if (l > next && l <= j && !(k == i && l == j)) next = l;
      if (next > k + 1) self(self, k, next);
      k = next;
      if (k != j || j < m) piece.push_back(k % m);
    }
    pieces.push_back(std::move(piece));
  };
  trace(trace, 0, m);

  std::vector<std::array<double, 2>> at(m);
  for (int k = 0; k < m; ++k) {
    const ImplicitPoint& p = points[boundary[k]];
    at[k] = {p.coordinate(projection.u).mid(), p.coordinate(projection.v).mid()};
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (std::vector<int>& poly : pieces) {
    while (poly.size() > 3) {
      const int n = static_cast<int>(poly.size());
      int best = -1;
      double best_cosine = 2;
      for (int i = 0; i < n; ++i) {
        const int p = poly[(i + n - 1) % n], c = poly[i], q = poly[(i + 1) % n];
        if (runs[p] & runs[c] & runs[q]) continue;  // collinear: no triangle
        bool diagonal_over_a_point = false;         // p -> q along an edge holding another vertex
        if (const std::uint8_t common = runs[p] & runs[q])
          for (int w : poly)
            if (w != p && w != c && w != q && (runs[w] & common)) diagonal_over_a_point = true;
        if (diagonal_over_a_point) continue;
        const double cosine = smallest_angle_cosine(at, p, c, q);
        if (cosine < best_cosine) {
          best_cosine = cosine;
          best = i;
        }
      }
      if (best < 0) return std::nullopt;
      triangles.push_back({boundary[poly[(best + n - 1) % n]], boundary[poly[best]], boundary[poly[(best + 1) % n]]});
      poly.erase(poly.begin() + best);
    }
    if (poly.size() != 3 || (runs[poly[0]] & runs[poly[1]] & runs[poly[2]])) return std::nullopt;
    triangles.push_back({boundary[poly[0]], boundary[poly[1]], boundary[poly[2]]});
  }
  if (static_cast<int>(triangles.size()) != m - 2) return std::nullopt;  // chords that cross
  return triangles;
}

namespace {

// orient2d of the face's points by local index. Points known to be collinear (one edge of
// the face, one intersection segment) have orientation 0 without arithmetic (the filter
// could never certify that zero: it would go to the exact path); every other triple is
// evaluated once, the ear clipping asking for the same triples again and again.
class MemoisedOrientation {
 public:
  // `lines`: bit k of a point's word says it is on collinear set k. `memo`: one entry per
  // set of three points (memo_size), all 2 (not known yet).
  MemoisedOrientation(const FacePoints& points, std::span<const std::uint64_t> lines, std::span<std::int8_t> memo)
      : points_(points), lines_(lines), memo_(memo) {}

  static std::size_t memo_size(std::size_t n) { return n * (n - 1) * (n - 2) / 6; }

  int operator()(int a, int b, int c) const {
    if (lines_[a] & lines_[b] & lines_[c]) return 0;
    int sign = 1;
    if (a > b) std::swap(a, b), sign = -sign;
    if (b > c) std::swap(b, c), sign = -sign;
    if (a > b) std::swap(a, b), sign = -sign;
    if (a == b || b == c) return 0;
    // The rank of {a < b < c} among all sets of three (combinatorial number system).
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b), uc = static_cast<std::size_t>(c);
    std::int8_t& known = memo_[ua + ub * (ub - 1) / 2 + uc * (uc - 1) * (uc - 2) / 6];
    if (known == 2) known = static_cast<std::int8_t>(points_.orient(a, b, c));
    return sign * known;
  }

 private:
  const FacePoints& points_;
  std::span<const std::uint64_t> lines_;
  std::span<std::int8_t> memo_;
};

// Local indices: the boundary points are 0 .. m-1 in order (FacePoints keeps the order);
// work.boundary_position is a point's place on the boundary, -1 inside the face.
void number_boundary(const FaceToSplit& face, const FacePoints& points, PolylineWork& work) {
  const int n = static_cast<int>(points.ids().size());
  const int m = static_cast<int>(face.boundary.size());
  auto& local_boundary = work.local_boundary;
  local_boundary.resize(m);
  for (int k = 0; k < m; ++k) local_boundary[k] = points.local(face.boundary[k]);
  auto& boundary_position = work.boundary_position;
  boundary_position.assign(n, -1);
  for (int k = 0; k < m; ++k) boundary_position[local_boundary[k]] = k;
}

// work.lines: bit k of a point's word says it is on the face's collinear set k (the first 64).
void mark_collinear_sets(const FaceToSplit& face, const FacePoints& points, PolylineWork& work) {
  auto& lines = work.lines;
  lines.assign(points.ids().size(), 0);
  for (std::size_t k = 0; k < face.collinear_sets.size() && k < 64; ++k)
    for (std::uint32_t id : face.collinear_sets[k]) lines[points.local(id)] |= std::uint64_t{1} << k;
}

// The graph of the boundary and the constraints, into work.around (unordered). False when
// a point has fewer than two neighbours: a loose end, so not a set of pieces.
bool connect_boundary_and_constraints(const FaceToSplit& face, const FacePoints& points, PolylineWork& work) {
  const int n = static_cast<int>(points.ids().size());
  const int m = static_cast<int>(face.boundary.size());
  const auto& local_boundary = work.local_boundary;
  auto& around = work.around;
  if (around.size() < static_cast<std::size_t>(n)) around.resize(n);
  for (int v = 0; v < n; ++v) around[v].clear();
  for (int k = 0; k < m; ++k) {
    const int a = local_boundary[k], b = local_boundary[(k + 1) % m];
    around[a].push_back(b);
    around[b].push_back(a);
  }
  for (auto [s, t] : face.constraints) {
    const int a = points.local(s), b = points.local(t);
    around[a].push_back(b);
    around[b].push_back(a);
  }
  for (int v = 0; v < n; ++v)
    if (around[v].size() < 2) return false;
  return true;
}

// Around every point its neighbours in counter-clockwise order, in exact angular order
// where that takes predicates.
void sort_neighbours_by_angle(const FaceToSplit& face, const FacePoints& points, const MemoisedOrientation& orient,
                              PolylineWork& work) {
  const int n = static_cast<int>(points.ids().size());
  const int m = static_cast<int>(face.boundary.size());
  const auto& local_boundary = work.local_boundary;
  auto& around = work.around;
  const int u_axis = face.projection.u, v_axis = face.projection.v;
  for (int v = 0; v < n; ++v) {
    if (around[v].size() < 3) continue;
    if (const int k = work.boundary_position[v]; k >= 0 && around[v].size() == 3) {
      // One constraint from the boundary: counter-clockwise from the next boundary point
      // the interior comes first, then the previous boundary point.
      around[v] = {local_boundary[(k + 1) % m], around[v][2], local_boundary[(k + m - 1) % m]};
      continue;
    }
    // Directions from v by angle in [0, 2 pi): the upper half-plane first, then the
    // order of orientation within a half (exact; two edges never share a direction).
    auto lower_half = [&](int w) {
      const int dv = points.compare(w, v, v_axis);
      return dv < 0 || (dv == 0 && points.compare(w, v, u_axis) < 0);
    };
    std::sort(around[v].begin(), around[v].end(), [&](int a, int b) {
      const bool ha = lower_half(a), hb = lower_half(b);
      if (ha != hb) return hb;
      return orient(v, a, b) > 0;
    });
  }
}

// The pieces are the graph's bounded faces, each walked with the piece on the left: from
// u -> v the walk goes on to the neighbour of v just clockwise of u. Fills
// work.pieces[0 .. count) and returns the count; nullopt when a piece is not a simple
// polygon or the graph is not connected.
std::optional<std::size_t> walk_pieces(int n, int m, PolylineWork& work) {
  const auto& local_boundary = work.local_boundary;
  const auto& around = work.around;
  auto clockwise_of = [&](int v, int u) {
    const auto& ring = around[v];
    const int d = static_cast<int>(ring.size());
    for (int k = 0; k < d; ++k)
      if (ring[k] == u) return ring[(k + d - 1) % d];
    return -1;
  };
  // Half-edges walked, keyed by (from, position of `to` in around[from]).
  auto& walked = work.walked;
  if (walked.size() < static_cast<std::size_t>(n)) walked.resize(n);
  for (int v = 0; v < n; ++v) walked[v].assign(around[v].size(), 0);
  auto mark = [&](int a, int b) {
    for (std::size_t k = 0; k < around[a].size(); ++k)
      if (around[a][k] == b) {
        if (walked[a][k]) return false;
        walked[a][k] = 1;
        return true;
      }
    return false;
  };
  // The outside of the face is not a piece.
  for (int k = 0; k < m; ++k) mark(local_boundary[(k + 1) % m], local_boundary[k]);
  auto& pieces = work.pieces;
  std::size_t piece_count = 0;
  auto& in_piece = work.in_piece;
  in_piece.assign(n, 0);
  for (int a = 0; a < n; ++a)
    for (std::size_t k = 0; k < around[a].size(); ++k) {
      if (walked[a][k]) continue;
      if (pieces.size() <= piece_count) pieces.emplace_back();
      std::vector<int>& piece = pieces[piece_count];
      piece.assign(1, a);
      walked[a][k] = 1;
      int from = a, to = around[a][k];
      while (to != a) {
        if (in_piece[to]) return std::nullopt;  // a point met twice: not a simple polygon
        in_piece[to] = 1;
        piece.push_back(to);
        const int next = clockwise_of(to, from);
        if (!mark(to, next)) return std::nullopt;
        from = to;
        to = next;
      }
      if (clockwise_of(a, from) != around[a][k]) return std::nullopt;
      for (int v : piece) in_piece[v] = 0;
      ++piece_count;
    }
  // A connected graph: V - E + F = 2 with the outside as one face (a loop of constraints
  // apart from the rest would bound a piece with a hole).
  std::size_t edges = 0;
  for (int v = 0; v < n; ++v) edges += around[v].size();
  edges /= 2;
  if (static_cast<std::size_t>(n) + piece_count + 1 != edges + 2) return std::nullopt;
  return piece_count;
}

// The points in the projection: work.at their approximate coordinates (for angles),
// work.box their interval boxes (u lo, u hi, v lo, v hi).
void project_points(const FaceToSplit& face, const FacePoints& points, PolylineWork& work) {
  const int n = static_cast<int>(points.ids().size());
  auto& at = work.at;
  at.resize(n);
  for (int i = 0; i < n; ++i)
    at[i] = {points.point(i).coordinate(face.projection.u).mid(), points.point(i).coordinate(face.projection.v).mid()};
  auto& box = work.box;
  box.resize(n);
  for (int i = 0; i < n; ++i) {
    const auto &iu = points.point(i).coordinate(face.projection.u), &iv = points.point(i).coordinate(face.projection.v);
    box[i] = {iu.lo, iu.hi, iv.lo, iv.hi};
  }
}

// Certainly outside the closed triangle pcq: its interval box misses the triangle's box
// (saves the exact orientations of nearly collinear points along a straight cut).
bool outside_box(std::span<const std::array<double, 4>> box, int w, int p, int c, int q) {
  const auto &bw = box[w], &bp = box[p], &bc = box[c], &bq = box[q];
  return bw[1] < std::min({bp[0], bc[0], bq[0]}) || bw[0] > std::max({bp[1], bc[1], bq[1]}) ||
         bw[3] < std::min({bp[2], bc[2], bq[2]}) || bw[2] > std::max({bp[3], bc[3], bq[3]});
}

// Cosine of the remaining polygon's angle at `corner` (walked before -> corner ->
// after), or -1 when that angle is not convex. Quality only, but the convexity is
// decided exactly: it matters when the three points are nearly collinear.
double remaining_angle_cosine(std::span<const std::array<double, 2>> at, const MemoisedOrientation& orient,
                              int before, int corner, int after) {
  if (orient(before, corner, after) <= 0) return -1.0;  // exact: near zero is the case that matters
  return angle_cosine(at[corner], at[before], at[after]);
}

// A corner's standing in the ear clipping of one piece.
enum EarState : std::uint8_t { kStale, kEar, kNoEar, kReflex };

// Ear-clips one piece (a simple polygon of local indices, counter-clockwise), appending
// its triangles as point ids. False when no ear is left, or only a sliver.
//
// The piece is a cyclic list; an ear's verdict and score depend only on its corner's
// two neighbours on each side, and clipping a vertex can only turn other corners into
// ears (one point fewer to contain), so a valid ear keeps its score until a neighbour
// within two steps is clipped. So is a reflex corner (its two neighbours decide it);
// corners whose triangle holds a point are re-examined every round.
bool clip_piece(std::span<const int> poly, const MemoisedOrientation& orient, std::span<const std::uint32_t> ids,
                PolylineWork& work, std::vector<std::array<std::uint32_t, 3>>& triangles) {
  static const double kSliverCosine = std::cos(0.1 * 3.141592653589793 / 180);  // 0.1 degree
  const std::span<const std::array<double, 2>> at = work.at;
  const std::span<const std::array<double, 4>> box = work.box;
  auto &prev = work.prev, &next = work.next;
  auto& score = work.score;
  auto& state = work.state;
  const int k = static_cast<int>(poly.size());
  prev.resize(k);
  next.resize(k);
  for (int i = 0; i < k; ++i) {
    prev[i] = (i + k - 1) % k;
    next[i] = (i + 1) % k;
  }
  score.assign(k, 2);
  state.assign(k, kStale);
  int head = 0, remaining = k;
  auto examine = [&](int i) {
    const int p = poly[prev[i]], c = poly[i], q = poly[next[i]];
    if (orient(p, c, q) <= 0) return kReflex;
    for (int j = next[next[i]], step = 3; step < remaining; ++step, j = next[j]) {
      const int w = poly[j];
      if (w != p && w != c && w != q && !outside_box(box, w, p, c, q) && orient(p, c, w) >= 0 &&
          orient(c, q, w) >= 0 && orient(q, p, w) >= 0)
        return kNoEar;
    }
    // The ear's own angles, and the angles its diagonal leaves at p and q for the
    // rest of the polygon: a diagonal along a nearly straight run of points leaves
    // a sliver that no later triangle can avoid.
    double cosine = smallest_angle_cosine(at, p, c, q);
    if (remaining > 3) {
      cosine = std::max(cosine, remaining_angle_cosine(at, orient, poly[prev[prev[i]]], p, q));
      cosine = std::max(cosine, remaining_angle_cosine(at, orient, p, q, poly[next[next[i]]]));
    }
    score[i] = cosine;
    return kEar;
  };
  while (remaining >= 3) {
    int best = -1;
    double best_cosine = 2;
    for (int step = 0, i = head; step < remaining; ++step, i = next[i]) {
      if (state[i] != kEar && state[i] != kReflex) state[i] = examine(i);
      if (state[i] == kEar && score[i] < best_cosine) {
        best_cosine = score[i];
        best = i;
      }
    }
    // No ear, or only a sliver: near-collinear points (a polyline that is almost
    // straight) are better served by the Delaunay choice of the advancing front.
    if (best < 0 || best_cosine > kSliverCosine) return false;
    const int p = prev[best], q = next[best];
    triangles.push_back({ids[poly[p]], ids[poly[best]], ids[poly[q]]});
    next[p] = q;
    prev[q] = p;
    if (head == best) head = q;
    --remaining;
    state[p] = state[q] = state[prev[p]] = state[next[q]] = kStale;
    if (remaining == 2) break;
  }
  return remaining == 2;
}

}  // namespace

std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulate_polylines(const FaceToSplit& face,
                                                                                const FacePoints& points) {
  PolylineWork work;
  return triangulate_polylines(face, points, work);
}

std::optional<std::vector<std::array<std::uint32_t, 3>>> triangulate_polylines(const FaceToSplit& face,
                                                                                const FacePoints& points,
                                                                                PolylineWork& work,
                                                                                const PieceWanted& wanted) {
  const int n = static_cast<int>(points.ids().size());
  const int m = static_cast<int>(face.boundary.size());
  if (n > 64) return std::nullopt;
  number_boundary(face, points, work);
  mark_collinear_sets(face, points, work);
  work.memo.assign(MemoisedOrientation::memo_size(static_cast<std::size_t>(n)), 2);
  const MemoisedOrientation orient(points, work.lines, work.memo);

  if (!connect_boundary_and_constraints(face, points, work)) return std::nullopt;
  sort_neighbours_by_angle(face, points, orient, work);
  const std::optional<std::size_t> piece_count = walk_pieces(n, m, work);
  if (!piece_count) return std::nullopt;

  // A triangulation of the face with all its points has m + 2 (n - m) - 2 triangles; a
  // piece of k corners, clipped, gives k - 2.
  int triangle_count = 0;
  for (std::size_t piece = 0; piece < *piece_count; ++piece)
    triangle_count += static_cast<int>(work.pieces[piece].size()) - 2;
  if (triangle_count != m + 2 * (n - m) - 2) return std::nullopt;
  project_points(face, points, work);
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (std::size_t piece = 0; piece < *piece_count; ++piece) {
    if (wanted) {
      work.piece_ids.clear();
      for (int local : work.pieces[piece]) work.piece_ids.push_back(points.ids()[local]);
      if (!wanted(work.piece_ids)) continue;
    }
    if (!clip_piece(work.pieces[piece], orient, points.ids(), work, triangles)) return std::nullopt;
  }
  return triangles;
}

}  // namespace molsurf::boolean_engine
