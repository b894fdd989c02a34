#pragma once
// The checks every surface job makes before any sphere is built, and the options it then
// runs with: the caller's, validated, with the van der Waals surface made the accessible one
// at probe 0. compute_surface and the blocked surface (src/blocks/) both start here, so a
// job refused by one is refused by the other with the same message.
#include <span>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"

namespace molsurf::surface_detail {

ComputeSurfaceOptions surface_job_options(std::span<const Atom> atoms, const ComputeSurfaceOptions& requested);

}  // namespace molsurf::surface_detail
