#include "boolean/split.hpp"

#include <algorithm>

#include "boolean/advancing_front.hpp"
#include "boolean/ear_clipping.hpp"
#include "boolean/face_points.hpp"
#include "common/parallel_exceptions.hpp"
#include "geometry/predicates.hpp"

namespace molsurf::boolean_engine {

namespace {

struct FaceSplit {
  std::vector<SubFace> sub_faces;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> curve_pieces;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> opposite_sides;  // local sub-face indices
};

// Pairs of sub-faces on the two sides of a transversal piece of the curve: each piece
// (s, t) is an edge of exactly one sub-face in each direction.
void find_opposite_sides(FaceSplit& out, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pieces) {
  for (auto [s, t] : pieces) {
    std::uint32_t forward = ~0u, backward = ~0u;
    for (std::uint32_t k = 0; k < out.sub_faces.size(); ++k) {
      const auto& p = out.sub_faces[k].points;
      for (int i = 0; i < 3; ++i) {
        if (p[i] == s && p[(i + 1) % 3] == t) forward = k;
        if (p[i] == t && p[(i + 1) % 3] == s) backward = k;
      }
    }
    if (forward != ~0u && backward != ~0u) out.opposite_sides.emplace_back(forward, backward);
  }
}

// Segments of face f that lie on one plane of the other operand (its faces there are
// exactly coplanar, e.g. the two triangles of a flat quad) lie on one line, the plane's
// crossing with f: all their points form one collinear set, whose zero orientations then
// need no arithmetic (the interval filter can never certify a zero). Only faces that
// share an edge are compared (one orient3d each), and coplanarity is chained across
// them: a flat region crossed along a line is a chain of neighbours. Nearly coplanar
// neighbours (a rotated flat mesh) make that orient3d exact, so comparing every pair
// would cost more than it saves.
void add_coplanar_lines(const Operands& ops, const Arrangement& arr, std::uint32_t f, std::size_t first_line,
                        std::vector<std::vector<std::uint32_t>>& collinear_sets) {
  const auto& planes = arr.segment_planes[f];
  const auto& segments = arr.face_segments[f];
  if (planes.size() < 2) return;
  // Faces g and h sharing an edge: coplanar iff h's third vertex is on g's plane.
  auto coplanar_neighbours = [&](std::uint32_t g, std::uint32_t h) {
    if (g == h) return true;
    const auto &a = ops.face(g), &b = ops.face(h);
    int shared = 0;
    std::uint32_t other = ~0u;
    for (std::uint32_t v : b) {
      if (v == a[0] || v == a[1] || v == a[2])
        ++shared;
      else
        other = v;
    }
    if (shared != 2) return false;
    return geometry::orient3d(ops.vertex(a[0]), ops.vertex(a[1]), ops.vertex(a[2]), ops.vertex(other)) == 0;
  };
  std::vector<std::uint32_t> plane_of(segments.size(), ~0u);
  for (std::size_t j = 0; j < segments.size(); ++j) {
    const auto it = std::lower_bound(planes.begin(), planes.end(), std::pair{segments[j], std::uint32_t{0}});
    if (it != planes.end() && it->first == segments[j]) plane_of[j] = it->second;
  }
  std::vector<std::size_t> parent(segments.size());
  for (std::size_t j = 0; j < parent.size(); ++j) parent[j] = j;
  auto root = [&](std::size_t j) {
    while (parent[j] != j) j = parent[j] = parent[parent[j]];
    return j;
  };
  for (std::size_t j = 0; j < segments.size(); ++j) {
    if (plane_of[j] == ~0u) continue;
    for (std::size_t k = j + 1; k < segments.size(); ++k)
      if (plane_of[k] != ~0u && root(j) != root(k) && coplanar_neighbours(plane_of[j], plane_of[k]))
        parent[root(k)] = root(j);
  }
  std::vector<std::vector<std::size_t>> groups(segments.size());
  for (std::size_t j = 0; j < segments.size(); ++j)
    if (plane_of[j] != ~0u) groups[root(j)].push_back(j);
  for (const auto& group : groups) {
    if (group.size() < 2) continue;
    std::vector<std::uint32_t> line;
    for (std::size_t j : group)
      line.insert(line.end(), collinear_sets[first_line + j].begin(), collinear_sets[first_line + j].end());
    std::sort(line.begin(), line.end());
    line.erase(std::unique(line.begin(), line.end()), line.end());
    collinear_sets.push_back(std::move(line));
  }
}

FaceSplit split_one_face(const Operands& ops, const Arrangement& arr, std::uint32_t f) {
  FaceSplit out;
  const auto& corners = ops.face(f);
  FaceToSplit face;
  face.projection = face_projection(ops.vertex(corners[0]), ops.vertex(corners[1]), ops.vertex(corners[2]));
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t from = corners[i], to = corners[(i + 1) % 3];
    std::vector<std::uint32_t> inside = arr.edge_points[ops.face_edges(f)[i]];
    face.add_edge(i, arr.vertex_point[from], arr.vertex_point[to], inside, ops.vertex(from), ops.vertex(to),
                  arr.points);
  }
  face.interior = arr.face_points[f];
  if (face.interior.empty()) {
    // Chords only: pieces are the segments themselves (no boundary point lies inside a
    // chord), and segments on the boundary are no constraints.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> chords;
    for (auto [s, t] : arr.face_segments[f])
      if (!face.on_one_edge(s, t)) chords.emplace_back(s, t);
    if (auto triangles = triangulate_chords(face.boundary, face.edge_runs, chords, arr.points, face.projection)) {
      out.curve_pieces = arr.face_segments[f];
      for (const auto& tri : *triangles) out.sub_faces.push_back({tri, f});
      find_opposite_sides(out, arr.transversal_segments[f]);
      return out;
    }
  }
  std::vector<std::uint32_t> ids = face.boundary;
  ids.insert(ids.end(), face.interior.begin(), face.interior.end());
  const FacePoints points(std::move(ids), arr.points, face.projection);
  for (const auto& run : face.edge_runs) face.collinear_sets.push_back(run);
  const std::size_t first_line = face.collinear_sets.size();
  const auto& segments = arr.face_segments[f];
  const auto pieces = split_segments_at_points(segments, points, face.collinear_sets);
  add_coplanar_lines(ops, arr, f, first_line, face.collinear_sets);
  // Pieces of transversal segments: both ends on the line of one (segments do not overlap
  // along a line unless they lie on a face's edge, which transversal ones never do).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> transversal_pieces;
  const auto& transversal = arr.transversal_segments[f];
  if (!transversal.empty())
    for (std::size_t j = 0; j < segments.size(); ++j) {
      if (!std::binary_search(transversal.begin(), transversal.end(), segments[j])) continue;
      const auto& line = face.collinear_sets[first_line + j];
      for (auto [s, t] : pieces)
        if (std::find(line.begin(), line.end(), s) != line.end() && std::find(line.begin(), line.end(), t) != line.end())
          transversal_pieces.emplace_back(s, t);
    }
  for (auto [s, t] : pieces) {
    out.curve_pieces.emplace_back(s, t);
    if (!face.on_one_edge(s, t)) face.constraints.emplace_back(s, t);
  }
  auto triangles = triangulate_polylines(face, points);
  if (!triangles) triangles = retriangulate_face(face, points);
  for (const auto& tri : *triangles) out.sub_faces.push_back({tri, f});
  find_opposite_sides(out, transversal_pieces);
  return out;
}

}  // namespace

SplitResult split_faces(const Operands& ops, const Arrangement& arr) {
  const std::uint32_t face_count = ops.face_count();
  std::vector<std::uint32_t> cut;
  for (std::uint32_t f = 0; f < face_count; ++f)
    if (arr.face_is_cut(ops, f)) cut.push_back(f);
  std::vector<FaceSplit> pieces(cut.size());
  const auto cut_count = static_cast<std::int64_t>(cut.size());
  ParallelExceptions errors;
#pragma omp parallel for schedule(dynamic, 16) if (cut_count > 128)
  for (std::int64_t k = 0; k < cut_count; ++k) errors.run(k, [&] { pieces[k] = split_one_face(ops, arr, cut[k]); });
  errors.rethrow();

  SplitResult result;
  result.split_faces = cut.size();
  result.first_sub_face.reserve(face_count + 1);
  result.cut.assign(face_count, 0);
  std::size_t next_cut = 0;
  for (std::uint32_t f = 0; f < face_count; ++f) {
    result.first_sub_face.push_back(static_cast<std::uint32_t>(result.sub_faces.size()));
    if (next_cut < cut.size() && cut[next_cut] == f) {
      result.cut[f] = 1;
      FaceSplit& p = pieces[next_cut++];
      const auto base = static_cast<std::uint32_t>(result.sub_faces.size());
      for (auto [x, y] : p.opposite_sides) result.opposite_sides.emplace_back(base + x, base + y);
      result.sub_faces.insert(result.sub_faces.end(), p.sub_faces.begin(), p.sub_faces.end());
      result.intersection_edges.insert(result.intersection_edges.end(), p.curve_pieces.begin(), p.curve_pieces.end());
      continue;
    }
    const auto& c = ops.face(f);
    result.sub_faces.push_back({{arr.vertex_point[c[0]], arr.vertex_point[c[1]], arr.vertex_point[c[2]]}, f});
  }
  result.first_sub_face.push_back(static_cast<std::uint32_t>(result.sub_faces.size()));
  std::sort(result.intersection_edges.begin(), result.intersection_edges.end());
  result.intersection_edges.erase(std::unique(result.intersection_edges.begin(), result.intersection_edges.end()),
                                  result.intersection_edges.end());
  return result;
}

}  // namespace molsurf::boolean_engine
