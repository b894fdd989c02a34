#pragma once
// What one process holds to make its blocks' pieces: atoms known by their index in the
// whole structure, and for each block it makes, which of them are the block's and which its
// halo's. A process alone, or the first of several (which read the structure), holds the
// whole structure and every block; each other process holds only the share the first sent
// it (block_share.hpp): its blocks' atoms, their halos and the atoms near them.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "blocks/block_partition.hpp"
#include "molsurf/atoms.hpp"

namespace molsurf::blocks {

struct BlockShare;

// Atoms by their index in the whole structure ("global"), held in increasing global index.
struct HeldAtoms {
  std::span<const Atom> atoms;
  std::span<const std::uint32_t> global_index;  // per held atom; empty: `atoms` is the whole structure
  std::span<const std::uint32_t> block_of;      // per held atom: its block
  std::span<const std::uint8_t> contained;      // per held atom: the whole structure's decision

  std::size_t size() const { return atoms.size(); }
  std::uint32_t global(std::size_t k) const {
    return global_index.empty() ? static_cast<std::uint32_t>(k) : global_index[k];
  }
  // The held atom whose global index is `g`; kNotHeld when this process does not hold it.
  static constexpr std::size_t kNotHeld = ~std::size_t{0};
  std::size_t local(std::uint32_t g) const;
};

class HeldBlocks {
 public:
  // The whole structure and every block of `partition` (both must outlive this).
  HeldBlocks(std::span<const Atom> atoms, const BlockPartition& partition);
  // A share received from the first process (which must outlive this).
  explicit HeldBlocks(const BlockShare& share);

  const HeldAtoms& held() const { return held_; }
  std::size_t block_count() const { return block_count_; }
  std::size_t total_atoms() const { return total_atoms_; }
  // Block b's atoms and its halo (std::logic_error when b is not held here).
  BlockAtoms block_atoms(std::size_t b) const;
  std::size_t block_size(std::size_t b) const { return lists(b).own.size(); }
  std::size_t halo_size(std::size_t b) const { return lists(b).halo.size(); }

 private:
  struct Lists {
    std::span<const std::uint32_t> own, halo;  // held atoms' positions, increasing
  };
  const Lists& lists(std::size_t b) const;
  HeldAtoms held_;
  std::size_t block_count_ = 0, total_atoms_ = 0;
  std::vector<std::size_t> blocks_;  // the blocks held, increasing
  std::vector<Lists> lists_;         // per block held
};

}  // namespace molsurf::blocks
