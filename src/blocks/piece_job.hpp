#pragma once
// What both block jobs (the glued one, blocked_surface.cpp, and the streamed one,
// streamed_surface.cpp) do alike: refuse what blocks cannot make, make one block's piece
// (union, cleanup with its seam band frozen, its own check) and add up the pieces' counts.
#include <cstddef>

#include "blocks/block_partition.hpp"
#include "blocks/piece_bytes.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/cleanup.hpp"
#include "molsurf/compute_surface.hpp"

namespace molsurf::blocks {

// Rings of edges around a piece's seam that its own cleanup leaves alone.
inline constexpr int kPieceSeamBand = 3;
// Rings around the glued seams that the seams' cleanup may change (two more than the
// pieces left alone: the pieces' slivers next to their frozen band are reached too).
inline constexpr int kSeamCleanupBand = kPieceSeamBand + 2;

// molsurf::Error for what blocks do not make: the SES, the pairwise method, outer_only,
// true_points, the Stern layer.
void refuse_unsupported(const ComputeSurfaceOptions& options);

// Block b's piece: computed, cleaned with its seam band frozen, checked but for the seam
// (SurfaceCheckFailed otherwise).
PieceMessage make_piece(std::span<const Atom> atoms, const BlockPartition& partition, std::size_t b,
                        const ComputeSurfaceOptions& options, int threads);

// The counts of one more cleanup (a piece's, or the seams').
void add_cleanup(ComputedSurface& result, const CleanupStats& cleaned);

// The quality of two meshes together, from each one's.
void combine_quality(Quality& total, const Quality& part);

}  // namespace molsurf::blocks
