#include "arrangement/patch_links.hpp"

#include <algorithm>
#include <numeric>

namespace molsurf::arrangement {

PatchLinks::PatchLinks(std::size_t patches, std::span<const std::pair<Key, std::uint32_t>> patch_keys,
                       std::span<const std::pair<Key, Key>> aliases)
    : patches_(patches) {
  keys_.reserve(patch_keys.size() + 2 * aliases.size());
  for (const auto& pk : patch_keys) keys_.push_back(pk.first);
  for (const auto& [x, y] : aliases) {
    keys_.push_back(x);
    keys_.push_back(y);
  }
  std::sort(keys_.begin(), keys_.end());
  keys_.erase(std::unique(keys_.begin(), keys_.end()), keys_.end());
  parent_.resize(patches + keys_.size());
  std::iota(parent_.begin(), parent_.end(), 0u);
  for (const auto& [key, patch] : patch_keys) unite(patch, node_of(key));
  for (const auto& [x, y] : aliases) unite(node_of(x), node_of(y));
}

std::uint32_t PatchLinks::node_of(const Key& key) const {
  return key_node(static_cast<std::size_t>(std::lower_bound(keys_.begin(), keys_.end(), key) - keys_.begin()));
}

std::uint32_t PatchLinks::root(std::uint32_t v) {
  while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
  return v;
}

void PatchLinks::unite(std::uint32_t a, std::uint32_t b) {
  a = root(a);
  b = root(b);
  parent_[std::max(a, b)] = std::min(a, b);
}

}  // namespace molsurf::arrangement
