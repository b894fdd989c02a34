#pragma once
// What both block jobs (the glued one, blocked_surface.cpp, and the streamed one,
// streamed_surface.cpp) do alike: refuse what blocks cannot make, make one block's piece
// (union, cleanup with its seam band frozen, its own check) and add up the pieces' counts.
#include <cstddef>
#include <span>

#include "blocks/block_partition.hpp"
#include "blocks/held_blocks.hpp"
#include "blocks/piece_bytes.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/cleanup.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/mesh_check.hpp"

namespace molsurf::blocks {

// Rings of edges around a piece's seam that its own cleanup leaves alone.
inline constexpr int kPieceSeamBand = 3;
// Rings around the glued seams that the seams' cleanup may change (two more than the
// pieces left alone: the pieces' slivers next to their frozen band are reached too).
inline constexpr int kSeamCleanupBand = kPieceSeamBand + 2;

// What every block job decides first, from the whole structure: its options
// (surface_job_options: the spheres checked) and its partition. Streamed, the limit on the
// spheres' faces applies to each block with its halo (a process holds one at a time), not
// to the whole structure. Throws molsurf::Error (or ParameterError) for a job refused.
struct BlockJob {
  ComputeSurfaceOptions options;
  BlockPartition partition;
};
BlockJob plan_block_job(std::span<const Atom> atoms, const ComputeSurfaceOptions& requested, std::size_t blocks,
                        bool streamed);

// Whether a job asked to stream its pieces can: the SES's pieces are joined and their seams
// cleaned on the first process, which holds the whole surface (blocked_ses.hpp); it is
// never streamed.
bool streams(const ComputeSurfaceOptions& options);

// molsurf::Error for what blocks do not make: the pairwise method, outer_only, true_points,
// the Stern layer.
void refuse_unsupported(const ComputeSurfaceOptions& options);

// The check every block job runs on what it makes: the job's choice of self-intersections.
MeshCheckOptions check_options_of(const ComputeSurfaceOptions& options);

// Block b's message, begun: its block and its atom counts.
PieceMessage begun_piece(const HeldBlocks& held, std::size_t b);

// A piece's own check, but for its seam, its only boundary (SurfaceCheckFailed naming the
// block otherwise); sets m.stats.seam_edges, m.seconds_check and m.stats.seconds.
void check_piece(const Mesh& piece, const ComputeSurfaceOptions& options, const HeldBlocks& held, std::size_t b,
                 PieceMessage& m);

// Block b's piece, from the atoms this process holds: computed, cleaned with its seam band
// frozen, checked but for the seam (SurfaceCheckFailed otherwise). The SES's: ses_piece.hpp.
PieceMessage make_piece(const HeldBlocks& held, std::size_t b, const ComputeSurfaceOptions& options, int threads);

// The counts of one more cleanup (a piece's, or the seams').
void add_cleanup(ComputedSurface& result, const CleanupStats& cleaned);

// The counts of one more set of vertices moved onto the true surface (an SES piece's, or
// the seams').
void add_true_points(std::optional<TruePointStats>& total, const TruePointStats& part);

// The quality of two meshes together, from each one's.
void combine_quality(Quality& total, const Quality& part);

// One piece's quality before cleanup, cleanup counts and times added to the whole surface's
// (a PieceMessage, glued, or a StreamedPiece).
template <class Piece>
void add_piece_totals(ComputedSurface& result, Quality& before, const Piece& piece, bool cleanup) {
  combine_quality(before, piece.before);
  if (cleanup) {
    add_cleanup(result, piece.cleanup);
    result.cleanup->area_before += piece.cleanup.area_before;
  }
  result.seconds.union_ += piece.seconds_union;
  result.seconds.cleanup += piece.seconds_cleanup;
  result.seconds.check += piece.seconds_check;
}

}  // namespace molsurf::blocks
