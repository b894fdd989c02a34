#include "blocks/block_partition.hpp"

#include <algorithm>
#include <stdexcept>

#include "blocks/coordinate_bisection.hpp"
#include "blocks/held_blocks.hpp"
#include "geometry/point_grid.hpp"
#include "surface/atom_polyhedra.hpp"

namespace molsurf::blocks {

BlockPartition partition_blocks(std::span<const Atom> atoms, const SphereOptions& options, std::size_t blocks) {
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
