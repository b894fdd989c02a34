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

// Interleaves the bits of three 21-bit integers: the Morton (Z-order) code.
std::uint64_t spread_bits(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffull;
  v = (v | v << 16) & 0x1f0000ff0000ffull;
  v = (v | v << 8) & 0x100f00f00f00f00full;
  v = (v | v << 4) & 0x10c30c30c30c30c3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}

// Atom indices in Z-order of their centres (ties by index: deterministic).
std::vector<std::uint32_t> spatial_order(std::span<const Atom> atoms) {
  BoundingBox box;
  for (const Atom& a : atoms) box.extend(a.centre);
  const Vec3 extent = box.max - box.min;
  const double size = std::max({extent.x, extent.y, extent.z, 1e-9});
  auto cell = [&](double x, double lo) {
    return static_cast<std::uint64_t>(std::clamp((x - lo) / size, 0.0, 1.0) * 2097151.0);
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(atoms.size());
  for (std::uint32_t i = 0; i < atoms.size(); ++i) {
    const Vec3& c = atoms[i].centre;
    keyed[i] = {spread_bits(cell(c.x, box.min.x)) | spread_bits(cell(c.y, box.min.y)) << 1 |
                    spread_bits(cell(c.z, box.min.z)) << 2,
                i};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order(atoms.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].second;
  return order;
}

}  // namespace

SurfaceResult solvent_accessible_surface(std::span<const Atom> atoms, const SurfaceOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SurfaceResult result;
  if (atoms.empty()) return result;
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();

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
    // Many small merges: one per thread. Few large ones: one at a time, each using all
    // threads inside the engine. Either way the result is the same.
    if (pairs >= static_cast<std::size_t>(threads)) {
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
      for (std::int64_t k = 0; k < pair_count; ++k) {
        Mesh& a = mesh_at(2 * k);
        Mesh& b = mesh_at(2 * k + 1);
        next[k] = boolean(a, b, BooleanOp::union_).mesh;
        level[2 * k].reset();
        level[2 * k + 1].reset();
      }
    } else {
      for (std::int64_t k = 0; k < pair_count; ++k) {
        next[k] = boolean(mesh_at(2 * k), mesh_at(2 * k + 1), BooleanOp::union_).mesh;
        level[2 * k].reset();
        level[2 * k + 1].reset();
      }
    }
    if (level.size() % 2 == 1) next.back() = std::move(mesh_at(level.size() - 1));
    merges_done += pairs;
    ++result.levels;
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
