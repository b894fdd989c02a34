#pragma once
// Patches joined into shells through what their boundaries share: the keys of their
// vertices and whole circles (sphere_arranger.hpp), and the aliases between two keys of one
// point (four or more spheres through it). Union-find over the patches, then the keys.
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "arrangement/sphere_arranger.hpp"

namespace molsurf::arrangement {

class PatchLinks {
 public:
  // patch_keys: (a key on a patch's boundary, the patch), patches numbered from 0.
  PatchLinks(std::size_t patches, std::span<const std::pair<Key, std::uint32_t>> patch_keys,
             std::span<const std::pair<Key, Key>> aliases);

  // The representative of a node: a patch p is node p, the k-th key node patches + k.
  std::uint32_t root(std::uint32_t node);
  std::uint32_t key_node(std::size_t k) const { return static_cast<std::uint32_t>(patches_ + k); }
  // Every key named, sorted, once each.
  std::span<const Key> keys() const { return keys_; }

 private:
  std::uint32_t node_of(const Key& key) const;
  void unite(std::uint32_t a, std::uint32_t b);

  std::size_t patches_ = 0;
  std::vector<Key> keys_;
  std::vector<std::uint32_t> parent_;
};

}  // namespace molsurf::arrangement
