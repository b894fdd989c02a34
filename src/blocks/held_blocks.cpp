#include "blocks/held_blocks.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "blocks/block_share.hpp"

namespace molsurf::blocks {

std::size_t HeldAtoms::local(std::uint32_t g) const {
  if (global_index.empty()) return g < atoms.size() ? g : kNotHeld;
  const auto it = std::lower_bound(global_index.begin(), global_index.end(), g);
  return it != global_index.end() && *it == g ? static_cast<std::size_t>(it - global_index.begin()) : kNotHeld;
}

HeldBlocks::HeldBlocks(std::span<const Atom> atoms, const BlockPartition& partition)
    : held_{atoms, {}, partition.block_of, partition.contained},
      block_count_(partition.size()),
      total_atoms_(atoms.size()) {
  for (std::size_t b = 0; b < partition.size(); ++b) {
    blocks_.push_back(b);
    lists_.push_back({partition.atoms[b], partition.halo[b]});
  }
}

HeldBlocks::HeldBlocks(const BlockShare& share)
    : held_{share.atoms, share.global_index, share.block_of, share.contained},
      block_count_(share.block_count),
      total_atoms_(share.total_atoms),
      blocks_(share.blocks) {
  for (std::size_t k = 0; k < share.blocks.size(); ++k) lists_.push_back({share.own[k], share.halo[k]});
}

const HeldBlocks::Lists& HeldBlocks::lists(std::size_t b) const {
  const auto it = std::lower_bound(blocks_.begin(), blocks_.end(), b);
  if (it == blocks_.end() || *it != b)
    throw std::logic_error("HeldBlocks: block " + std::to_string(b) + " is not held by this process");
  return lists_[static_cast<std::size_t>(it - blocks_.begin())];
}

BlockAtoms HeldBlocks::block_atoms(std::size_t b) const {
  const Lists& l = lists(b);
  BlockAtoms out;
  const std::size_t total = l.own.size() + l.halo.size();
  out.atoms.reserve(total);
  out.global_index.reserve(total);
  out.in_block.reserve(total);
  out.contained.reserve(total);
  // Both lists increase, and so do the held atoms' global indices: merged, the block and its
  // halo keep the whole structure's order.
  std::size_t a = 0, h = 0;
  while (a < l.own.size() || h < l.halo.size()) {
    const bool from_block = h == l.halo.size() || (a < l.own.size() && l.own[a] < l.halo[h]);
    const std::uint32_t k = from_block ? l.own[a++] : l.halo[h++];
    out.atoms.push_back(held_.atoms[k]);
    out.global_index.push_back(held_.global(k));
    out.in_block.push_back(from_block ? 1 : 0);
    out.contained.push_back(held_.contained[k]);
  }
  return out;
}

}  // namespace molsurf::blocks
