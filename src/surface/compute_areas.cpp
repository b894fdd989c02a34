#include "molsurf/compute_areas.hpp"

#include <chrono>

#include "molsurf/surface_measures.hpp"

namespace molsurf {

ComputedAreas compute_areas(std::span<const Atom> atoms, const SphereOptions& spheres, int threads) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Vec3> centres(atoms.size());
  std::vector<double> radii(atoms.size());
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    centres[i] = atoms[i].centre;
    radii[i] = sphere_radius(atoms[i], spheres);
  }
  ComputedAreas out;
  out.arrangement = arrange_spheres(centres, radii, {.threads = threads});
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::vector<double> exact_atom_area(const SphereArrangement& arrangement, bool outer_only) {
  if (!outer_only) return arrangement.area_per_sphere;
  std::vector<double> area(arrangement.area_per_sphere.size(), 0);
  for (const ArrangementPatch& p : arrangement.patches)
    if (!arrangement.shells[p.shell].cavity()) area[p.sphere] += p.area;
  return area;
}

}  // namespace molsurf
