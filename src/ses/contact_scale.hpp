#pragma once
// Where the SES's contact patches lie: each atom's SAS faces scaled about its centre onto
// its van der Waals sphere. Flat facets cannot match a sphere's area and volume at once:
// the area-corrected icosphere of frequency 4 has the sphere's area and 0.58 % less
// volume, the inscribed one loses both. The contact patch is scaled so that the two
// errors are equal and opposite (area +0.23 %, volume -0.23 % at frequency 4): a probe's
// footprint on a small atom is most of the SES, and neither the area nor the volume that a
// BEM solver integrates should carry the whole faceting error.
#include <span>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/surface.hpp"

namespace molsurf::ses_detail {

// Per atom, the factor that takes its SAS sphere's mesh (about the atom's centre) to its
// contact patch: r / (r + probe), times the facets' balance for that sphere's frequency.
std::vector<double> contact_scales(std::span<const Atom> atoms, const SphereOptions& spheres);

// For a sphere meshed as `spheres` mesh it at this frequency: the radial factor after which
// its facets' area is as much above the sphere's as their volume is below it.
double facet_balance(int frequency, bool area_corrected);

}  // namespace molsurf::ses_detail
