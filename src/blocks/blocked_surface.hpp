#pragma once
// The surface job over spatial blocks (`molsurf --blocks N`): the atoms cut into blocks
// (block_partition.hpp), each block's piece computed from its atoms and halo, cleaned with
// its seam frozen and checked on its own. Glued (the default): the pieces are glued along
// their seams, the seams' slivers cleaned with both sides in view, the whole surface checked
// and measured as compute_surface measures one (components and cavities joined through the
// seams), and handed back block by block; the peak memory is the surface's. In both, the
// exact areas come from each block's own arrangement (block_areas.hpp), joined.
// Streamed (streamed_surface.hpp): each piece's faces away from the seams are handed out
// as soon as the piece is checked and released; the peak memory is a piece's and the seams'.
// The SES (ses_piece.hpp, blocked_ses.hpp): each block draws the SES of its atoms and a
// wider halo, cleans it with all but its own faces and a band around them frozen, and keeps
// its own faces; the first process glues the pieces by position and cleans the band. It is
// never streamed: the first process holds the whole cleaned SES, the others one block's.
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "blocks/block_exchange.hpp"
#include "blocks/piece_bytes.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf::blocks {

struct BlockShare;

struct BlockedSurfaceOptions {
  std::size_t blocks = 1;
  // Called with each block's piece of the checked surface (face tags: atom indices), block
  // by block. May be empty. Streamed: with the piece's faces away from the seams, on the
  // process that made it, as soon as it is checked.
  std::function<void(std::size_t block, const Mesh& piece)> piece_done;
  // Streamed: the mesh's faces are not kept; the seams' faces, cleaned and checked with the
  // faces near them, go to `seams_done` (on the first process; may be empty, and so may the
  // seams with one block), and the result's mesh is empty, its measures and check merged
  // from the pieces'. Ignored for the SES (never streamed: streams(), piece_job.hpp).
  bool streamed = false;
  std::function<void(const Mesh& seams)> seams_done;
  // Processes that share the job (may be null: this one alone). Each makes its blocks'
  // pieces (r, r + size, ...); the first glues (or, streamed, joins the seams), checks and
  // measures them.
  BlockExchange* exchange = nullptr;
  // With an exchange of several processes: this process's share of the structure
  // (share_blocks, block_share.hpp). The first process's holds the partition, and `atoms`
  // is the whole structure there; the others hold only their blocks' atoms, halos and the
  // atoms near them, and their `atoms` argument is ignored.
  const BlockShare* share = nullptr;
};

struct BlockedSurface {
  ComputedSurface surface;  // mesh: the pieces glued along their seams, checked (streamed: empty)
  std::vector<BlockStats> blocks;
  // False on every process of an exchange but the first: it made its pieces and handed
  // them over; `surface` is empty.
  bool root = true;
};

// The SAS, vdW and SES surfaces by the one-pass method (the pairwise method, outer_only and
// true_points are refused with molsurf::Error). Throws SurfaceCheckFailed when a piece
// or the glued surface fails its check.
BlockedSurface compute_blocked_surface(std::span<const Atom> atoms, const ComputeSurfaceOptions& options,
                                       const BlockedSurfaceOptions& blocked);

// What a piece must be: its own check passed but for the seam, which is its only boundary
// (one line per problem; empty when it is sound).
std::vector<std::string> piece_problems(const MeshCheck& check, std::size_t seam_edges);

}  // namespace molsurf::blocks
