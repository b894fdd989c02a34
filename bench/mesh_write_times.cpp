// The time write_mesh takes for one mesh file and format, alone (docs/formats.md):
//   mesh_write_times STRUCTURE SURFACE OUTPUT [REPEATS]
// reads STRUCTURE's atoms and a surface file of it (its face tags are atom indices, as
// molsurf writes them), then writes OUTPUT REPEATS times (default 5) with the atoms' cell
// arrays and prints each write's wall-clock and CPU time (all threads; less sensitive to a
// busy machine) and their medians. Public API only, so that the same source builds
// against another version of the library to compare.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include <exception>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/io.hpp"

int main(int argc, char** argv) {
  if (argc < 4 || argc > 5) {
    std::fprintf(stderr, "usage: mesh_write_times STRUCTURE SURFACE OUTPUT [REPEATS]\n");
    return 2;
  }
  try {
    const molsurf::Structure structure = molsurf::read_structure(argv[1]);
    const molsurf::Mesh mesh = molsurf::read_mesh(argv[2]);
    const int repeats = argc == 5 ? std::max(1, std::atoi(argv[4])) : 5;
    std::vector<double> wall, cpu;
    for (int r = 0; r < repeats; ++r) {
      const auto start = std::chrono::steady_clock::now();
      const std::clock_t cpu_start = std::clock();
      molsurf::write_mesh(argv[3], mesh, {.atoms = structure.atoms});
      cpu.push_back(static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
      wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      std::printf("wall %.4f s, cpu %.4f s\n", wall.back(), cpu.back());
    }
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    std::printf("median wall %.4f s, cpu %.4f s (%zu vertices, %zu faces)\n", wall[wall.size() / 2],
                cpu[cpu.size() / 2], mesh.vertex_count(), mesh.face_count());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 1;
  }
}
