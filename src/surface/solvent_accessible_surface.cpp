#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <numeric>
#include <optional>

#include "molsurf/boolean.hpp"
#include "molsurf/surface.hpp"

namespace molsurf {

namespace {

// The leaf order of the merge tree. The tree joins consecutive pairs level by level, so a
// node at height h covers order positions [k 2^h, (k + 1) 2^h): its left child holds the
// first 2^(h-1) of them. Each node's atoms are split there by their coordinate along the
// longest extent of their centres (ties by atom index: deterministic), a k-d tree whose
// two halves of any node lie on either side of one plane.
void order_subtree(std::span<const Atom> atoms, std::span<std::uint32_t> ids, std::size_t height) {
  if (ids.size() <= 1 || height == 0) return;
  const std::size_t left = std::size_t{1} << (height - 1);
  if (ids.size() <= left) {  // only a left child: nothing to split at this height
    order_subtree(atoms, ids, height - 1);
    return;
  }
  BoundingBox box;
  for (std::uint32_t i : ids) box.extend(atoms[i].centre);
  const Vec3 extent = box.max - box.min;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  std::nth_element(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(left), ids.end(),
                   [&](std::uint32_t i, std::uint32_t j) {
                     const double ci = atoms[i].centre[axis], cj = atoms[j].centre[axis];
                     return ci != cj ? ci < cj : i < j;
                   });
  order_subtree(atoms, ids.first(left), height - 1);
  order_subtree(atoms, ids.subspan(left), height - 1);
}

std::vector<std::uint32_t> spatial_order(std::span<const Atom> atoms) {
  std::vector<std::uint32_t> order(atoms.size());
  std::iota(order.begin(), order.end(), 0u);
  std::size_t height = 0;
  while ((std::size_t{1} << height) < atoms.size()) ++height;
  order_subtree(atoms, order, height);
  return order;
}

// The engine's own parallel loops use the default team size: make it the caller's thread
// count for the duration (with one outer thread, inner regions would otherwise start
// spinning workers on every core).
class ThreadCountScope {
 public:
  explicit ThreadCountScope(int threads) : previous_(omp_get_max_threads()) { omp_set_num_threads(threads); }
  ~ThreadCountScope() { omp_set_num_threads(previous_); }
  ThreadCountScope(const ThreadCountScope&) = delete;
  ThreadCountScope& operator=(const ThreadCountScope&) = delete;

 private:
  int previous_;
};

}  // namespace

SurfaceLevel& SurfaceLevel::operator+=(const BooleanStats& m) {
  ++merges;
  faces_in += m.faces_a + m.faces_b;
  active_faces += m.active_faces;
  faces_out += m.output_faces;
  split_faces += m.split_faces;
  ray_casts += m.ray_casts;
  whole_reruns += m.whole_reruns;
  steps.cull += m.seconds.cull;
  steps.intersect += m.seconds.intersect;
  steps.split += m.seconds.split;
  steps.classify += m.seconds.classify;
  steps.stitch += m.seconds.stitch;
  return *this;
}

SurfaceLevel& SurfaceLevel::operator+=(const SurfaceLevel& o) {
  merges += o.merges;
  faces_in += o.faces_in;
  active_faces += o.active_faces;
  faces_out += o.faces_out;
  split_faces += o.split_faces;
  ray_casts += o.ray_casts;
  whole_reruns += o.whole_reruns;
  steps.cull += o.steps.cull;
  steps.intersect += o.steps.intersect;
  steps.split += o.steps.split;
  steps.classify += o.steps.classify;
  steps.stitch += o.steps.stitch;
  seconds += o.seconds;
  return *this;
}

SurfaceResult solvent_accessible_surface(std::span<const Atom> atoms, const SurfaceOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SurfaceResult result;
  if (atoms.empty()) return result;
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  const ThreadCountScope thread_count(threads);

  // Level 0: one (lazily built) sphere per atom, in spatial order.
  const std::vector<std::uint32_t> order = spatial_order(atoms);
  std::vector<std::optional<Mesh>> level(order.size());
  auto mesh_at = [&](std::size_t k) -> Mesh& {
    if (!level[k]) {
      const std::uint32_t atom = order[k];
      level[k] = atom_sphere(atoms[atom], static_cast<std::int32_t>(atom), options.spheres);
    }
    return *level[k];
  };
  const std::size_t total_merges = order.size() - 1;
  std::size_t merges_done = 0;
  while (level.size() > 1) {
    const std::size_t pairs = level.size() / 2;
    std::vector<std::optional<Mesh>> next((level.size() + 1) / 2);
    const auto pair_count = static_cast<std::int64_t>(pairs);
    std::vector<BooleanStats> merge_stats(pairs);
    const auto level_start = std::chrono::steady_clock::now();
    // Many small merges: one per thread. Few large ones: one at a time, each using all
    // threads inside the engine. Either way the result is the same.
    if (pairs >= static_cast<std::size_t>(threads)) {
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
      for (std::int64_t k = 0; k < pair_count; ++k) {
        Mesh& a = mesh_at(2 * k);
        Mesh& b = mesh_at(2 * k + 1);
        BooleanResult merged = boolean(a, b, BooleanOp::union_);
        merge_stats[k] = merged.stats;
        next[k] = std::move(merged.mesh);
        level[2 * k].reset();
        level[2 * k + 1].reset();
      }
    } else {
      for (std::int64_t k = 0; k < pair_count; ++k) {
        BooleanResult merged = boolean(mesh_at(2 * k), mesh_at(2 * k + 1), BooleanOp::union_);
        merge_stats[k] = merged.stats;
        next[k] = std::move(merged.mesh);
        level[2 * k].reset();
        level[2 * k + 1].reset();
      }
    }
    if (level.size() % 2 == 1) next.back() = std::move(mesh_at(level.size() - 1));
    merges_done += pairs;
    ++result.levels;
    SurfaceLevel& stats = result.level_stats.emplace_back();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - level_start).count();
    for (const BooleanStats& m : merge_stats) stats += m;
    if (options.progress) options.progress(merges_done, total_merges);
    level = std::move(next);
  }
  result.mesh = std::move(mesh_at(0));
  result.merges = total_merges;
  result.seconds.total = result.seconds.union_levels =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace molsurf
