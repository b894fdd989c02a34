#pragma once
// An exact check written apart from molsurf's: CGAL's (Debian libcgal-dev, exact
// constructions). Sheets that touch count as self-intersections there, as in molsurf's.
// A file including this must be compiled with -frounding-math (CGAL's interval filters).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <string>
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf::testing {

// Empty when closed, free of self-intersection and touching, and outward; else what failed.
inline std::string cgal_defects(const Mesh& m) {
  using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
  using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
  SurfaceMesh s;
  std::vector<SurfaceMesh::Vertex_index> v;
  v.reserve(m.vertices.size());
  for (const Vec3& p : m.vertices) v.push_back(s.add_vertex(Kernel::Point_3(p.x, p.y, p.z)));
  for (const Triangle& t : m.faces)
    if (s.add_face(v[t[0]], v[t[1]], v[t[2]]) == SurfaceMesh::null_face()) return "not 2-manifold (CGAL)";
  if (!CGAL::is_closed(s)) return "not closed (CGAL)";
  if (CGAL::Polygon_mesh_processing::does_self_intersect(s)) return "self-intersecting or touching (CGAL)";
  if (!CGAL::Polygon_mesh_processing::is_outward_oriented(s)) return "not outward (CGAL)";
  return {};
}

}  // namespace molsurf::testing
