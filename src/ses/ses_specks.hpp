#pragma once
// Components of a drawn SES too small to be part of the true one. Every component of the
// SES holds a whole ball: an outer surface at least one atom's van der Waals ball, a cavity
// at least one probe ball (the probe's centre reaches a cavity of the accessible surface).
// A component whose bounding box is narrower in every direction than half the smaller of
// those two diameters (half: a cavity that just holds a probe ball, drawn with facets inside
// its sphere, stays) holds neither: a speck that the probe balls' carving left between their
// scallops and the cleanup then shrank (3pqr at density 4: ten faces 0.04 A across, whose
// exact volume came out negative, so the surface failed its check).
#include <cstddef>
#include <span>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf::ses_detail {

// Removes them from `mesh` (and the vertices only they used); returns how many.
std::size_t remove_specks(Mesh& mesh, std::span<const Atom> atoms, double probe);

}  // namespace molsurf::ses_detail
