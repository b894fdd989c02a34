#include "arrangement/joined_parts.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

namespace molsurf::arrangement {

SphereArrangement join_parts(std::span<const ArrangementPart> parts, std::size_t spheres,
                             const std::function<Ball(std::uint32_t)>& ball_of) {
  SphereArrangement result;
  result.area_per_sphere.assign(spheres, 0);
  ArrangementStats& stats = result.stats;
  std::vector<Key> open_vertices;
  std::vector<std::size_t> first_part(parts.size() + 1, 0);  // global numbering of the shell parts
  for (std::size_t b = 0; b < parts.size(); ++b) {
    const ArrangementPart& p = parts[b];
    stats.spheres += p.stats.spheres;
    stats.buried += p.stats.buried;
    stats.circles += p.stats.circles;
    stats.exact_decisions += p.stats.exact_decisions;
    stats.degenerate_points += p.stats.degenerate_points;
    stats.vertices += p.stats.vertices;
    stats.arcs += p.stats.arcs;
    for (const SphereArea& s : p.sphere_area) {
      if (s.sphere >= spheres) throw std::invalid_argument("join_parts: a sphere beyond the structure");
      result.area_per_sphere[s.sphere] = s.area;
    }
    open_vertices.insert(open_vertices.end(), p.open_vertices.begin(), p.open_vertices.end());
    first_part[b + 1] = first_part[b] + p.shells.size();
  }
  if (stats.spheres != spheres) throw std::invalid_argument("join_parts: the parts do not hold every sphere once");
  // A vertex on a block boundary is an arc end on each block that owns one of its spheres.
  std::sort(open_vertices.begin(), open_vertices.end());
  stats.vertices += static_cast<std::size_t>(std::unique(open_vertices.begin(), open_vertices.end()) -
                                             open_vertices.begin());
  open_vertices = {};

  // The shell parts joined where they share an open key.
  const std::size_t count = first_part.back();
  std::vector<std::uint32_t> parent(count);
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  {
    std::vector<std::pair<Key, std::uint32_t>> keys;
    for (std::size_t b = 0; b < parts.size(); ++b)
      for (const OpenKey& k : parts[b].open_keys) {
        if (k.part >= parts[b].shells.size()) throw std::invalid_argument("join_parts: a key of no shell part");
        keys.emplace_back(k.key, static_cast<std::uint32_t>(first_part[b] + k.part));
      }
    std::sort(keys.begin(), keys.end());
    for (std::size_t k = 1; k < keys.size(); ++k)
      if (keys[k].first == keys[k - 1].first) {
        const std::uint32_t x = root(keys[k].second), y = root(keys[k - 1].second);
        parent[std::max(x, y)] = std::min(x, y);
      }
  }
  // Shells in the order the whole arrangement finds them: by their first patch, the lowest
  // sphere's (one block's parts are in patch order already); each summed about the origin of
  // its first part.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> order;  // (first sphere, part) of parts with patches
  std::vector<const ShellPart*> part_at(count);
  for (std::size_t b = 0; b < parts.size(); ++b)
    for (std::size_t k = 0; k < parts[b].shells.size(); ++k) {
      const ShellPart& s = parts[b].shells[k];
      part_at[first_part[b] + k] = &s;
      if (!s.patches.empty()) order.emplace_back(s.first_sphere, static_cast<std::uint32_t>(first_part[b] + k));
    }
  std::sort(order.begin(), order.end());
  std::vector<std::int64_t> shell_of(count, -1);
  std::vector<ShellMoments> moments;
  std::vector<std::vector<std::uint32_t>> shell_spheres;
  for (const auto& [first, k] : order) {
    const std::uint32_t r = root(k);
    const ShellPart& s = *part_at[k];
    if (shell_of[r] < 0) {
      shell_of[r] = static_cast<std::int64_t>(moments.size());
      moments.push_back(s.moments);
      shell_spheres.emplace_back();
    } else {
      moments[static_cast<std::size_t>(shell_of[r])].add(s.moments);
    }
    const auto shell = static_cast<std::uint32_t>(shell_of[r]);
    for (const SphereArea& p : s.patches) {
      if (p.sphere >= spheres) throw std::invalid_argument("join_parts: a sphere beyond the structure");
      shell_spheres[shell].push_back(p.sphere);
      result.patches.push_back({p.sphere, p.area, {}, shell});
    }
  }
  FinishedShells finished = finish_shells(moments, std::move(shell_spheres), ball_of);
  result.shells = std::move(finished.shells);
  for (ArrangementPatch& patch : result.patches) patch.shell = finished.rank[patch.shell];
  std::stable_sort(result.patches.begin(), result.patches.end(),
                   [](const ArrangementPatch& x, const ArrangementPatch& y) { return x.sphere < y.sphere; });
  for (const ArrangementShell& shell : result.shells) result.volume += shell.volume;
  for (double a : result.area_per_sphere) result.area += a;
  return result;
}

}  // namespace molsurf::arrangement
