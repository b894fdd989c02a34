// How the spatial blocks (src/blocks/) split a structure: per block count, the atoms per
// block, the halo each block needs (atoms of other blocks whose polyhedra reach its own),
// and the bytes a process receives for it (docs/scale-out.md's projection).
// Usage: block_halo STRUCTURE N...
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "blocks/block_partition.hpp"
#include "molsurf/atoms.hpp"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s STRUCTURE N...\n", argv[0]);
    return 2;
  }
  const molsurf::Structure s = molsurf::read_structure(argv[1]);
  const molsurf::SphereOptions options;
  std::printf("%s: %zu atoms\n", argv[1], s.atoms.size());
  std::printf("%8s %12s %12s %12s %12s %14s\n", "blocks", "atoms/block", "max atoms", "halo mean", "halo max",
              "halo/atoms");
  for (int k = 2; k < argc; ++k) {
    const std::size_t n = std::strtoul(argv[k], nullptr, 10);
    const molsurf::blocks::BlockPartition p = molsurf::blocks::partition_blocks(s.atoms, options, n);
    std::size_t max_atoms = 0, max_halo = 0, halo = 0;
    for (std::size_t b = 0; b < p.size(); ++b) {
      max_atoms = std::max(max_atoms, p.atoms[b].size());
      max_halo = std::max(max_halo, p.halo[b].size());
      halo += p.halo[b].size();
    }
    std::printf("%8zu %12.0f %12zu %12.0f %12zu %13.1f%%\n", n, double(s.atoms.size()) / n, max_atoms,
                double(halo) / n, max_halo, 100.0 * halo / s.atoms.size());
  }
}
