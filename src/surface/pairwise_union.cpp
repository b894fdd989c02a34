#include "surface/pairwise_union.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <numeric>
#include <optional>
#include <vector>

#include "common/parallel_exceptions.hpp"
#include "molsurf/boolean.hpp"
#include "surface/atom_polyhedra.hpp"

namespace molsurf::surface_detail {

namespace {

// One merge of the tree. `checked`: the union checked, with the second operand moved by a
// step far below the facets where no rounding of the exact union is valid
// (valid_boolean), so that no merge hands a broken operand on; a check per merge more
// than doubles the method's time (the merges work on the faces near the other operand,
// the check on all), so it is the second try, when the plain tree's surface fails.
BooleanResult union_merge(const Mesh& left, const Mesh& right, bool checked) {
  if (!checked) return boolean(left, right, BooleanOp::union_);
  MeshCheckOptions quick;
  quick.max_examples = 1;
  return valid_boolean(left, right, BooleanOp::union_, quick).result;
}

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

// The merge tree: node (h, k) covers leaves [k 2^h, (k + 1) 2^h) of the spatial order.
// It is the union of its two children, or its left child alone when the right one would
// be empty (an odd end of a level). The same tree whatever the evaluation order.
class MergeTree {
 public:
  MergeTree(std::span<const Atom> atoms, const std::vector<std::uint32_t>& order, const SphereOptions& spheres,
            bool checked)
      : atoms_(atoms), order_(order), spheres_(spheres), checked_(checked) {}

  bool exists(std::size_t height, std::size_t k) const { return (k << height) < order_.size(); }

  // Node (h, k) evaluated depth first; each merge's statistics go to `levels[its height - 1]`.
  Mesh evaluate(std::size_t height, std::size_t k, std::vector<SurfaceLevel>& levels) const {
    if (height == 0) {
      const std::uint32_t atom = order_[k];
      return atom_sphere(atoms_[atom], static_cast<std::int32_t>(atom), spheres_);
    }
    if (!exists(height - 1, 2 * k + 1)) return evaluate(height - 1, 2 * k, levels);
    BooleanResult merged;
    std::chrono::steady_clock::time_point start;
    {
      const Mesh left = evaluate(height - 1, 2 * k, levels);
      const Mesh right = evaluate(height - 1, 2 * k + 1, levels);
      start = std::chrono::steady_clock::now();
      merged = union_merge(left, right, checked_);
    }
    SurfaceLevel& level = levels[height - 1];
    level += merged.stats;
    level.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::move(merged.mesh);
  }

 private:
  std::span<const Atom> atoms_;
  const std::vector<std::uint32_t>& order_;
  const SphereOptions& spheres_;
  bool checked_;
};

void merge_tree(std::span<const Atom> atoms, const SphereUnionOptions& options, int threads, bool checked,
                SphereUnion& result) {
  // Atoms inside another's ball add nothing to the union (copies: the lowest index stands
  // for all; as in the one-pass method); merging them only multiplies coincident faces.
  std::vector<std::uint32_t> order = spatial_order(atoms);
  {
    const AtomPolyhedra polyhedra(atoms, options.spheres);
    std::erase_if(order, [&](std::uint32_t a) { return polyhedra.contained(a); });
  }
  std::size_t height = 0;  // of the whole tree
  while ((std::size_t{1} << height) < order.size()) ++height;
  const MergeTree tree(atoms, order, options.spheres, checked);
  result.level_stats.resize(height);
  const std::size_t total_merges = order.size() - 1;
  std::size_t merges_done = 0;

  // Bottom part: whole subtrees, one per thread at a time, each depth first. Only the
  // meshes on the path being merged are alive (a level at a time held every sphere of
  // the structure at once), and each subtree's spheres stay in one core's cache. The
  // subtrees' height leaves at least 8 per thread to balance the load.
  std::size_t subtree_height = 0;
  while (subtree_height < height && (order.size() >> (subtree_height + 1)) >= 8 * static_cast<std::size_t>(threads))
    ++subtree_height;
  const std::size_t subtrees = ((order.size() - 1) >> subtree_height) + 1;
  std::vector<std::optional<Mesh>> level(subtrees);
  std::vector<std::vector<SurfaceLevel>> subtree_levels(subtrees, std::vector<SurfaceLevel>(height));
  const auto bottom_start = std::chrono::steady_clock::now();
  const auto subtree_count = static_cast<std::int64_t>(subtrees);
  ParallelExceptions errors;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::int64_t k = 0; k < subtree_count; ++k)
    errors.run(k, [&] {
      if (cancel_requested(options.cancel)) return;
      level[k] = tree.evaluate(subtree_height, static_cast<std::size_t>(k), subtree_levels[k]);
      std::size_t merges = 0;
      for (const SurfaceLevel& l : subtree_levels[k]) merges += l.merges;
#pragma omp critical(surface_progress)
      {
        merges_done += merges;
        if (options.progress) options.progress(merges_done, total_merges);
      }
    });
  errors.rethrow();
  throw_if_cancelled(options.cancel);
  for (const auto& levels : subtree_levels)
    for (std::size_t h = 0; h < height; ++h) result.level_stats[h] += levels[h];
  result.seconds.subtrees = std::chrono::duration<double>(std::chrono::steady_clock::now() - bottom_start).count();
  result.subtree_height = subtree_height;

  // Top part: level by level. Many merges: one per thread. Few large ones: one at a
  // time, each using all threads inside the engine. Either way the result is the same.
  for (std::size_t h = subtree_height; level.size() > 1; ++h) {
    const std::size_t pairs = level.size() / 2;
    std::vector<std::optional<Mesh>> next((level.size() + 1) / 2);
    const auto pair_count = static_cast<std::int64_t>(pairs);
    std::vector<BooleanStats> merge_stats(pairs);
    const auto level_start = std::chrono::steady_clock::now();
    auto merge = [&](std::int64_t k) {
      throw_if_cancelled(options.cancel);
      BooleanResult merged = union_merge(*level[2 * k], *level[2 * k + 1], checked);
      merge_stats[k] = merged.stats;
      next[k] = std::move(merged.mesh);
      level[2 * k].reset();
      level[2 * k + 1].reset();
    };
    if (pairs >= static_cast<std::size_t>(threads)) {
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
      for (std::int64_t k = 0; k < pair_count; ++k) errors.run(k, [&] { merge(k); });
      errors.rethrow();
    } else {
      for (std::int64_t k = 0; k < pair_count; ++k) merge(k);
    }
    if (level.size() % 2 == 1) next.back() = std::move(level.back());
    merges_done += pairs;
    SurfaceLevel& stats = result.level_stats[h];
    for (const BooleanStats& m : merge_stats) stats += m;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - level_start).count();
    if (options.progress) options.progress(merges_done, total_merges);
    level = std::move(next);
  }
  result.mesh = std::move(*level[0]);
  result.merges = total_merges;
  result.levels = height;
}

}  // namespace

void pairwise_union(std::span<const Atom> atoms, const SphereUnionOptions& options, int threads, SphereUnion& result) {
  merge_tree(atoms, options, threads, /*checked=*/false, result);
  MeshCheckOptions quick;
  quick.max_examples = 1;
  if (check_mesh(result.mesh, quick).valid()) return;
  // A merge met sheets closer than rounding keeps apart (three rounded points within an
  // ulp of one point of the input, icosahedral shells at frequency 1): again, each merge
  // checked.
  result.level_stats.clear();
  merge_tree(atoms, options, threads, /*checked=*/true, result);
}

}  // namespace molsurf::surface_detail
