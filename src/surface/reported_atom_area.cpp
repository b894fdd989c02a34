#include "molsurf/reported_atom_area.hpp"

#include "molsurf/compute_areas.hpp"

namespace molsurf {

std::vector<double> reported_atom_area(const ComputedSurface& computed, bool outer_only,
                                       const SurfaceMeasures& facets) {
  if (!computed.exact.area_per_sphere.empty()) return exact_atom_area(computed.exact, outer_only);
  if (computed.ses_patches) return computed.ses_patches->area_per_atom;
  return facets.atom_area;
}

ReportedTotals reported_totals(const ComputedSurface& computed, const SurfaceMeasures& facets) {
  if (computed.ses_patches) return {computed.ses_patches->area, computed.ses_patches->volume};
  return {facets.area, facets.volume};
}

}  // namespace molsurf
