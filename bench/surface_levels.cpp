// Where the time of one solvent-accessible surface goes, level by level of the merge
// tree: merges, faces in / active / out, and the Boolean's steps summed over the level.
//   surface_levels STRUCTURE [--threads N] [--density D] [--probe P]
#include <omp.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "molsurf/atoms.hpp"
#include "molsurf/surface.hpp"
#include "surface/solvent_accessible_surface.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: surface_levels STRUCTURE [--threads N] [--density D] [--probe P]\n");
    return 2;
  }
  molsurf::SphereUnionOptions options;
  options.method = molsurf::SurfaceMethod::pairwise;  // the method with merge levels
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--threads") options.threads = std::atoi(argv[i + 1]);
    if (flag == "--density") options.spheres.density = std::atof(argv[i + 1]);
    if (flag == "--probe") options.spheres.probe = std::atof(argv[i + 1]);
  }
  const molsurf::Structure structure = molsurf::read_structure(argv[1]);
  const molsurf::SphereUnion result = molsurf::solvent_accessible_surface(structure.atoms, options);
  std::printf("%s: %zu atoms, %zu faces, %d threads, union %.3f s (levels 0-%zu in subtrees: %.3f s)\n\n", argv[1],
              structure.atoms.size(), result.mesh.faces.size(),
              options.threads > 0 ? options.threads : omp_get_max_threads(), result.seconds.union_levels,
              result.subtree_height > 0 ? result.subtree_height - 1 : 0, result.seconds.subtrees);
  // "merge s": wall time of a level merged level by level; below the subtree height, the
  // summed durations of the level's merges (they ran inside subtrees, interleaved).
  std::printf("| level | merges | faces in | active | faces out | split faces | rays | reruns | cull s | intersect s | split s | classify s | stitch s | merge s |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  molsurf::SurfaceLevel sum;
  for (std::size_t k = 0; k < result.level_stats.size(); ++k) {
    const auto& l = result.level_stats[k];
    std::printf("| %zu | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |\n", k, l.merges,
                l.faces_in, l.active_faces, l.faces_out, l.split_faces, l.ray_casts, l.whole_reruns, l.steps.cull,
                l.steps.intersect, l.steps.split, l.steps.classify, l.steps.stitch, l.seconds);
    sum += l;
  }
  std::printf("| all | %zu | %zu | %zu | %zu | %zu | %zu | %zu | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |\n", sum.merges,
              sum.faces_in, sum.active_faces, sum.faces_out, sum.split_faces, sum.ray_casts, sum.whole_reruns,
              sum.steps.cull, sum.steps.intersect, sum.steps.split, sum.steps.classify, sum.steps.stitch, sum.seconds);
  return 0;
}
