// The union engine's pipeline: cull, intersect, split, classify, stitch (paper §2.2-2.4).
#include "molsurf/boolean.hpp"

#include <algorithm>
#include <array>
#include <chrono>

#include "boolean/active_part.hpp"
#include "boolean/arrangement.hpp"
#include "boolean/classify.hpp"
#include "boolean/cull.hpp"
#include "boolean/intersect.hpp"
#include "boolean/operands.hpp"
#include "boolean/repair_rounding.hpp"
#include "boolean/outer_envelope.hpp"
#include "boolean/split.hpp"
#include "boolean/stitch.hpp"
#include "common/parallel_exceptions.hpp"
#include "geometry/triangle_intersection.hpp"

namespace molsurf {

namespace {

// Above this many faces in the boxes' overlap, the finer cull (faces near the other
// surface) pays for its tree and rays.
constexpr std::size_t kNearCullFaces = 20000;
// Candidate face pairs intersected at a time (cull_intersect_split).
constexpr std::size_t kIntersectChunk = std::size_t{1} << 16;

}  // namespace

const char* boolean_op_name(BooleanOp op) {
  const auto index = static_cast<std::size_t>(op);
  return index < std::size(kBooleanOpNames) ? kBooleanOpNames[index].data() : "?";
}

namespace {

class StepTimer {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

namespace {

using namespace boolean_engine;

struct SplitArrangement {
  Arrangement arrangement;
  SplitResult split;
};

// The first three steps: cull, intersect, split.
SplitArrangement cull_intersect_split(const Operands& operands, BooleanStats& stats, StepTimer& timer) {
  // The candidates are intersected a chunk at a time and only the pairs that meet are kept:
  // most candidates do not, and a slot for each (over 100 bytes) held the SES's largest
  // block of memory through the arrangement and the split. The candidates go once
  // intersected, and the pairs once the arrangement holds what they found.
  std::vector<PairIntersection> pairs;
  {
    const auto candidates = cull_face_pairs(operands);
    stats.candidate_pairs = candidates.size();
    stats.seconds.cull += timer.lap();
    std::vector<PairIntersection> chunk;
    ParallelExceptions errors;
    for (std::size_t begin = 0; begin < candidates.size(); begin += kIntersectChunk) {
      const std::size_t end = std::min(candidates.size(), begin + kIntersectChunk);
      chunk.assign(end - begin, PairIntersection{});
      const auto count = static_cast<std::int64_t>(end - begin);
#pragma omp parallel for schedule(dynamic, 256) if (count > 2048)
      for (std::int64_t k = 0; k < count; ++k)
        errors.run(static_cast<std::int64_t>(begin) + k, [&] {
          const auto& [a, b] = candidates[begin + static_cast<std::size_t>(k)];
          chunk[static_cast<std::size_t>(k)] = intersect_faces(operands, a, b);
        });
      errors.rethrow();
      for (PairIntersection& p : chunk)
        if (!p.empty()) pairs.push_back(std::move(p));
    }
  }
  stats.intersecting_pairs = pairs.size();
  stats.coplanar_pairs = 0;
  for (const auto& p : pairs) stats.coplanar_pairs += p.coplanar;
  Arrangement arrangement = build_arrangement(operands, pairs);
  pairs = {};
  stats.intersection_points = arrangement.intersection_point_count;
  stats.seconds.intersect += timer.lap();

  SplitResult split = split_faces(operands, arrangement);
  stats.split_faces = split.split_faces;
  stats.seconds.split += timer.lap();
  return {std::move(arrangement), std::move(split)};
}

// The five steps on parts of the solids a and b (or on the solids themselves).

StitchResult run_steps(const Mesh& part_a, const Mesh& part_b, const Mesh& a, const Mesh& b,
                       const std::array<BoundingBox, 2>& boxes, BooleanOp op, BooleanStats& stats, StepTimer& timer) {
  const Operands operands(part_a, part_b, a, b, boxes);
  const auto [arrangement, split] = cull_intersect_split(operands, stats, timer);

  const Classification classes = classify_sub_faces(operands, arrangement, split);
  stats.ray_casts = classes.ray_casts;
  stats.exact_ray_casts = classes.exact_ray_casts;
  stats.seconds.classify += timer.lap();

  StitchResult stitched = stitch_sub_faces(operands, arrangement, split.sub_faces, classes.side, op);
  stats.split_vertices = stitched.split_vertices;
  // Output vertices that are input vertices: the part vertex they are (a's, then b's).
  for (std::uint32_t& p : stitched.vertex_point)
    if (p >= operands.vertex_count()) p = ~0u;
  stats.seconds.stitch += timer.lap();
  return stitched;
}

// The outer envelope: the steps up to split on the whole operands (passive faces are
// part of the envelope too, and may be open), then the flood fill instead of classify.
StitchResult run_outer_envelope(const Mesh& a, const Mesh& b, BooleanStats& stats, StepTimer& timer) {
  const Operands operands(a, b, a, b, /*allow_open=*/true);
  const auto [arrangement, split] = cull_intersect_split(operands, stats, timer);

  const EnvelopeSelection envelope = select_outer_envelope(operands, arrangement, split);
  stats.envelope_components = envelope.components;
  stats.envelope_components_kept = envelope.components_kept;
  stats.two_sided_faces = envelope.two_sided_faces;
  stats.seconds.classify += timer.lap();

  // Sheets seen from both sides (open operands) meet the rest along fins: no 2-manifold there.
  StitchResult stitched =
      stitch_sub_faces(operands, arrangement, split.sub_faces, envelope.keep, envelope.two_sided_faces == 0);
  stats.split_vertices = stitched.split_vertices;
  stats.seconds.stitch += timer.lap();
  return stitched;
}

void take_whole(BooleanResult& result, StitchResult&& stitched) {
  result.mesh = std::move(stitched.mesh);
  result.face_operand = std::move(stitched.face_operand);
  result.face_source = std::move(stitched.face_source);
}

}  // namespace

BooleanResult union_outer_envelope(const Mesh& a, const Mesh& b) {
  BooleanResult result;
  result.stats.faces_a = a.faces.size();
  result.stats.faces_b = b.faces.size();
  result.stats.active_faces = a.faces.size() + b.faces.size();
  StepTimer timer;
  take_whole(result, run_outer_envelope(a, b, result.stats, timer));
  result.stats.output_faces = result.mesh.faces.size();
  return result;
}

namespace {

// Whether a face of the active part's result that rounding can have turned over (a sliver
// or a tiny face) crosses a passive face at a vertex they share (exact). Faces
// [0, active_faces) and vertices [0, active_vertices) are the active part's.
bool passive_face_crossed(const Mesh& out, std::size_t active_faces, std::size_t active_vertices) {
  std::vector<std::pair<Index, std::uint32_t>> shared;  // (vertex, passive face)
  for (std::size_t g = active_faces; g < out.faces.size(); ++g)
    for (Index v : out.faces[g])
      if (v < active_vertices) shared.emplace_back(v, static_cast<std::uint32_t>(g));
  if (shared.empty()) return false;
  std::sort(shared.begin(), shared.end());
  for (std::size_t f = 0; f < active_faces; ++f) {
    const Triangle& t = out.faces[f];
    bool at_shared = false;
    for (Index v : t)
      at_shared |= std::binary_search(shared.begin(), shared.end(), std::pair<Index, std::uint32_t>{v, 0},
                                      [](const auto& x, const auto& y) { return x.first < y.first; });
    if (!at_shared || !boolean_engine::may_turn_over(out, t)) continue;
    for (Index v : t) {
      auto it = std::lower_bound(shared.begin(), shared.end(), std::pair<Index, std::uint32_t>{v, 0});
      for (; it != shared.end() && it->first == v; ++it)
        if (geometry::classify_triangle_pair(out, t, out.faces[it->second]) ==
            geometry::TrianglePairRelation::intersecting)
          return true;
    }
  }
  return false;
}

}  // namespace

BooleanResult boolean(const Mesh& a, const Mesh& b, BooleanOp op) {
  using namespace boolean_engine;
  BooleanResult result;
  BooleanStats& stats = result.stats;
  stats.faces_a = a.faces.size();
  stats.faces_b = b.faces.size();
  StepTimer timer;

  const std::array<BoundingBox, 2> boxes{bounding_box(a), bounding_box(b)};
  ActivePart part[2] = {active_part(a, boxes[1]), active_part(b, boxes[0])};
  auto active_count = [&] {
    return (part[0].whole ? a.faces.size() : part[0].mesh.faces.size()) +
           (part[1].whole ? b.faces.size() : part[1].mesh.faces.size());
  };
  // Per passive face, whether it lies inside the other solid; empty: every passive face is
  // outside (beyond the other's box).
  std::vector<std::uint8_t> passive_inside[2];
  // Solids whose boxes overlap far more than their surfaces do (a surface and scattered
  // local tools): only the faces near the other surface run the steps. Only when both
  // surfaces have many faces there: a few on one side already make few candidate pairs,
  // and the finer cull's tree and rays then cost more than they save (Table I's sphere and
  // slab, 37 000 and 1 200 faces in the overlap: 84 ms with it, 26 ms without).
  const std::size_t active_a = part[0].whole ? a.faces.size() : part[0].mesh.faces.size();
  const std::size_t active_b = part[1].whole ? b.faces.size() : part[1].mesh.faces.size();
  if (active_count() > kNearCullFaces && 4 * active_count() > a.faces.size() + b.faces.size() &&
      std::min(active_a, active_b) > kNearCullFaces / 4) {
    part[0] = active_part_near(a, b);
    part[1] = active_part_near(b, a);
    if (!part[0].whole || !part[1].whole) {
      passive_inside[0] = passive_sides(a, part[0], b);
      passive_inside[1] = passive_sides(b, part[1], a);
    }
  }
  stats.active_faces = active_count();
  stats.seconds.cull += timer.lap();
  if (part[0].whole && part[1].whole) {
    take_whole(result, run_steps(a, b, a, b, boxes, op, stats, timer));
    stats.output_faces = result.mesh.faces.size();
    return result;
  }
  const Mesh* solid[2] = {&a, &b};
  StitchResult stitched = run_steps(part[0].whole ? a : part[0].mesh, part[1].whole ? b : part[1].mesh, a, b,
                                    boxes, op, stats, timer);
  if (stitched.repair.refused_frozen > 0) {
    // A rounding repair needed a vertex that the passive faces share: redo it whole.
    stats.whole_reruns = 1;
    stats.active_faces = a.faces.size() + b.faces.size();
    take_whole(result, run_steps(a, b, a, b, boxes, op, stats, timer));
    stats.output_faces = result.mesh.faces.size();
    return result;
  }

  // Join the part's result with the passive faces: those of a are outside b (kept by
  // union and difference), those of b outside a (kept by union only).
  Mesh& out = result.mesh;
  out = std::move(stitched.mesh);
  const std::size_t stitched_faces = out.faces.size(), stitched_vertices = out.vertices.size();
  result.face_operand = std::move(stitched.face_operand);
  result.face_source = std::move(stitched.face_source);
  for (std::size_t k = 0; k < result.face_source.size(); ++k) {
    const ActivePart& p = part[result.face_operand[k]];
    if (!p.whole) result.face_source[k] = p.face_origin[result.face_source[k]];
  }
  // What the operation does with a passive face: by its side of the other solid.
  auto passive_keep = [&](int operand, std::size_t k) {
    const bool inside = !passive_inside[operand].empty() && passive_inside[operand][k] != 0;
    return select_sub_face(op, operand, inside ? Side::inside : Side::outside);
  };
  constexpr std::uint32_t unmapped = ~std::uint32_t{0};
  std::vector<std::uint32_t> out_vertex[2];
  for (int operand = 0; operand < 2; ++operand)
    if (!part[operand].passive_faces.empty()) out_vertex[operand].assign(solid[operand]->vertices.size(), unmapped);
  const auto part_vertices_a =
      static_cast<std::uint32_t>(part[0].whole ? a.vertices.size() : part[0].mesh.vertices.size());
  for (std::uint32_t v = 0; v < stitched.vertex_point.size(); ++v) {
    const std::uint32_t p = stitched.vertex_point[v];
    if (p == ~0u) continue;
    const int operand = p < part_vertices_a ? 0 : 1;
    if (out_vertex[operand].empty()) continue;
    const std::uint32_t local = operand == 0 ? p : p - part_vertices_a;
    out_vertex[operand][part[operand].whole ? local : part[operand].vertex_origin[local]] = v;
  }
  const bool tagged = a.has_tags() || b.has_tags();
  if (tagged && out.face_tags.size() != out.faces.size()) out.face_tags.resize(out.faces.size(), kNoTag);
  for (int operand = 0; operand < 2; ++operand) {
    const Mesh& m = *solid[operand];
    for (std::size_t k = 0; k < part[operand].passive_faces.size(); ++k) {
      const Keep keep = passive_keep(operand, k);
      if (keep == Keep::drop) continue;
      const std::uint32_t f = part[operand].passive_faces[k];
      Triangle t = m.faces[f];
      if (keep == Keep::keep_flipped) std::swap(t[1], t[2]);
      for (Index& v : t) {
        std::uint32_t& mapped = out_vertex[operand][v];
        if (mapped == unmapped) {
          mapped = static_cast<std::uint32_t>(out.vertices.size());
          out.vertices.push_back(m.vertices[v]);
        }
        v = mapped;
      }
      out.faces.push_back(t);
      result.face_operand.push_back(static_cast<std::uint8_t>(operand));
      result.face_source.push_back(f);
      if (tagged) out.face_tags.push_back(m.tag(f));
    }
  }
  if (passive_face_crossed(out, stitched_faces, stitched_vertices)) {
    // The rounding repair saw only the active part: a fold at a vertex it shares with the
    // passive faces can cross one of them. Redo it whole, where the repair sees them.
    stats.whole_reruns = 1;
    stats.active_faces = a.faces.size() + b.faces.size();
    take_whole(result, run_steps(a, b, a, b, boxes, op, stats, timer));
    stats.output_faces = result.mesh.faces.size();
    return result;
  }
  stats.output_faces = out.faces.size();
  stats.seconds.stitch += timer.lap();
  return result;
}

}  // namespace molsurf
