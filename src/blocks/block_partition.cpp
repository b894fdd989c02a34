#include "blocks/block_partition.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "blocks/coordinate_bisection.hpp"
#include "blocks/held_blocks.hpp"
#include "geometry/point_grid.hpp"
#include "surface/atom_polyhedra.hpp"

namespace molsurf::blocks {

namespace {

// Every atom of another block whose centre lies in block b's box of centres grown by
// `reach`, added to its halo: the atoms sorted by x once, each block's slab found by
// bisection.
void add_atoms_within_reach(std::span<const Vec3> centres, double reach, BlockPartition& partition) {
  std::vector<std::uint32_t> by_x(centres.size());
  std::iota(by_x.begin(), by_x.end(), std::uint32_t{0});
  std::sort(by_x.begin(), by_x.end(), [&](std::uint32_t a, std::uint32_t b) {
    return centres[a].x < centres[b].x || (centres[a].x == centres[b].x && a < b);
  });
  for (std::size_t b = 0; b < partition.size(); ++b) {
    if (partition.atoms[b].empty()) continue;
    Vec3 low = centres[partition.atoms[b].front()], high = low;
    for (std::uint32_t i : partition.atoms[b]) {
      low = {std::min(low.x, centres[i].x), std::min(low.y, centres[i].y), std::min(low.z, centres[i].z)};
      high = {std::max(high.x, centres[i].x), std::max(high.y, centres[i].y), std::max(high.z, centres[i].z)};
    }
    const auto first = std::lower_bound(by_x.begin(), by_x.end(), low.x - reach,
                                        [&](std::uint32_t i, double x) { return centres[i].x < x; });
    for (auto it = first; it != by_x.end() && centres[*it].x <= high.x + reach; ++it) {
      const Vec3& c = centres[*it];
      if (partition.block_of[*it] != b && c.y >= low.y - reach && c.y <= high.y + reach && c.z >= low.z - reach &&
          c.z <= high.z + reach)
        partition.halo[b].push_back(*it);
    }
  }
}

}  // namespace

BlockPartition partition_blocks(std::span<const Atom> atoms, const SphereOptions& options, std::size_t blocks,
                                double halo_reach) {
  if (blocks == 0) throw std::invalid_argument("partition_blocks: at least one block");
  BlockPartition partition;
  const std::size_t n = atoms.size();
  std::vector<Vec3> centres(n);
  for (std::size_t i = 0; i < n; ++i) centres[i] = atoms[i].centre;
  partition.block_of = bisect_coordinates(centres, blocks);
  partition.atoms.resize(blocks);
  partition.halo.resize(blocks);
  for (std::uint32_t i = 0; i < n; ++i) partition.atoms[partition.block_of[i]].push_back(i);

  // The polyhedra's sizes and the containment, as the whole union computes them; only
  // per-atom numbers (no faces), freed on return.
  const surface_detail::AtomPolyhedra polyhedra(atoms, options);
  partition.contained.resize(n);
  double largest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    partition.contained[i] = polyhedra.contained(i) ? 1 : 0;
    if (!polyhedra.contained(i)) largest = std::max(largest, polyhedra.circumradius(i));
  }
  if (blocks == 1) return partition;
  // The neighbour rule of find_neighbours (atom_polyhedra.cpp), to the bit: a halo that
  // missed one neighbour would trim a block atom differently.
  const geometry::PointGrid grid(centres, 2 * largest, [&](std::size_t i) { return !polyhedra.contained(i); });
  for (std::uint32_t i = 0; i < n; ++i) {
    if (polyhedra.contained(i)) continue;
    const std::uint32_t block = partition.block_of[i];
    grid.for_each_near(centres[i], [&](std::uint32_t j) {
      if (partition.block_of[j] == block) return;
      const Vec3 d = centres[j] - centres[i];
      const double reach = polyhedra.circumradius(i) + polyhedra.circumradius(j);
      if (dot(d, d) <= reach * reach * (1 + 1e-9)) partition.halo[block].push_back(j);
    });
  }
  if (halo_reach > 0) add_atoms_within_reach(centres, halo_reach, partition);
  for (auto& halo : partition.halo) {
    std::sort(halo.begin(), halo.end());
    halo.erase(std::unique(halo.begin(), halo.end()), halo.end());
  }
  return partition;
}

BlockAtoms block_atoms(std::span<const Atom> atoms, const BlockPartition& partition, std::size_t block) {
  if (block >= partition.size()) throw std::invalid_argument("block_atoms: no such block");
  return HeldBlocks(atoms, partition).block_atoms(block);
}

}  // namespace molsurf::blocks
