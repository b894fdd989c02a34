#pragma once
// The surface job over spatial blocks (`molsurf --blocks N`): the atoms cut into blocks
// (block_partition.hpp), each block's piece computed from its atoms and halo, cleaned with
// its seam frozen, checked on its own, and handed to the caller as soon as it is done; then
// the seams matched and the whole surface checked and measured as compute_surface measures
// one (exact areas, components and cavities joined through the seams).
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf::blocks {

struct BlockStats {
  std::size_t atoms = 0, halo_atoms = 0, faces = 0, seam_edges = 0;
  double seconds = 0;  // union, cleanup and check of the piece
};

struct BlockedSurfaceOptions {
  std::size_t blocks = 1;
  // Called with each checked piece (face tags: atom indices), block by block, as soon as it
  // is done. May be empty.
  std::function<void(std::size_t block, const Mesh& piece)> piece_done;
};

struct BlockedSurface {
  ComputedSurface surface;  // mesh: the pieces glued along their seams, checked
  std::vector<BlockStats> blocks;
};

// The SAS and vdW surfaces by the one-pass method (the SES, the pairwise method, outer_only
// and true_points are refused with molsurf::Error). Throws SurfaceCheckFailed when a piece
// or the glued surface fails its check.
BlockedSurface compute_blocked_surface(std::span<const Atom> atoms, const ComputeSurfaceOptions& options,
                                       const BlockedSurfaceOptions& blocked);

// What a piece must be: its own check passed but for the seam, which is its only boundary
// (one line per problem; empty when it is sound).
std::vector<std::string> piece_problems(const MeshCheck& check, std::size_t seam_edges);

}  // namespace molsurf::blocks
