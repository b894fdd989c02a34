#pragma once
// What defines an intersection point: the simplest input elements it lies on. Keys are
// canonical, so every face that meets the same point names it the same way and the hash
// table of points shares it (paper §2.2.2 d).
#include <cstdint>
#include <functional>

#include "boolean/operands.hpp"
#include "geometry/implicit_point.hpp"

namespace molsurf::boolean_engine {

enum class PointKind : std::uint8_t {
  vertex,     // i: an input vertex (combined index)
  edge_face,  // i: an edge of one operand crossing the interior of face j of the other
  edge_edge,  // i: an edge of a and j: an edge of b crossing at a point inside both
};

struct PointKey {
  PointKind kind = PointKind::vertex;
  std::uint32_t i = 0, j = 0;
  friend bool operator==(const PointKey&, const PointKey&) = default;
  friend auto operator<=>(const PointKey&, const PointKey&) = default;
};

struct PointKeyHash {
  std::size_t operator()(const PointKey& k) const {
    const std::uint64_t h = (std::uint64_t(k.i) << 32 | k.j) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(h ^ (h >> 29) ^ static_cast<std::uint64_t>(k.kind));
  }
};

// The implicit point a key stands for, defined the same way whoever asks (deterministic).
geometry::ImplicitPoint make_point(const Operands& operands, const PointKey& key);

}  // namespace molsurf::boolean_engine
