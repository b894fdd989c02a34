#include "surface/surface_job_options.hpp"

#include "molsurf/compute_areas.hpp"
#include "molsurf/parameters.hpp"
#include "molsurf/resource_limits.hpp"

namespace molsurf::surface_detail {

ComputeSurfaceOptions surface_job_options(std::span<const Atom> atoms, const ComputeSurfaceOptions& requested) {
  validate(requested);
  ComputeSurfaceOptions options = requested;
  if (options.surface == SurfaceKind::vdw) {
    options.surface = SurfaceKind::sas;
    options.spheres.probe = 0;
  }
  check_spheres(atoms, options.spheres);
  check_sphere_resolution(atoms, options.spheres);
  // Before any sphere is built: a typo in the density must not run the machine out of memory.
  check_sphere_resources(options.source, atoms, options.spheres, options.max_sphere_faces);
  return options;
}

}  // namespace molsurf::surface_detail
