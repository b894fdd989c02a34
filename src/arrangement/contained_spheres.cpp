#include "arrangement/contained_spheres.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>

#include "arrangement/sphere_predicates.hpp"

namespace molsurf::arrangement {

namespace {

// The kept spheres of radius in [2^level, 2^(level + 1)), by cells of side 2^(level + 2):
// a ball holding a sphere centred at p has its centre within its own radius, less than
// half a cell, of p, so in one of the 8 cells nearest p (along each axis, p's cell and the
// neighbour on p's nearer side).
class LevelGrid {
 public:
  explicit LevelGrid(int level) : inverse_cell_(std::ldexp(1.0, -(level + 2)) / (1 + 1e-6)) {}

  void insert(const Vec3& p, std::uint32_t sphere) {
    std::array<std::int64_t, 3> c;
    std::array<int, 3> side;
    cell_of(p, c, side);
    cells_[key(c)].push_back(sphere);
  }

  // Stops at the first sphere `found` accepts; returns it, or `none`.
  template <class Found>
  std::uint32_t find_near(const Vec3& p, std::uint32_t none, Found&& found) const {
    std::array<std::int64_t, 3> c;
    std::array<int, 3> side;
    cell_of(p, c, side);
    for (int corner = 0; corner < 8; ++corner) {
      const std::array<std::int64_t, 3> cell{c[0] + (corner & 1 ? side[0] : 0), c[1] + (corner & 2 ? side[1] : 0),
                                             c[2] + (corner & 4 ? side[2] : 0)};
      if (const auto it = cells_.find(key(cell)); it != cells_.end())
        for (const std::uint32_t j : it->second)
          if (found(j)) return j;
    }
    return none;
  }

 private:
  // p's cell, and per axis the step (-1 or +1) to the neighbour on p's nearer side.
  void cell_of(const Vec3& p, std::array<std::int64_t, 3>& cell, std::array<int, 3>& side) const {
    for (int a = 0; a < 3; ++a) {
      // Clamped before the conversion: a tiny cell far from the origin exceeds int64.
      const double scaled = std::clamp(p[a] * inverse_cell_, -4e18, 4e18), floor = std::floor(scaled);
      cell[a] = static_cast<std::int64_t>(floor);
      side[a] = scaled - floor < 0.5 ? -1 : 1;
    }
  }
  // Cells 2^21 apart share a key: that only adds candidates, which the exact test drops.
  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    return (static_cast<std::uint64_t>(c[0]) & 0x1fffff) << 42 | (static_cast<std::uint64_t>(c[1]) & 0x1fffff) << 21 |
           (static_cast<std::uint64_t>(c[2]) & 0x1fffff);
  }

  double inverse_cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

// Radii below 2^-30 A share the lowest level (a wider cell only adds candidates); radii
// are below 1e16 (the readers' bound), so levels stay under 54.
int level_of(double radius) { return radius > 0x1p-30 ? std::ilogb(radius) : -30; }

}  // namespace

std::vector<std::uint32_t> sphere_containers(std::span<const Vec3> centres, std::span<const double> radii) {
  const std::size_t n = centres.size();
  std::vector<std::uint32_t> container(n);
  std::iota(container.begin(), container.end(), 0u);
  // Largest first, ties by index: a sphere's possible holders (as large or larger, and of
  // its copies the lower indices) are settled before it.
  std::vector<std::uint32_t> order(container);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return radii[a] != radii[b] ? radii[a] > radii[b] : a < b; });
  std::map<int, LevelGrid> levels;
  DecisionCounter decisions;
  constexpr std::uint32_t kNone = ~std::uint32_t{0};
  for (const std::uint32_t i : order) {
    const Vec3& c = centres[i];
    std::uint32_t holder = kNone;
    // Levels whose cells are wider than r_i: a holder's radius is at least r_i. Held
    // spheres are never inserted: what holds them holds whatever they hold.
    for (auto level = levels.lower_bound(level_of(radii[i])); level != levels.end() && holder == kNone; ++level)
      holder = level->second.find_near(c, kNone, [&](std::uint32_t j) {
        return ball_in_ball(c, radii[i], centres[j], radii[j], decisions);
      });
    if (holder != kNone) {
      container[i] = holder;
      continue;
    }
    const int level = level_of(radii[i]);
    levels.try_emplace(level, level).first->second.insert(c, i);
  }
  return container;
}

}  // namespace molsurf::arrangement
