// The arrangement of the true spheres (include/molsurf/sphere_arrangement.hpp), sphere by
// sphere in parallel (SphereArranger, sphere_arranger.hpp), then joined here:
//  1. neighbours: which balls cut sphere i, which bury it (exact; sphere_arranger.cpp);
//  2. circles: each pair of caps either crosses (two vertices), or one circle lies inside
//     the other cap (covered), or they are apart (exact; sphere_arranger.cpp);
//  3. exposed arcs: on each circle, the arcs between the caps that cross it, outside every
//     cap (exposed_arcs.cpp);
//  4. cycles: arcs joined at their vertices; patches: cycles grouped into the connected
//     exposed regions of the sphere, with their areas (sphere_patches.cpp);
//  5. shells: patches that share a vertex or a whole circle, joined; area and volume per
//     sphere, patch and shell by Stokes' and the divergence theorem (below).
#include "arrangement/sphere_arrangement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "arrangement/contained_spheres.hpp"
#include "arrangement/patch_links.hpp"
#include "arrangement/power_neighbours.hpp"
#include "arrangement/shell_moments.hpp"
#include "arrangement/sphere_arranger.hpp"
#include "common/parallel_exceptions.hpp"
#include "common/thread_count_scope.hpp"

namespace molsurf {

using arrangement::Key;
using arrangement::kWholeCircle;
using arrangement::LocalArc;
using arrangement::LocalPatch;
using arrangement::SphereArranger;
using arrangement::SphereResult;

namespace arrangement {

std::vector<SphereResult> arrange_each_sphere(std::span<const Vec3> centres, std::span<const double> radii,
                                              std::span<const char> held, std::span<const char> copy,
                                              std::span<const char> arrange) {
  const std::size_t n = centres.size();
  std::vector<char> include(n);
  for (std::size_t i = 0; i < n; ++i) include[i] = radii[i] > 0 && !held[i];
  const PowerNeighbours neighbours = power_neighbours(centres, radii, include);
  const SphereArranger arranger(centres, radii, neighbours);
  std::vector<SphereResult> spheres(n);
  ParallelExceptions errors;
#pragma omp parallel for schedule(dynamic, 16)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i)
    errors.run(i, [&] {
      if (!arrange[i]) return;
      if (held[i]) {
        spheres[i].buried = true;
        spheres[i].duplicate = copy[i];
        return;
      }
      spheres[i] = arranger.arrange(static_cast<std::uint32_t>(i));
    });
  errors.rethrow();
  return spheres;
}

}  // namespace arrangement

SphereArrangement arrange_spheres(std::span<const Vec3> centres, std::span<const double> radii,
                                  const ArrangementOptions& options) {
  if (centres.size() != radii.size()) throw std::invalid_argument("arrange_spheres: one radius per centre");
  if (centres.size() >= kWholeCircle) throw std::invalid_argument("arrange_spheres: too many spheres");
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Vec3& c = centres[i];
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) || !std::isfinite(radii[i]) ||
        radii[i] < 0)
      throw std::invalid_argument("arrange_spheres: sphere " + std::to_string(i) +
                                  " has a coordinate or radius that is not finite, or a negative radius");
  }
  const ThreadCountScope threads(options.threads);
  SphereArrangement result;
  const std::size_t n = centres.size();
  result.area_per_sphere.assign(n, 0);
  result.stats.spheres = n;
  if (n == 0) return result;
  // A sphere inside another's closed ball is buried and cuts nothing; of copies (same
  // centre and radius) the lowest index counts, so that a circle's spheres are alike on
  // every sphere. Settled before the neighbours: a thousand atoms at one centre would
  // otherwise each be every other's neighbour.
  const std::vector<std::uint32_t> container = arrangement::sphere_containers(centres, radii);
  std::vector<char> copy(n, 0), held(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    held[i] = container[i] != i;
    copy[i] = held[i] && centres[container[i]] == centres[i] && radii[container[i]] == radii[i];
  }
  std::vector<SphereResult> spheres =
      arrangement::arrange_each_sphere(centres, radii, held, copy, std::vector<char>(n, 1));

  // Vertices: every arc's ends, once each, in key order. A vertex's point is the one the
  // lowest of its spheres computed (each sphere rounds it in its own frame): the same from
  // any set of spheres that holds those three, as a block with its halo does, whatever else
  // the set holds and however a sort would order equal keys.
  std::vector<std::pair<Key, Vec3>> seen;
  for (std::uint32_t i = 0; i < n; ++i)
    for (const LocalArc& arc : spheres[i].arcs)
      if (!arc.whole) seen.emplace_back(arc.from, centres[i] + arc.from_point);
  std::stable_sort(seen.begin(), seen.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Key> vertex_keys;
  for (const auto& [key, point] : seen)
    if (vertex_keys.empty() || vertex_keys.back() != key) {
      vertex_keys.push_back(key);
      result.vertices.push_back({{key.a, key.b, key.c}, key.side, point});
    }
  auto vertex_index = [&](const Key& key) -> std::int64_t {
    const auto it = std::lower_bound(vertex_keys.begin(), vertex_keys.end(), key);
    return it != vertex_keys.end() && *it == key ? it - vertex_keys.begin() : -1;
  };

  // Arcs and patches in global numbering; shells by the keys the patches share.
  std::vector<std::pair<Key, std::uint32_t>> patch_keys;
  for (std::uint32_t i = 0; i < n; ++i) {
    SphereResult& s = spheres[i];
    result.area_per_sphere[i] = s.area;
    result.stats.buried += s.buried;
    result.stats.duplicate += s.duplicate;
    result.stats.circles += s.circles;
    result.stats.exact_decisions += s.decisions.exact;
    result.stats.degenerate_points += s.degenerate;
    const auto first_patch = static_cast<std::uint32_t>(result.patches.size());
    for (const LocalArc& arc : s.arcs) {
      ArrangementArc a;
      a.sphere = i;
      a.other = arc.other;
      a.from = arc.whole ? -1 : vertex_index(arc.from);
      a.to = arc.whole ? -1 : vertex_index(arc.to);
      a.angle = arc.delta;
      a.patch = first_patch + arc.patch;
      result.arcs.push_back(a);
    }
    for (const LocalPatch& p : s.patches) {
      const auto index = static_cast<std::uint32_t>(result.patches.size());
      result.patches.push_back({i, p.area, p.vector_area, 0});
      for (const Key& key : p.keys) patch_keys.emplace_back(key, index);
    }
  }
  result.stats.vertices = result.vertices.size();
  result.stats.arcs = result.arcs.size();
  std::vector<std::pair<Key, Key>> aliases;
  for (const SphereResult& s : spheres) aliases.insert(aliases.end(), s.aliases.begin(), s.aliases.end());
  spheres = {};
  const std::size_t patches = result.patches.size();
  arrangement::PatchLinks links(patches, patch_keys, aliases);

  // Shell measures, each about its own first sphere's centre.
  std::vector<std::int64_t> shell_of(patches, -1);
  std::vector<arrangement::ShellMoments> moments;
  std::vector<std::vector<std::uint32_t>> shell_spheres;
  for (std::uint32_t p = 0; p < patches; ++p) {
    const std::uint32_t root = links.root(p);
    ArrangementPatch& patch = result.patches[p];
    const std::uint32_t i = patch.sphere;
    if (shell_of[root] < 0) {
      shell_of[root] = static_cast<std::int64_t>(moments.size());
      moments.emplace_back();
      moments.back().origin = centres[i];
      shell_spheres.emplace_back();
    }
    const auto s = static_cast<std::size_t>(shell_of[root]);
    moments[s].add_patch(centres[i], radii[i], patch.area, patch.vector_area);
    if (shell_spheres[s].empty() || shell_spheres[s].back() != i) shell_spheres[s].push_back(i);
    patch.shell = static_cast<std::uint32_t>(s);
  }
  arrangement::FinishedShells finished = arrangement::finish_shells(
      moments, std::move(shell_spheres), [&](std::uint32_t i) { return arrangement::Ball{centres[i], radii[i]}; });
  result.shells = std::move(finished.shells);
  for (ArrangementPatch& patch : result.patches) patch.shell = finished.rank[patch.shell];
  for (const ArrangementShell& shell : result.shells) result.volume += shell.volume;
  for (double a : result.area_per_sphere) result.area += a;
  return result;
}

}  // namespace molsurf
