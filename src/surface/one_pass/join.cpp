#include "surface/one_pass/join.hpp"

#include <parallel/algorithm>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <span>
#include <utility>

#include "boolean/repair_rounding.hpp"
#include "geometry/implicit_point.hpp"
#include "molsurf/error.hpp"

namespace molsurf::surface_detail::one_pass {

namespace {

// Each atom's points and faces take a range of one global sequence: atom i's points are
// [point_start[i], point_start[i + 1]), and so on.
struct SequenceRanges {
  std::vector<std::size_t> point_start, face_start, implicit_start;
};

// The ranges, and the trim's counts added into `stats`.
SequenceRanges sequence_ranges(std::span<const AtomPieces> pieces, OnePassStats& stats) {
  SequenceRanges ranges;
  ranges.point_start.assign(pieces.size() + 1, 0);
  ranges.face_start.assign(pieces.size() + 1, 0);
  ranges.implicit_start.assign(pieces.size() + 1, 0);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const AtomPieces& p = pieces[i];
    stats.faces_inside += p.faces_inside;
    stats.faces_whole += p.faces_whole;
    stats.faces_cut += p.faces_cut;
    stats.crossings += p.crossings;
    ranges.point_start[i + 1] = ranges.point_start[i] + p.points.size();
    ranges.face_start[i + 1] = ranges.face_start[i] + p.triangles.size();
    ranges.implicit_start[i + 1] = ranges.implicit_start[i] + p.implicit_points;
  }
  if (ranges.point_start.back() >= std::numeric_limits<std::uint32_t>::max())
    throw Error("the union is too large to index: more than 4 billion points");
  return ranges;
}

struct HashedPosition {
  std::uint64_t hash;
  std::uint32_t position;
  bool operator<(const HashedPosition& o) const { return hash != o.hash ? hash < o.hash : position < o.position; }
};

// Merge by definition: implicit points sorted by (hash, position); in a run of equal
// hashes, a point's representative is the first point of the run with its definition.
// Per position of the global sequence, the position of its representative.
std::vector<std::uint32_t> representatives_by_definition(std::span<const AtomPieces> pieces,
                                                         const SequenceRanges& ranges, int threads) {
  const auto atom_count = static_cast<std::int64_t>(pieces.size());
  std::vector<const PointDefinition*> sequence(ranges.point_start.back());
  std::vector<std::uint32_t> representative(sequence.size());
  std::vector<HashedPosition> hashed(ranges.implicit_start.back());
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
  for (std::int64_t i = 0; i < atom_count; ++i) {
    const AtomPieces& p = pieces[i];
    std::size_t next_implicit = ranges.implicit_start[i];
    for (std::size_t k = 0; k < p.points.size(); ++k) {
      const auto position = static_cast<std::uint32_t>(ranges.point_start[i] + k);
      sequence[position] = &p.points[k];
      representative[position] = position;
      // An atom's own corners are points of no other atom, unless two atoms have a vertex
      // in common, which the merge by exact value finds.
      if (!p.points[k].is_explicit()) hashed[next_implicit++] = {p.points[k].hash(), position};
    }
  }
  __gnu_parallel::sort(hashed.begin(), hashed.end());
  const auto hashed_count = static_cast<std::int64_t>(hashed.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t k = 0; k < hashed_count; ++k) {
    std::int64_t first = k;
    while (first > 0 && hashed[first - 1].hash == hashed[k].hash) --first;
    const PointDefinition& point = *sequence[hashed[k].position];
    for (std::int64_t j = first; j < k; ++j)
      if (*sequence[hashed[j].position] == point) {
        representative[hashed[k].position] = hashed[j].position;
        break;
      }
  }
  return representative;
}

// The points distinct by definition, in order of first appearance.
struct DistinctPoints {
  std::vector<PointDefinition> points;
  std::vector<Vec3> coordinates;        // as written; NaN x: not yet known
  std::vector<std::uint32_t> point_of;  // per position of the global sequence: its point
};

DistinctPoints distinct_points(std::span<const AtomPieces> pieces, std::span<const std::uint32_t> representative) {
  DistinctPoints distinct;
  distinct.point_of.resize(representative.size());
  std::size_t count = 0;
  for (std::size_t s = 0; s < representative.size(); ++s) count += representative[s] == s;
  distinct.points.reserve(count);
  distinct.coordinates.reserve(count);
  for (std::size_t i = 0, s = 0; i < pieces.size(); ++i)
    for (std::size_t k = 0; k < pieces[i].points.size(); ++k, ++s) {
      if (representative[s] == s) {
        distinct.point_of[s] = static_cast<std::uint32_t>(distinct.points.size());
        distinct.points.push_back(pieces[i].points[k]);
        distinct.coordinates.push_back(pieces[i].coordinates[k]);
      } else {
        distinct.point_of[s] = distinct.point_of[representative[s]];
      }
    }
  return distinct;
}

// The atoms' triangles into `mesh`, on the distinct points, each tagged with its atom.
void join_faces(std::span<const AtomPieces> pieces, const SequenceRanges& ranges,
                std::span<const std::uint32_t> point_of, int threads, Mesh& mesh) {
  const auto atom_count = static_cast<std::int64_t>(pieces.size());
  mesh.faces.resize(ranges.face_start.back());
  mesh.face_tags.resize(ranges.face_start.back());
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
  for (std::int64_t i = 0; i < atom_count; ++i) {
    const auto& triangles = pieces[i].triangles;
    for (std::size_t j = 0; j < triangles.size(); ++j) {
      Triangle& t = mesh.faces[ranges.face_start[i] + j];
      for (int c = 0; c < 3; ++c) t[c] = point_of[ranges.point_start[i] + triangles[j][c]];
      mesh.face_tags[ranges.face_start[i] + j] = static_cast<std::int32_t>(i);
    }
  }
}

// A written coordinate is within about 2 ulps of the exact one (the filter box's midpoint
// when the box is that tight, the exact value truncated otherwise), so points equal by
// exact value have written coordinates within this reach of each other.
double rounding_reach(double c) {
  return 8 * std::numeric_limits<double>::epsilon() * std::fabs(c) + 8 * std::numeric_limits<double>::denorm_min();
}

// Points equal by exact value but defined differently (degenerate contacts): the implicit
// points are rebuilt and compared exactly only where their written coordinates' windows
// overlap, in a sweep along x. Per point, a lower point equal to it (itself when none);
// the chains end at the lowest. Constructs the coordinates not known yet.
std::vector<std::uint32_t> merge_equal_values(const AtomPolyhedra& polyhedra, int threads, DistinctPoints& distinct) {
  const std::vector<PointDefinition>& points = distinct.points;
  std::vector<Vec3>& coordinates = distinct.coordinates;
  const auto point_count = static_cast<std::int64_t>(points.size());
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (std::int64_t p = 0; p < point_count; ++p)
    if (std::isnan(coordinates[p].x)) coordinates[p] = construct(points[p], polyhedra).rounded();
  auto windows_overlap = [&](std::uint32_t a, std::uint32_t b) {
    for (int axis = 0; axis < 3; ++axis) {
      const double x = coordinates[a][axis], y = coordinates[b][axis];
      if (x + rounding_reach(x) < y - rounding_reach(y) || y + rounding_reach(y) < x - rounding_reach(x)) return false;
    }
    return true;
  };
  std::vector<std::pair<double, std::uint32_t>> order(points.size());
  std::vector<std::uint32_t> same(points.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t p = 0; p < point_count; ++p) {
    const double x = coordinates[p].x;
    order[p] = {x - rounding_reach(x), static_cast<std::uint32_t>(p)};
  }
  std::iota(same.begin(), same.end(), 0u);
  __gnu_parallel::sort(order.begin(), order.end());  // a total order: the same for any thread count
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint32_t a = order[k].second;
    const double end = coordinates[a].x + rounding_reach(coordinates[a].x);
    for (std::size_t l = k + 1; l < order.size() && order[l].first <= end; ++l) {
      const std::uint32_t b = order[l].second, x = std::min(a, b), y = std::max(a, b);
      if (same[y] != y || !windows_overlap(a, b) ||
          !geometry::same_point(construct(points[a], polyhedra), construct(points[b], polyhedra)))
        continue;
      std::uint32_t root = x;
      while (same[root] != root) root = same[root];
      same[y] = root;
    }
  }
  return same;
}

// The mesh's vertices: one per class of equal points, numbered in order of their lowest
// point; the faces renumbered onto them. Per point, its vertex.
std::vector<std::uint32_t> number_vertices(std::span<const std::uint32_t> same, std::span<const Vec3> coordinates,
                                           int threads, Mesh& mesh) {
  const auto point_count = static_cast<std::int64_t>(same.size());
  std::vector<std::uint32_t> vertex_of(same.size());
  std::size_t vertex_count = 0;
  for (std::uint32_t p = 0; p < same.size(); ++p) {
    std::uint32_t root = p;
    while (same[root] != root) root = same[root];
    vertex_of[p] = root == p ? static_cast<std::uint32_t>(vertex_count++) : vertex_of[root];
  }
  mesh.vertices.resize(vertex_count);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t p = 0; p < point_count; ++p)
    if (same[p] == static_cast<std::uint32_t>(p)) mesh.vertices[vertex_of[p]] = coordinates[p];
  const auto face_count = static_cast<std::int64_t>(mesh.faces.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t f = 0; f < face_count; ++f)
    for (Index& v : mesh.faces[f]) v = vertex_of[v];
  return vertex_of;
}

// Rounding the points to doubles, after every decision, can make a tiny piece degenerate
// or fold it over its neighbour; the engine's repair fixes that by exact predicates on the
// rounded coordinates, without moving a vertex.
void repair_rounded_points(std::span<const PointDefinition> points, std::span<const std::uint32_t> vertex_of,
                           Mesh& mesh) {
  std::vector<std::uint8_t> rounded(mesh.vertices.size(), 0), operand(mesh.faces.size(), 0);
  for (std::uint32_t p = 0; p < points.size(); ++p)
    if (!points[p].is_explicit()) rounded[vertex_of[p]] = 1;
  std::vector<std::uint32_t> atom_of(mesh.face_tags.begin(), mesh.face_tags.end());
  boolean_engine::repair_rounding(mesh, operand, atom_of, rounded, {});
  mesh.face_tags.assign(atom_of.begin(), atom_of.end());
}

// Directed edges (u, v) without their reverse: 0 for a closed surface. The reverse is
// found among the few edges that leave v (edges bucketed by their first vertex).
// The buckets are counted and filled in parallel: the order within a bucket depends on the
// threads, the count does not.
std::size_t count_open_edges(const Mesh& mesh, int threads) {
  std::vector<std::uint32_t> first(mesh.vertices.size() + 1, 0);
  const auto face_total = static_cast<std::int64_t>(mesh.faces.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::int64_t f = 0; f < face_total; ++f)
    for (const Index v : mesh.faces[f]) std::atomic_ref(first[v + 1]).fetch_add(1, std::memory_order_relaxed);
  std::partial_sum(first.begin(), first.end(), first.begin());
  const auto to = std::make_unique_for_overwrite<Index[]>(first.back());  // first written in parallel
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t f = 0; f < face_total; ++f) {
      const Triangle& t = mesh.faces[f];
      for (int k = 0; k < 3; ++k) to[std::atomic_ref(fill[t[k]]).fetch_add(1, std::memory_order_relaxed)] = t[(k + 1) % 3];
    }
  }
  std::size_t open_edges = 0;
  const auto vertex_total = static_cast<std::int64_t>(mesh.vertices.size());
#pragma omp parallel for schedule(static) reduction(+ : open_edges) num_threads(threads)
  for (std::int64_t u = 0; u < vertex_total; ++u)
    for (std::uint32_t k = first[u]; k < first[u + 1]; ++k) {
      const Index v = to[k];
      const Index *begin = to.get() + first[v], *end = to.get() + first[v + 1];
      if (std::find(begin, end, static_cast<Index>(u)) == end) ++open_edges;
    }
  return open_edges;
}

}  // namespace

void join_pieces(std::vector<AtomPieces> pieces, const AtomPolyhedra& polyhedra, int threads, Mesh& mesh,
                 OnePassStats& stats, std::vector<VertexOrigin>* origins) {
  // The steps run in parallel where they are not linear scans, and number points as a
  // serial scan would (in order of first appearance). Buffers go as soon as their step is
  // done, to keep the peak memory down.
  const SequenceRanges ranges = sequence_ranges(pieces, stats);
  DistinctPoints distinct = distinct_points(pieces, representatives_by_definition(pieces, ranges, threads));
  join_faces(pieces, ranges, distinct.point_of, threads, mesh);
  // Distinct points are numbered in order of first appearance: the k-th is first seen at
  // the k-th position whose point is new.
  std::vector<VertexOrigin> point_origin;
  if (origins) {
    point_origin.resize(distinct.points.size());
    std::vector<std::uint8_t> seen(distinct.points.size(), 0);
    for (std::uint32_t i = 0, s = 0; i < pieces.size(); ++i)
      for (std::uint32_t k = 0; k < pieces[i].points.size(); ++k, ++s) {
        const std::uint32_t p = distinct.point_of[s];
        if (seen[p]) continue;
        seen[p] = 1;
        point_origin[p] = {distinct.points[p], i, k};
      }
  }
  distinct.point_of = {};
  pieces = {};
  const std::vector<std::uint32_t> same = merge_equal_values(polyhedra, threads, distinct);
  const std::vector<std::uint32_t> vertex_of = number_vertices(same, distinct.coordinates, threads, mesh);
  if (origins) {
    // A vertex's root point is its class's first: the lowest distinct point.
    origins->assign(mesh.vertices.size(), {});
    for (std::uint32_t p = 0; p < same.size(); ++p)
      if (same[p] == p) (*origins)[vertex_of[p]] = point_origin[p];
  }
  stats.merged_points = distinct.points.size() - mesh.vertices.size();
  repair_rounded_points(distinct.points, vertex_of, mesh);
  stats.open_edges = count_open_edges(mesh, threads);
}

}  // namespace molsurf::surface_detail::one_pass
