#pragma once
// The blocked surface streamed to disk (`molsurf --blocks N -o NAME.pvtp`, and mpirun): each
// piece is made, cleaned with its seam band frozen and checked as in the glued job, then
// split (streamed_piece.hpp): its faces away from the seams go to their file at once and are
// released, and only the seam band, the border and a summary are kept (on the first process,
// which receives them from the others). The seam bands are then glued and cleaned with
// both sides in view (the written faces near them frozen, as obstacles), checked together
// with every border, and become one more piece. The report is merged from the summaries:
// totals, per-atom areas, and the components joined through the band; the exact areas
// from each block's arrangement of its own spheres (block_areas.hpp), made once the piece's
// written faces are released. A process alone keeps each block's kept part on disk until
// every block is made (spilled_bytes.hpp). The peak memory is one piece's, or the bands and
// borders' at the join, not the whole surface's, nor the whole structure's arrangement.
#include <span>

#include "blocks/block_partition.hpp"
#include "blocks/blocked_surface.hpp"
#include "blocks/held_blocks.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"

namespace molsurf::blocks {

// `options`: the job's (surface_job_options), its thread count already set. `held`: what
// this process makes its pieces from; `origin`: the whole structure's volume_origin. On the
// first process (or one alone), which joins the seams, `atoms` is the whole structure and
// `partition` the job's; the others, which hold only their share, give neither.
BlockedSurface compute_streamed_surface(std::span<const Atom> atoms, const BlockPartition* partition,
                                        const HeldBlocks& held, const Vec3& origin,
                                        const ComputeSurfaceOptions& options, const BlockedSurfaceOptions& blocked);

}  // namespace molsurf::blocks
