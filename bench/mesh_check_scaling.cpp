// Prints how `check_mesh` scales with the number of faces, on rows of overlapping-free
// icospheres (a valid mesh, so every stage of the check runs to the end).
// Usage: mesh_check_scaling [--threads N]
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "mesh/icosphere.hpp"
#include "molsurf/mesh_check.hpp"

namespace {

// `count` unit spheres of 50 000 faces each, 2.5 apart on a grid: disjoint, so valid.
molsurf::Mesh disjoint_spheres(int count) {
  molsurf::Mesh mesh;
  for (int i = 0; i < count; ++i)
    mesh.append(molsurf::make_icosphere({2.5 * (i % 7), 2.5 * (i / 7), 0.3 * i}, 1.0, {.frequency = 50}));
  return mesh;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--threads") == 0) omp_set_num_threads(std::atoi(argv[i + 1]));
  std::printf("threads: %d\n\n| faces | valid | check s | µs per face |\n|---:|:---:|---:|---:|\n",
              omp_get_max_threads());
  for (int count : {1, 4, 10, 20, 40}) {
    const molsurf::Mesh mesh = disjoint_spheres(count);
    const auto start = std::chrono::steady_clock::now();
    const molsurf::MeshCheck check = molsurf::check_mesh(mesh);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("| %zu | %s | %.3f | %.2f |\n", check.faces, check.valid() ? "yes" : "NO", seconds,
                1e6 * seconds / static_cast<double>(check.faces));
  }
}
