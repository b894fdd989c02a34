#include "arrangement/power_neighbours.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>

namespace molsurf::arrangement {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel,
                                                               CGAL::Regular_triangulation_vertex_base_3<Kernel>>;
using CellBase = CGAL::Regular_triangulation_cell_base_3<Kernel>;
using Regular = CGAL::Regular_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<VertexBase, CellBase>>;

}  // namespace

PowerNeighbours power_neighbours(std::span<const Vec3> centres, std::span<const double> radii,
                                 std::span<const char> include) {
  const std::size_t n = centres.size();
  std::vector<std::pair<Kernel::Weighted_point_3, std::uint32_t>> points;
  points.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i)
    if (include[i])
      points.emplace_back(Kernel::Weighted_point_3(Kernel::Point_3(centres[i].x, centres[i].y, centres[i].z),
                                                   radii[i] * radii[i]),
                          i);
  const Regular triangulation(points.begin(), points.end());  // spatially sorted insertion

  PowerNeighbours out;
  out.hidden.assign(n, 1);
  for (auto v = triangulation.finite_vertices_begin(); v != triangulation.finite_vertices_end(); ++v)
    out.hidden[v->info()] = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(8 * points.size());
  for (auto e = triangulation.finite_edges_begin(); e != triangulation.finite_edges_end(); ++e) {
    const std::uint32_t a = e->first->vertex(e->second)->info(), b = e->first->vertex(e->third)->info();
    edges.emplace_back(a, b);
    edges.emplace_back(b, a);
  }
  std::sort(edges.begin(), edges.end());
  out.offset.assign(n + 1, 0);
  for (const auto& [a, b] : edges) ++out.offset[a + 1];
  for (std::size_t i = 0; i < n; ++i) out.offset[i + 1] += out.offset[i];
  out.list.reserve(edges.size());
  for (const auto& [a, b] : edges) out.list.push_back(b);
  return out;
}

}  // namespace molsurf::arrangement
