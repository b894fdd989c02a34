#include "arrangement/power_neighbours.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <numeric>

#include "common/parallel_exceptions.hpp"

namespace molsurf::arrangement {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel,
                                                               CGAL::Regular_triangulation_vertex_base_3<Kernel>>;
using CellBase = CGAL::Regular_triangulation_cell_base_3<Kernel>;
using Regular = CGAL::Regular_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<VertexBase, CellBase>>;

// Spheres per block. The blocks are fixed by the input alone (never by the thread count):
// a block's neighbour lists may hold a few more spheres than the whole's, and the result
// must not depend on how the work was shared.
constexpr std::size_t kBlockSpheres = 40000;

}  // namespace

PowerNeighbours power_neighbours(std::span<const Vec3> centres, std::span<const double> radii,
                                 std::span<const char> include) {
  const std::size_t n = centres.size();
  std::vector<std::uint32_t> taking;
  double largest = 0;
  for (std::uint32_t i = 0; i < n; ++i)
    if (include[i]) {
      taking.push_back(i);
      largest = std::max(largest, radii[i]);
    }
  // Slabs across the longest extent, equal in spheres, each triangulated with a halo of the
  // spheres within two largest radii of it. Removing spheres only grows the others' power
  // cells, so every face between two overlapping spheres of a slab (they lie within two
  // radii) is in its triangulation: its lists hold all their neighbours, and perhaps more.
  Vec3 low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
  for (std::uint32_t i : taking)
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], centres[i][k]);
      high[k] = std::max(high[k], centres[i][k]);
    }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (high[k] - low[k] > high[axis] - low[axis]) axis = k;
  std::stable_sort(taking.begin(), taking.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return centres[a][axis] < centres[b][axis]; });
  // At least two slabs from a few thousand spheres on, so that two threads share the work.
  const std::size_t blocks = std::max<std::size_t>(taking.size() >= 2000 ? 2 : 1,
                                                   (taking.size() + kBlockSpheres - 1) / kBlockSpheres);
  const double halo = 2 * largest;

  PowerNeighbours out;
  out.hidden.assign(n, 1);
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> edges(blocks);
  ParallelExceptions errors;
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t b = 0; b < static_cast<std::int64_t>(blocks); ++b)
    errors.run(b, [&] {
      const std::size_t first = taking.size() * b / blocks, last = taking.size() * (b + 1) / blocks;
      if (first == last) return;
      const double from = centres[taking[first]][axis] - halo, to = centres[taking[last - 1]][axis] + halo;
      // The slab's spheres and its halo: a contiguous run of the sorted order.
      auto begin = std::lower_bound(taking.begin(), taking.end(), from,
                                    [&](std::uint32_t i, double x) { return centres[i][axis] < x; });
      auto end = std::upper_bound(taking.begin(), taking.end(), to,
                                  [&](double x, std::uint32_t i) { return x < centres[i][axis]; });
      std::vector<std::pair<Kernel::Weighted_point_3, std::uint32_t>> points;
      points.reserve(end - begin);
      for (auto it = begin; it != end; ++it) {
        const Vec3& c = centres[*it];
        points.emplace_back(Kernel::Weighted_point_3(Kernel::Point_3(c.x, c.y, c.z), radii[*it] * radii[*it]), *it);
      }
      const Regular triangulation(points.begin(), points.end());  // spatially sorted insertion
      // The slab's own spheres only (the halo's lists come from their own slab).
      std::vector<char> own(n, 0);
      for (std::size_t k = first; k < last; ++k) own[taking[k]] = 1;
      for (auto v = triangulation.finite_vertices_begin(); v != triangulation.finite_vertices_end(); ++v)
        if (own[v->info()]) out.hidden[v->info()] = 0;
      std::vector<std::pair<std::uint32_t, std::uint32_t>>& mine = edges[b];
      for (auto e = triangulation.finite_edges_begin(); e != triangulation.finite_edges_end(); ++e) {
        const std::uint32_t p = e->first->vertex(e->second)->info(), q = e->first->vertex(e->third)->info();
        if (own[p]) mine.emplace_back(p, q);
        if (own[q]) mine.emplace_back(q, p);
      }
    });
  errors.rethrow();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> all;
  for (auto& e : edges) all.insert(all.end(), e.begin(), e.end());
  std::sort(all.begin(), all.end());
  out.offset.assign(n + 1, 0);
  for (const auto& [a, b] : all) ++out.offset[a + 1];
  for (std::size_t i = 0; i < n; ++i) out.offset[i + 1] += out.offset[i];
  out.list.reserve(all.size());
  for (const auto& [a, b] : all) out.list.push_back(b);
  return out;
}

}  // namespace molsurf::arrangement
