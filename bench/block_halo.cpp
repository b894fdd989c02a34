// How the spatial blocks (src/blocks/) split a structure: per block count, the atoms per
// block, the halo each block needs (atoms of other blocks whose polyhedra reach its own),
// and the share a process holds under mpirun with one block per process (its block, its halo
// and the atoms near it, block_share.hpp): atoms and bytes (docs/scale-out.md's projection).
// Usage: block_halo STRUCTURE N...
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "blocks/block_partition.hpp"
#include "blocks/block_share.hpp"
#include "molsurf/atoms.hpp"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s STRUCTURE N...\n", argv[0]);
    return 2;
  }
  const molsurf::Structure s = molsurf::read_structure(argv[1]);
  const molsurf::SphereOptions options;
  std::printf("%s: %zu atoms\n", argv[1], s.atoms.size());
  std::printf("%8s %12s %12s %12s %12s %14s %12s %12s %12s\n", "blocks", "atoms/block", "max atoms", "halo mean",
              "halo max", "halo/atoms", "share mean", "share max", "share MB max");
  for (int k = 2; k < argc; ++k) {
    const std::size_t n = std::strtoul(argv[k], nullptr, 10);
    const molsurf::blocks::BlockPartition p = molsurf::blocks::partition_blocks(s.atoms, options, n);
    std::size_t max_atoms = 0, max_halo = 0, halo = 0;
    for (std::size_t b = 0; b < p.size(); ++b) {
      max_atoms = std::max(max_atoms, p.atoms[b].size());
      max_halo = std::max(max_halo, p.halo[b].size());
      halo += p.halo[b].size();
    }
    std::size_t share = 0, max_share = 0, max_bytes = 0;
    for (std::size_t r = 0; r < n; ++r) {
      const molsurf::blocks::BlockShare held =
          molsurf::blocks::share_of_process(s.atoms, p, options, static_cast<int>(r), static_cast<int>(n));
      share += held.atoms.size();
      max_share = std::max(max_share, held.atoms.size());
      max_bytes = std::max(max_bytes, molsurf::blocks::block_share_bytes(held).size());
    }
    std::printf("%8zu %12.0f %12zu %12.0f %12zu %13.1f%% %12.0f %12zu %12.2f\n", n, double(s.atoms.size()) / n,
                max_atoms, double(halo) / n, max_halo, 100.0 * halo / s.atoms.size(), double(share) / n, max_share,
                max_bytes / 1e6);
  }
}
