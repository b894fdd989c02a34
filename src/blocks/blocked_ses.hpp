#pragma once
// The first process's part of the SES over blocks: the pieces (ses_piece.hpp) glued by
// position, the seams' band cleaned by the SES's rules and moved onto the true patches with
// both sides in view, specks removed, the whole checked; the patches' measures from the
// whole structure's arrangement, as compute_surface measures one SES.
#include <span>
#include <string>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf::blocks {

// Fills `result` (mesh, check, measures, patches, arrangement; adds to its cleanup counts,
// true points and times, which hold the pieces' already). `area_change`: what the pieces'
// cleanups changed the area by, in all (the seams' cleanup gets what is left of the budget).
// False, with `why`, when the pieces leave a seam open or the glued surface fails its
// check: the caller then draws the SES whole.
bool finish_blocked_ses(std::span<const Atom> atoms, const ComputeSurfaceOptions& options, std::vector<Mesh> pieces,
                        double area_change, ComputedSurface& result, std::string& why);

}  // namespace molsurf::blocks
