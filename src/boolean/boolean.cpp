// The union engine's pipeline: cull, intersect, split, classify, stitch (paper §2.2-2.4).
#include "molsurf/boolean.hpp"

#include <chrono>

#include "boolean/arrangement.hpp"
#include "boolean/classify.hpp"
#include "boolean/cull.hpp"
#include "boolean/intersect.hpp"
#include "boolean/operands.hpp"
#include "boolean/split.hpp"
#include "boolean/stitch.hpp"

namespace molsurf {

const char* boolean_op_name(BooleanOp op) {
  switch (op) {
    case BooleanOp::union_: return "union";
    case BooleanOp::intersection: return "intersection";
    case BooleanOp::difference: return "difference";
  }
  return "?";
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

BooleanResult boolean(const Mesh& a, const Mesh& b, BooleanOp op) {
  using namespace boolean_engine;
  BooleanResult result;
  BooleanStats& stats = result.stats;
  stats.faces_a = a.faces.size();
  stats.faces_b = b.faces.size();
  StepTimer timer;

  const Operands operands(a, b);
  const auto candidates = cull_face_pairs(operands);
  stats.candidate_pairs = candidates.size();
  stats.seconds.cull = timer.lap();

  std::vector<PairIntersection> pairs(candidates.size());
  const auto pair_count = static_cast<std::int64_t>(candidates.size());
#pragma omp parallel for schedule(dynamic, 256) if (pair_count > 2048)
  for (std::int64_t k = 0; k < pair_count; ++k)
    pairs[k] = intersect_faces(operands, candidates[k].first, candidates[k].second);
  std::erase_if(pairs, [](const PairIntersection& p) { return p.empty(); });
  stats.intersecting_pairs = pairs.size();
  for (const auto& p : pairs) stats.coplanar_pairs += p.coplanar;
  const Arrangement arrangement = build_arrangement(operands, pairs);
  stats.intersection_points = arrangement.intersection_point_count;
  stats.seconds.intersect = timer.lap();

  const SplitResult split = split_faces(operands, arrangement);
  stats.split_faces = split.split_faces;
  stats.seconds.split = timer.lap();

  const Classification classes = classify_sub_faces(operands, arrangement, split);
  stats.exact_ray_casts = classes.exact_ray_casts;
  stats.seconds.classify = timer.lap();

  StitchResult stitched = stitch_sub_faces(operands, arrangement, split.sub_faces, classes.side, op);
  stats.split_vertices = stitched.split_vertices;
  result.mesh = std::move(stitched.mesh);
  result.face_operand = std::move(stitched.face_operand);
  result.face_source = std::move(stitched.face_source);
  stats.output_faces = result.mesh.faces.size();
  stats.seconds.stitch = timer.lap();
  return result;
}

}  // namespace molsurf
