#include "boolean/cull.hpp"

#include <algorithm>

#include "common/parallel_exceptions.hpp"
#include "geometry/face_bvh.hpp"

namespace molsurf::boolean_engine {

std::vector<std::pair<std::uint32_t, std::uint32_t>> cull_face_pairs(const Operands& operands) {
  const Mesh& a = operands.mesh(0);
  const Mesh& b = operands.mesh(1);
  BoundingBox overlap;
  {
    const BoundingBox box_a = bounding_box(a), box_b = bounding_box(b);
    if (box_a.empty() || box_b.empty() || !box_a.overlaps(box_b)) return {};
    overlap.min = {std::max(box_a.min.x, box_b.min.x), std::max(box_a.min.y, box_b.min.y),
                   std::max(box_a.min.z, box_b.min.z)};
    overlap.max = {std::min(box_a.max.x, box_b.max.x), std::min(box_a.max.y, box_b.max.y),
                   std::min(box_a.max.z, box_b.max.z)};
  }
  std::vector<std::uint8_t> b_near(b.faces.size());
  for (std::size_t f = 0; f < b.faces.size(); ++f) b_near[f] = geometry::face_box(b, f).overlaps(overlap);
  const geometry::BoxBvh tree = geometry::BoxBvh::for_faces(b, b_near);

  const auto face_count_a = static_cast<std::int64_t>(a.faces.size());
  const std::uint32_t offset_b = operands.face_offset_b();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  // Pairs in order of a's face, then b's (deterministic for any thread count).
  auto candidates_of = [&](std::uint32_t f, std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) {
    const BoundingBox box = geometry::face_box(a, f);
    if (!box.overlaps(overlap)) return;
    const std::size_t first = out.size();
    tree.for_each_overlap(box, [&](std::uint32_t g) { out.emplace_back(f, g + offset_b); });
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
  };
  // Small unions (most of a molecule's merge tree) stay serial: a parallel region costs more.
  if (face_count_a <= 8192) {
    for (std::uint32_t f = 0; f < a.faces.size(); ++f) candidates_of(f, pairs);
    return pairs;
  }
  constexpr std::int64_t kChunk = 1024;
  const std::int64_t chunks = (face_count_a + kChunk - 1) / kChunk;
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> per_chunk(chunks);
  ParallelExceptions errors;
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t c = 0; c < chunks; ++c)
    errors.run(c, [&] {
      for (std::int64_t f = c * kChunk; f < std::min(face_count_a, (c + 1) * kChunk); ++f)
        candidates_of(static_cast<std::uint32_t>(f), per_chunk[c]);
    });
  errors.rethrow();
  for (const auto& list : per_chunk) pairs.insert(pairs.end(), list.begin(), list.end());
  return pairs;
}

}  // namespace molsurf::boolean_engine
