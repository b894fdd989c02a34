#pragma once
// compute_surface for the SES when the atoms' SAS union is made already: the blocks
// (src/blocks/) make it piece by piece and glue it, the same faces as the one-pass union of
// one process, and everything after it (the SES drawn, cleaned, moved onto its patches,
// checked and measured) is compute_surface's own.
#include <span>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf::surface_detail {

// options.surface must be SurfaceKind::ses. `sas_union`: the one-pass union of the atoms'
// r + probe spheres as it leaves it (closed, uncleaned; face tags the atoms' indices).
ComputedSurface compute_ses_from_union(std::span<const Atom> atoms, const ComputeSurfaceOptions& options,
                                       Mesh sas_union);

}  // namespace molsurf::surface_detail
