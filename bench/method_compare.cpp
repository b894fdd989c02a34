#include "surface/one_pass/one_pass_union.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/surface.hpp"
#include "surface/solvent_accessible_surface.hpp"
#include <chrono>
#include <cstdio>
#include <cstdlib>
using namespace molsurf;
int main(int argc, char** argv){
  Structure s = read_structure(argv[1], {});
  SphereOptions so; if (argc>2) so.probe=atof(argv[2]); if (argc>3) so.density=atof(argv[3]);
  int threads = argc>4? atoi(argv[4]) : 2;
  auto t0=std::chrono::steady_clock::now();
  auto r = surface_detail::one_pass_union(s.atoms, so, threads);
  double t1=std::chrono::duration<double>(std::chrono::steady_clock::now()-t0).count();
  auto& st=r.stats;
  printf("atoms %zu dup %zu pairs %zu faces_in %zu inside %zu whole %zu cut %zu crossings %zu open %zu out %zu verts %zu trim %.3f join %.3f total %.3f\n",
    st.atoms, st.contained_atoms, st.neighbour_pairs, st.faces_in, st.faces_inside, st.faces_whole, st.faces_cut, st.crossings, st.open_edges, r.mesh.faces.size(), r.mesh.vertices.size(), st.seconds_trim, st.seconds_join, t1);
  printf("area %.12g volume %.12g\n", surface_area(r.mesh), signed_volume(r.mesh));
  if (getenv("PAIR")) {
    SphereUnionOptions o; o.spheres=so; o.threads=threads; o.method=SurfaceMethod::pairwise;
    auto p = solvent_accessible_surface(s.atoms, o);
    printf("pairwise faces %zu area %.12g volume %.12g  rel %.3g %.3g\n", p.mesh.faces.size(), surface_area(p.mesh), signed_volume(p.mesh),
      surface_area(r.mesh)/surface_area(p.mesh)-1, signed_volume(r.mesh)/signed_volume(p.mesh)-1);
  }
  if (getenv("CHECK")) { auto c = check_mesh(r.mesh, {}); printf("check valid %d\n", (int)c.valid()); }
}
