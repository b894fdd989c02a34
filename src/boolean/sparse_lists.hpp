#pragma once
// Lists indexed by face or by edge of the operands, where most indices have none: the
// arrangement's points and constraints lie on the few faces where the surfaces meet. Each
// index costs 4 bytes (a slot number) instead of an empty std::vector's 24, which on the
// SES's carving (millions of faces and edges, six such tables) was most of the
// arrangement's memory.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace molsurf::boolean_engine {

template <class T>
class SparseLists {
 public:
  // `count` indices, every list empty.
  void resize(std::size_t count) {
    slot_.assign(count, kNone);
    lists_.clear();
  }
  std::size_t size() const { return slot_.size(); }
  // Index i's list (empty when nothing was added to it).
  const std::vector<T>& operator[](std::size_t i) const {
    const std::uint32_t s = slot_[i];
    return s == kNone ? none_ : lists_[s];
  }
  // Index i's list, to add to.
  std::vector<T>& list(std::size_t i) {
    std::uint32_t& s = slot_[i];
    if (s == kNone) {
      s = static_cast<std::uint32_t>(lists_.size());
      lists_.emplace_back();
    }
    return lists_[s];
  }
  // Every list that was added to, in the order first added to.
  std::span<std::vector<T>> lists() { return lists_; }

 private:
  static constexpr std::uint32_t kNone = ~std::uint32_t{0};
  std::vector<std::uint32_t> slot_;
  std::vector<std::vector<T>> lists_;
  std::vector<T> none_;
};

}  // namespace molsurf::boolean_engine
