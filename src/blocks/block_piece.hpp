#pragma once
// One block's piece of the solvent-accessible union: the block atoms' faces, trimmed by the
// block and its halo (block_partition.hpp), joined into a mesh that is closed except on the
// seam with the other blocks. Face tags are the atoms' indices in the whole structure, and
// every decision (ties between identical atoms, coplanar faces, containment) is taken as
// in the whole union, so the pieces glued along their seams (seam.hpp) are the
// single-process one-pass union face for face.
#include <span>
#include <vector>

#include "blocks/block_partition.hpp"
#include "blocks/seam.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"
#include "surface/solvent_accessible_surface.hpp"

namespace molsurf::blocks {

struct BlockPiece {
  Mesh mesh;  // face tags: atom index in the whole structure
  std::vector<SeamPoint> seam;  // the seam's points, for the glue
  OnePassStats stats;  // of the block's atoms; open_edges: the seam's directed edges
};

BlockPiece compute_block_piece(const BlockAtoms& block, const SphereOptions& options, int threads);

// The exact test the glue asks (seam.hpp) for points of `atoms` (the whole structure),
// containment as the partition decided it. The polyhedra are built on the first question
// only: most seams have none. `atoms` and `contained` must outlive the test.
SamePoint exact_same_point(std::span<const Atom> atoms, const SphereOptions& options,
                           std::span<const std::uint8_t> contained);

}  // namespace molsurf::blocks
