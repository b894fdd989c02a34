// The solvent region around a molsurf surface meshed by Netgen's nglib instead of gmsh:
// the comparison behind the choice of mesher (docs/volume_mesh.md). The same boundary as
// `molsurf --volume-mesh`: the surface as written, inside a box `margin` beyond its
// bounding box; nglib meshes the region between them. Prints one line: tetrahedra,
// nodes, seconds, nglib's result code (0: success), whether the boundary triangles are the
// given ones (their count), the tetrahedra's volume against the region's, and the quality
// measures molsurf reports for gmsh's mesh.
//
//   nglib_volume_mesh SURFACE [margin=10] [maxh=0: the box's edge]
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <chrono>
#include <utility>

// nglib.h uses NULL without including what defines it, and its library defines the
// functions in namespace nglib, which the header leaves out.
namespace nglib {
#include <nglib.h>
}
using namespace nglib;

#include <algorithm>
#include <array>
#include <vector>

#include "molsurf/io.hpp"
#include "support/shapes.hpp"
#include "volume/tetrahedron_quality.hpp"

namespace {

// Triangles as nglib takes them (1-based point numbers); `reverse` turns a face around.
void add_triangles(Ng_Mesh* mesh, const molsurf::Mesh& m, int first_point, bool reverse) {
  for (const molsurf::Triangle& t : m.faces) {
    int points[3] = {first_point + static_cast<int>(t[0]), first_point + static_cast<int>(t[1]),
                     first_point + static_cast<int>(t[2])};
    if (reverse) std::swap(points[1], points[2]);
    Ng_AddSurfaceElement(mesh, NG_TRIG, points);
  }
}

void add_points(Ng_Mesh* mesh, const molsurf::Mesh& m) {
  for (const molsurf::Vec3& v : m.vertices) {
    double x[3] = {v.x, v.y, v.z};
    Ng_AddPoint(mesh, x);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SURFACE [margin=10] [maxh=0]\n", argv[0]);
    return 2;
  }
  const molsurf::Mesh surface = molsurf::read_mesh(argv[1]);
  const double margin = argc > 2 ? std::atof(argv[2]) : 10.0;
  const molsurf::BoundingBox b = molsurf::bounding_box(surface);
  const molsurf::Vec3 lo{b.min.x - margin, b.min.y - margin, b.min.z - margin};
  const molsurf::Vec3 hi{b.max.x + margin, b.max.y + margin, b.max.z + margin};
  const molsurf::Mesh box = molsurf::make_box(lo, hi, 4, 4, 4);

  const auto start = std::chrono::steady_clock::now();
  Ng_Init();
  Ng_Mesh* mesh = Ng_NewMesh();
  add_points(mesh, surface);
  add_points(mesh, box);
  // nglib meshes the side its triangles face away from: the box as it is (outward), the
  // surface turned around (the solvent lies outside it).
  add_triangles(mesh, surface, 1, /*reverse=*/true);
  add_triangles(mesh, box, 1 + static_cast<int>(surface.vertices.size()), /*reverse=*/false);
  Ng_Meshing_Parameters parameters;
  parameters.maxh = argc > 3 && std::atof(argv[3]) > 0 ? std::atof(argv[3]) : (hi.x - lo.x) / 4;
  const Ng_Result result = Ng_GenerateVolumeMesh(mesh, &parameters);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int tetrahedra = Ng_GetNE(mesh);
  double volume = 0, min_dihedral = 180;
  std::vector<double> ratios;
  for (int k = 1; k <= tetrahedra; ++k) {
    int corners[4];
    Ng_GetVolumeElement(mesh, k, corners);
    std::array<molsurf::Vec3, 4> p;
    for (int i = 0; i < 4; ++i) {
      double x[3];
      Ng_GetPoint(mesh, corners[i], x);
      p[i] = {x[0], x[1], x[2]};
    }
    const auto shape = molsurf::volume_detail::tetrahedron_shape(p);
    volume += shape.volume;
    min_dihedral = std::min(min_dihedral, shape.min_dihedral_deg);
    ratios.push_back(shape.radius_ratio);
  }
  std::sort(ratios.begin(), ratios.end());
  const double region = molsurf::signed_volume(box) - molsurf::signed_volume(surface);
  std::printf("%s: %d tetrahedra, %d nodes, %.1f s, result %d; %d boundary triangles (given %zu); "
              "volume %.6g of %.6g; min dihedral %.2f deg, radius ratio min %.3f median %.3f\n",
              argv[1], tetrahedra, Ng_GetNP(mesh), seconds, static_cast<int>(result), Ng_GetNSE(mesh),
              surface.faces.size() + box.faces.size(), volume, region, ratios.empty() ? 0.0 : min_dihedral,
              ratios.empty() ? 0.0 : ratios.front(), ratios.empty() ? 0.0 : ratios[ratios.size() / 2]);
  Ng_DeleteMesh(mesh);
  Ng_Exit();
  return result == NG_OK ? 0 : 1;
}
