#pragma once
// The faces around each vertex, as both mesh editors (the cleanup and the rounding
// repair) keep it while they change a mesh. Sparse: a vertex gets its list when it is first
// given a face (the repair indexes only the faces near what rounding broke), so an index
// over a few faces of a large mesh costs one word per vertex.
#include <cstdint>
#include <span>
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
    for (Index v : t) std::erase(list(v), f);
  }
  // The faces around v, in the order they were added; empty for a vertex never given one.
  std::span<const std::uint32_t> of(Index v) const {
    if (slot_of_[v] == kNoSlot) return {};
    return slots_[slot_of_[v]];
  }

 private:
  std::vector<std::uint32_t>& list(Index v) {
    if (slot_of_[v] == kNoSlot) {
      slot_of_[v] = static_cast<std::uint32_t>(slots_.size());
      slots_.emplace_back();
    }
    return slots_[slot_of_[v]];
  }

  static constexpr std::uint32_t kNoSlot = ~std::uint32_t{0};
  std::vector<std::uint32_t> slot_of_;            // per vertex: its row in slots_
  std::vector<std::vector<std::uint32_t>> slots_;
};

}  // namespace molsurf
