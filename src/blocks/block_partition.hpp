#pragma once
// Atoms split into spatial blocks, and each block's halo: the atoms of other blocks whose
// polyhedra can reach a block atom's (the one-pass union's neighbour rule). A block's atoms
// trimmed by the block and its halo alone are trimmed exactly as in the whole union, since
// the trim of an atom reads only its neighbours; containment (an atom inside another's
// ball adds nothing) is decided once on the whole structure, since a halo atom's holder may
// lie beyond the halo.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/surface.hpp"

namespace molsurf::blocks {

struct BlockPartition {
  std::vector<std::uint32_t> block_of;            // per atom
  std::vector<std::uint8_t> contained;            // per atom: held by another atom's ball
  std::vector<std::vector<std::uint32_t>> atoms;  // per block, increasing atom index
  std::vector<std::vector<std::uint32_t>> halo;   // per block, increasing atom index

  std::size_t size() const { return atoms.size(); }
};

// `blocks` blocks balanced by atom count (bisect_coordinates), with their halos. With
// `halo_reach` > 0 a block's halo holds as well every atom of another block whose centre
// lies in the box of the block's centres grown by it (the SES's halo: ses_halo_reach).
BlockPartition partition_blocks(std::span<const Atom> atoms, const SphereOptions& options, std::size_t blocks,
                                double halo_reach = 0);

// One block's atoms and its halo, all that computing its piece needs, in increasing
// global index (the order the whole union decides ties by).
struct BlockAtoms {
  std::vector<Atom> atoms;
  std::vector<std::uint32_t> global_index;  // per atom here: its index in the whole structure
  std::vector<std::uint8_t> in_block;       // per atom here: 1 for the block's, 0 for the halo's
  std::vector<std::uint8_t> contained;      // per atom here: the whole structure's decision
};

BlockAtoms block_atoms(std::span<const Atom> atoms, const BlockPartition& partition, std::size_t block);

}  // namespace molsurf::blocks
