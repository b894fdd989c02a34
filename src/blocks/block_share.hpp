#pragma once
// The structure dealt out to the processes of an exchange (mpirun): the first process alone
// reads it, checks its spheres and cuts it into blocks, then sends every other process its
// share, and no other process ever holds the whole structure. A share is what the process's
// blocks (b = rank, rank + size, ...) need: each block's atoms, its halo (the atoms whose
// polyhedra can reach the block's), and the atoms near the block whose spheres' boxes the
// streamed piece's border is cut against (streamed_piece.hpp), each with every field of its
// record (the pieces' files name the atoms' residues and chains) and its index in the whole
// structure, so keys, face tags and the merged report are the same as from the whole.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "blocks/block_partition.hpp"
#include "blocks/blocked_surface.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/vec3.hpp"

namespace molsurf::blocks {

struct BlockShare {
  // On the first process (and a process alone): the whole job's partition; it makes its
  // blocks from the whole structure, which stays the caller's. Empty on the others.
  std::optional<BlockPartition> partition;
  // On the others: what they hold.
  std::size_t block_count = 0, total_atoms = 0;
  Vec3 origin;  // the whole structure's (volume_origin): every piece's volume is taken about it
  std::vector<Atom> atoms;  // in increasing global index
  std::vector<std::uint32_t> global_index, block_of;
  std::vector<std::uint8_t> contained;
  std::vector<std::size_t> blocks;                    // made here, increasing
  std::vector<std::vector<std::uint32_t>> own, halo;  // per block made here: positions in `atoms`
};

// The share of process `rank` of `size` (blocks rank, rank + size, ...): its blocks' atoms,
// their halos, and every atom of another block whose sphere's box, grown by the border's
// reach and half an angstrom, meets such a box of one of the block's atoms (a superset of
// the atoms split_piece cuts the border against, for every face that check_seams accepts).
// `spheres`: the job's (surface_job_options).
BlockShare share_of_process(std::span<const Atom> atoms, const BlockPartition& partition, const SphereOptions& spheres,
                            int rank, int size);

// A share (without its partition) as bytes, and back (std::invalid_argument for bytes
// block_share_bytes did not write).
std::string block_share_bytes(const BlockShare& share);
BlockShare read_block_share(std::string_view bytes);

// Collective over `blocked.exchange`: on the first process (or one alone) `atoms` is the
// whole structure, checked as compute_blocked_surface checks it and cut into blocks; every
// other process receives its share (its `atoms` argument is ignored). What the first
// process finds wrong before the shares go out is thrown on every process.
BlockShare share_blocks(std::span<const Atom> atoms, const ComputeSurfaceOptions& options,
                        const BlockedSurfaceOptions& blocked);

}  // namespace molsurf::blocks
