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
#include "arrangement/power_neighbours.hpp"
#include "arrangement/sphere_arranger.hpp"
#include "common/parallel_exceptions.hpp"
#include "common/thread_count_scope.hpp"

namespace molsurf {

using arrangement::Key;
using arrangement::kPi;
using arrangement::kWholeCircle;
using arrangement::LocalArc;
using arrangement::LocalPatch;
using arrangement::SphereArranger;
using arrangement::SphereResult;

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
  std::vector<char> include(n);
  for (std::size_t i = 0; i < n; ++i) include[i] = radii[i] > 0 && !held[i];
  const arrangement::PowerNeighbours neighbours = arrangement::power_neighbours(centres, radii, include);
  const SphereArranger arranger(centres, radii, neighbours);
  std::vector<SphereResult> spheres(n);
  ParallelExceptions errors;
#pragma omp parallel for schedule(dynamic, 16)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i)
    errors.run(i, [&] {
      if (held[i]) {
        spheres[i].buried = true;
        spheres[i].duplicate = copy[i];
        return;
      }
      spheres[i] = arranger.arrange(static_cast<std::uint32_t>(i));
    });
  errors.rethrow();

  // Vertices: every arc's ends, once each, in key order.
  std::vector<std::pair<Key, Vec3>> seen;
  for (std::uint32_t i = 0; i < n; ++i)
    for (const LocalArc& arc : spheres[i].arcs)
      if (!arc.whole) seen.emplace_back(arc.from, centres[i] + arc.from_point);
  std::sort(seen.begin(), seen.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
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
  // Shells: patches joined through the keys on their boundaries, keys through their aliases
  // (union-find over patches, then keys).
  std::vector<Key> keys;
  keys.reserve(patch_keys.size());
  for (const auto& pk : patch_keys) keys.push_back(pk.first);
  std::vector<std::pair<Key, Key>> aliases;
  for (const SphereResult& s : spheres) aliases.insert(aliases.end(), s.aliases.begin(), s.aliases.end());
  for (const auto& [x, y] : aliases) {
    keys.push_back(x);
    keys.push_back(y);
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  const std::size_t patches = result.patches.size();
  auto key_node = [&](const Key& k) {
    return static_cast<std::uint32_t>(patches + (std::lower_bound(keys.begin(), keys.end(), k) - keys.begin()));
  };
  std::vector<std::uint32_t> parent(patches + keys.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  auto unite = [&](std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    parent[std::max(a, b)] = std::min(a, b);
  };
  for (const auto& [key, patch] : patch_keys) unite(patch, key_node(key));
  for (const auto& [x, y] : aliases) unite(key_node(x), key_node(y));

  // Shell measures, each about its own first sphere's centre (the divergence theorem's
  // origin is free; a near one keeps the sum's cancellation small).
  std::vector<std::int64_t> shell_of(patches, -1);
  std::vector<Vec3> origin;
  std::vector<ArrangementShell> shells;
  // A bound on each shell volume's rounding: a patch's area and vector area come from
  // integrals of order r^2 on the unit sphere, each some 1e-15 r^2 off, summed over its arcs.
  std::vector<double> volume_error;
  for (std::uint32_t p = 0; p < patches; ++p) {
    const std::uint32_t root = find(p);
    if (shell_of[root] < 0) {
      shell_of[root] = static_cast<std::int64_t>(shells.size());
      shells.emplace_back();
      origin.push_back(centres[result.patches[p].sphere]);
      volume_error.push_back(0);
    }
    const auto s = static_cast<std::size_t>(shell_of[root]);
    ArrangementPatch& patch = result.patches[p];
    const std::uint32_t i = patch.sphere;
    ArrangementShell& shell = shells[s];
    shell.area += patch.area;
    shell.volume += (radii[i] * patch.area + dot(centres[i] - origin[s], patch.vector_area)) / 3;
    shell.centroid += (centres[i] - origin[s]) * patch.area + radii[i] * patch.vector_area;
    volume_error[s] += 1e-12 * radii[i] * radii[i] * (radii[i] + norm(centres[i] - origin[s]));
    if (shell.spheres.empty() || shell.spheres.back() != i) shell.spheres.push_back(i);
    patch.shell = static_cast<std::uint32_t>(s);
  }
  for (std::size_t s = 0; s < shells.size(); ++s) {
    ArrangementShell& shell = shells[s];
    shell.centroid = shell.area > 0 ? origin[s] + shell.centroid / shell.area : origin[s];
    if (std::fabs(shell.volume) > volume_error[s]) continue;
    // A shell too small for its volume's sign (a void of 1e-13 A^3 where four spheres nearly
    // meet). An outer shell holds whole balls, so its area is at least that of its smallest
    // sphere (a surface around a ball is no smaller than the ball's sphere): a shell with
    // less is a cavity. Otherwise (not seen) its centroid decides: outside its balls, a void.
    double smallest = std::numeric_limits<double>::infinity();
    bool inside = false;
    for (std::uint32_t i : shell.spheres) {
      smallest = std::min(smallest, radii[i]);
      const Vec3 d = shell.centroid - centres[i];
      inside |= dot(d, d) < radii[i] * radii[i];
    }
    if (shell.area < 4 * kPi * smallest * smallest) inside = false;
    shell.volume = inside ? std::fabs(shell.volume) : -std::fabs(shell.volume);
    if (shell.volume == 0) shell.volume = inside ? 0.0 : -0.0;
  }
  // The largest outer shell first, then by area.
  std::vector<std::size_t> order(shells.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    if (shells[x].cavity() != shells[y].cavity()) return !shells[x].cavity();
    return shells[x].area > shells[y].area;
  });
  std::vector<std::uint32_t> rank(shells.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    rank[order[k]] = static_cast<std::uint32_t>(k);
    result.shells.push_back(std::move(shells[order[k]]));
  }
  for (ArrangementPatch& patch : result.patches) patch.shell = rank[patch.shell];
  for (ArrangementShell& shell : result.shells) {
    std::sort(shell.spheres.begin(), shell.spheres.end());
    shell.spheres.erase(std::unique(shell.spheres.begin(), shell.spheres.end()), shell.spheres.end());
    result.volume += shell.volume;
  }
  for (double a : result.area_per_sphere) result.area += a;
  return result;
}

}  // namespace molsurf
