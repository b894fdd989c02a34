#include "molsurf/compute_areas.hpp"

#include <chrono>
#include <cmath>
#include <string>

#include "molsurf/error.hpp"

#include "molsurf/surface_measures.hpp"

namespace molsurf {

void check_spheres(std::span<const Atom> atoms, const SphereOptions& spheres) {
  if (!std::isfinite(spheres.probe) || spheres.probe < 0)
    throw Error("probe radius " + std::to_string(spheres.probe) + ": not a finite number of zero or more");
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    const Vec3& c = a.centre;
    for (const double x : {c.x, c.y, c.z})
      if (!std::isfinite(x)) throw Error("atom " + std::to_string(i) + ": a coordinate is not a finite number");
    if (!std::isfinite(a.radius) || a.radius < 0)
      throw Error("atom " + std::to_string(i) + ": radius " + std::to_string(a.radius) +
                  " is not a finite number of zero or more");
  }
}

ComputedAreas compute_areas(std::span<const Atom> atoms, const SphereOptions& spheres, int threads) {
  check_spheres(atoms, spheres);
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
