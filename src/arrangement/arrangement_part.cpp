#include "arrangement/arrangement_part.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "arrangement/patch_links.hpp"
#include "arrangement/sphere_arrangement.hpp"
#include "common/thread_count_scope.hpp"

namespace molsurf::arrangement {

ArrangementPart arrange_part(std::span<const Vec3> centres, std::span<const double> radii,
                             std::span<const std::uint8_t> held, std::span<const std::uint8_t> owned,
                             std::span<const std::uint32_t> global_index, int threads) {
  const std::size_t n = centres.size();
  if (radii.size() != n || held.size() != n || owned.size() != n || global_index.size() != n)
    throw std::invalid_argument("arrange_part: one radius, containment, ownership and index per centre");
  for (std::size_t i = 1; i < n; ++i)
    if (global_index[i] <= global_index[i - 1]) throw std::invalid_argument("arrange_part: indices must increase");
  const ThreadCountScope scope(threads);
  ArrangementPart part;
  const std::vector<char> held_here(held.begin(), held.end()), arrange(owned.begin(), owned.end());
  std::vector<SphereResult> spheres =
      arrange_each_sphere(centres, radii, held_here, std::vector<char>(n, 0), arrange);

  // Keys in the whole structure's numbering: the indices' order is the same, so are the
  // sorted triples and their sides.
  auto global = [&](std::uint32_t i) { return i == kWholeCircle ? kWholeCircle : global_index[i]; };
  auto global_key = [&](const Key& k) { return Key{global(k.a), global(k.b), global(k.c), k.side}; };
  auto open = [&](const Key& k) { return !owned[k.a] || !owned[k.b] || (k.c != kWholeCircle && !owned[k.c]); };

  std::vector<Key> inner_vertices;
  std::vector<std::pair<Key, std::uint32_t>> patch_keys;
  std::vector<std::pair<Key, Key>> aliases;
  struct Patch {
    std::uint32_t sphere;  // local
    double area;
    Vec3 vector_area;
  };
  std::vector<Patch> patches;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!owned[i]) continue;
    const SphereResult& s = spheres[i];
    ArrangementStats& stats = part.stats;
    ++stats.spheres;
    stats.buried += s.buried;
    stats.circles += s.circles;
    stats.exact_decisions += s.decisions.exact;
    stats.degenerate_points += s.degenerate;
    stats.arcs += s.arcs.size();
    if (s.area != 0) part.sphere_area.push_back({global_index[i], s.area});
    for (const LocalArc& arc : s.arcs)
      if (!arc.whole) (open(arc.from) ? part.open_vertices : inner_vertices).push_back(global_key(arc.from));
    for (const LocalPatch& p : s.patches) {
      const auto index = static_cast<std::uint32_t>(patches.size());
      patches.push_back({i, p.area, p.vector_area});
      for (const Key& key : p.keys) patch_keys.emplace_back(key, index);
    }
    aliases.insert(aliases.end(), s.aliases.begin(), s.aliases.end());
  }
  spheres = {};
  std::sort(inner_vertices.begin(), inner_vertices.end());
  part.stats.vertices = static_cast<std::size_t>(
      std::unique(inner_vertices.begin(), inner_vertices.end()) - inner_vertices.begin());
  inner_vertices = {};
  std::sort(part.open_vertices.begin(), part.open_vertices.end());
  part.open_vertices.erase(std::unique(part.open_vertices.begin(), part.open_vertices.end()),
                           part.open_vertices.end());

  // Shell parts: the patches joined through keys (local numbering here), each about its first
  // sphere's centre; then the open keys of each, which another block's parts may share.
  PatchLinks links(patches.size(), patch_keys, aliases);
  patch_keys = {};
  aliases = {};
  std::vector<std::int64_t> part_of(patches.size() + links.keys().size(), -1);
  auto part_of_root = [&](std::uint32_t root) {
    if (part_of[root] < 0) {
      part_of[root] = static_cast<std::int64_t>(part.shells.size());
      part.shells.emplace_back();
    }
    return static_cast<std::size_t>(part_of[root]);
  };
  for (std::uint32_t p = 0; p < patches.size(); ++p) {
    const Patch& patch = patches[p];
    const std::uint32_t i = patch.sphere;
    const std::size_t k = part_of_root(links.root(p));
    ShellPart& shell = part.shells[k];
    if (shell.patches.empty()) {
      shell.moments.origin = centres[i];
      shell.first_sphere = global_index[i];
    }
    shell.moments.add_patch(centres[i], radii[i], patch.area, patch.vector_area);
    if (!shell.patches.empty() && shell.patches.back().sphere == global_index[i])
      shell.patches.back().area += patch.area;
    else
      shell.patches.push_back({global_index[i], patch.area});
  }
  // A part without patches (open keys joined by aliases alone) only links other blocks' parts.
  for (std::size_t k = 0; k < links.keys().size(); ++k) {
    const Key& key = links.keys()[k];
    if (!open(key)) continue;
    const std::size_t shell = part_of_root(links.root(links.key_node(k)));
    part.open_keys.push_back({global_key(key), static_cast<std::uint32_t>(shell)});
  }
  std::sort(part.open_keys.begin(), part.open_keys.end(),
            [](const OpenKey& x, const OpenKey& y) { return x.key < y.key; });
  return part;
}

}  // namespace molsurf::arrangement
