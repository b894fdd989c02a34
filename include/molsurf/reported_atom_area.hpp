#pragma once
// The per-atom area every report of a computed surface gives: the --per-atom, --per-residue
// and --per-chain tables, --sasa-structure's B-factors, the report's by-chain and by-class
// rows, the JSON's residues and atoms, --format's reports, --all-models' rows, and Python's
// Surface.area_per_atom and area_per_residue. Chosen here once, so the command and the
// Python module cannot disagree.
#include <vector>

#include "molsurf/compute_surface.hpp"

namespace molsurf {

// The exact area where the run computed it, else the facets':
// - the SAS and vdW surfaces with exact_areas: the true spheres' (exact_atom_area; with
//   outer_only only what lies on the outer shells);
// - the SES with exact_areas: its patches' (SesMeasures::area_per_atom, which already honour
//   the outer_only the surface was computed with);
// - otherwise (exact_areas off): `facets.atom_area`, the area of the mesh's faces on each atom.
// `facets`: the measures of the mesh as its file holds it (a format that rounds coordinates
// changes them a little); computed.measures when no file rounds. `outer_only`: as the surface
// was computed.
std::vector<double> reported_atom_area(const ComputedSurface& computed, bool outer_only,
                                       const SurfaceMeasures& facets);
inline std::vector<double> reported_atom_area(const ComputedSurface& computed, bool outer_only) {
  return reported_atom_area(computed, outer_only, computed.measures);
}

// The total area and volume reported beside them when the run has no true spheres'
// arrangement (the SES, or exact_areas off): the SES's patches' where computed, else the
// facets' (`facets` as above). With the arrangement, make_exact_report gives them.
struct ReportedTotals {
  double area = 0, volume = 0;
};
ReportedTotals reported_totals(const ComputedSurface& computed, const SurfaceMeasures& facets);

}  // namespace molsurf
