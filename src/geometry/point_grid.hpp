#pragma once
// Points by the cells of a uniform grid, hashed (only occupied cells are stored, so a
// sparse assembly costs what it holds). With cells as wide as the largest distance asked
// about, every point within that distance of p lies in the 27 cells around p's own: the
// neighbour search of atoms (their centres, cells of the largest diameter).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "molsurf/vec3.hpp"

namespace molsurf::geometry {

class PointGrid {
 public:
  // Indexes points[i] for every i that include(i) accepts, for neighbours up to `reach`
  // apart.
  template <class Include>
  PointGrid(std::span<const Vec3> points, double reach, Include&& include)
      // A millionth wider than asked: rounding in the cell computation cannot then put
      // two points `reach` apart two cells apart.
      : inverse_cell_(1 / (std::max(reach, 1e-6) * (1 + 1e-6))) {
    for (std::size_t i = 0; i < points.size(); ++i)
      if (include(i)) cells_[key(cell_of(points[i]))].push_back(static_cast<std::uint32_t>(i));
  }
  PointGrid(std::span<const Vec3> points, double reach) : PointGrid(points, reach, [](std::size_t) { return true; }) {}

  // Calls visit(i) for every indexed point in the 27 cells around p: each point once, cell
  // by cell, in increasing index within a cell. Distances are the caller's to test.
  template <class Visit>
  void for_each_near(const Vec3& p, Visit&& visit) const {
    const std::array<std::int64_t, 3> c = cell_of(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz)
          if (const auto it = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz})); it != cells_.end())
            for (std::uint32_t i : it->second) visit(i);
  }

 private:
  std::array<std::int64_t, 3> cell_of(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x * inverse_cell_)),
            static_cast<std::int64_t>(std::floor(p.y * inverse_cell_)),
            static_cast<std::int64_t>(std::floor(p.z * inverse_cell_))};
  }
  // 21 bits per axis: cells 2^21 apart share a key, which only adds candidates that the
  // caller's distance test drops.
  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    return (static_cast<std::uint64_t>(c[0]) & 0x1fffff) << 42 | (static_cast<std::uint64_t>(c[1]) & 0x1fffff) << 21 |
           (static_cast<std::uint64_t>(c[2]) & 0x1fffff);
  }

  double inverse_cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

}  // namespace molsurf::geometry
