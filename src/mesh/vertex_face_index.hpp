#pragma once
// The faces around each vertex, as both mesh editors (the cleanup and the rounding
// repair) keep it while they change a mesh. Sparse: a vertex gets its list when it is first
// given a face (the repair indexes only the faces near what rounding broke), so an index
// over a few faces of a large mesh costs one word per vertex.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf {

class VertexFaceIndex {
 public:
  explicit VertexFaceIndex(std::size_t vertices) : slot_of_(vertices, kNoSlot) {}

  // Face f listed around each of its corners, after the faces listed before (a face with
  // a repeated corner is listed once per occurrence). Not safe to run in parallel with
  // anything when it gives a vertex its first face.
  void add(std::uint32_t f, const Triangle& t) {
    for (Index v : t) list(v).push_back(f);
  }
  // Every face of `faces`, in order, as add() would list them, with each list allocated
  // once at its final size.
  void add_all(std::span<const Triangle> faces) {
    std::vector<std::uint32_t> count(slot_of_.size(), 0);
    for (const Triangle& t : faces)
      for (Index v : t) ++count[v];
    for (const Triangle& t : faces)
      for (Index v : t)
        if (slot_of_[v] == kNoSlot) list(v).reserve(count[v]);
    for (std::uint32_t f = 0; f < faces.size(); ++f) add(f, faces[f]);
  }
  // Face f (whose corners are t) no longer listed anywhere around them.
  void remove(std::uint32_t f, const Triangle& t) {
    for (Index v : t) list(v).erase(f);
  }
  // The faces around v, in the order they were added; empty for a vertex never given one.
  std::span<const std::uint32_t> of(Index v) const {
    if (slot_of_[v] == kNoSlot) return {};
    return slots_[slot_of_[v]].items();
  }

 private:
  // One vertex's faces: up to kInline of them in place (a surface's vertex has six faces
  // on average), more in one array of their own. 32 bytes, against a std::vector's 24
  // and its array's allocation for every vertex: on the largest surfaces this index is
  // one of the cleanup's largest arrays, and building it was one allocation per vertex.
  class FaceList {
   public:
    FaceList() = default;
    FaceList(FaceList&& other) noexcept { take(other); }
    FaceList& operator=(FaceList&& other) noexcept {
      if (this != &other) {
        release();
        take(other);
      }
      return *this;
    }
    FaceList(const FaceList&) = delete;
    FaceList& operator=(const FaceList&) = delete;
    ~FaceList() { release(); }

    std::span<const std::uint32_t> items() const { return {on_heap() ? heap_ : local_, size_}; }
    void reserve(std::size_t n) {
      if (n > capacity_) grow(static_cast<std::uint32_t>(n));
    }
    void push_back(std::uint32_t f) {
      if (size_ == capacity_) grow(capacity_ * 2);
      (on_heap() ? heap_ : local_)[size_++] = f;
    }
    // Every occurrence of f removed, the others kept in order.
    void erase(std::uint32_t f) {
      std::uint32_t* items = on_heap() ? heap_ : local_;
      size_ = static_cast<std::uint32_t>(std::remove(items, items + size_, f) - items);
    }

   private:
    bool on_heap() const { return capacity_ > kInline; }
    // Other's faces moved here (this holds none), other left empty.
    void take(FaceList& other) {
      size_ = other.size_;
      capacity_ = other.capacity_;
      if (on_heap())
        heap_ = std::exchange(other.heap_, nullptr);
      else
        std::copy_n(other.local_, size_, local_);
      other.size_ = 0;
      other.capacity_ = kInline;
    }
    void grow(std::uint32_t capacity) {
      std::uint32_t* bigger = std::allocator<std::uint32_t>().allocate(capacity);
      std::copy_n(on_heap() ? heap_ : local_, size_, bigger);
      release();
      heap_ = bigger;
      capacity_ = capacity;
    }
    void release() {
      if (on_heap()) std::allocator<std::uint32_t>().deallocate(heap_, capacity_);
    }

    static constexpr std::uint32_t kInline = 6;
    std::uint32_t size_ = 0, capacity_ = kInline;
    union {
      std::uint32_t local_[kInline];
      std::uint32_t* heap_;
    };
  };
  static_assert(sizeof(FaceList) == 32);

  FaceList& list(Index v) {
    if (slot_of_[v] == kNoSlot) {
      slot_of_[v] = static_cast<std::uint32_t>(slots_.size());
      slots_.emplace_back();
    }
    return slots_[slot_of_[v]];
  }

  static constexpr std::uint32_t kNoSlot = ~std::uint32_t{0};
  std::vector<std::uint32_t> slot_of_;  // per vertex: its row in slots_
  std::vector<FaceList> slots_;
};

}  // namespace molsurf
