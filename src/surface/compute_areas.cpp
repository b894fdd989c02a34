#include "molsurf/compute_areas.hpp"

#include <chrono>
#include <cmath>
#include <string>

#include "arrangement/sphere_arrangement.hpp"
#include "molsurf/error.hpp"
#include "molsurf/input_checks.hpp"
#include "molsurf/parameters.hpp"
#include "molsurf/surface_measures.hpp"

namespace molsurf {

void check_spheres(std::span<const Atom> atoms, const SphereOptions& spheres) {
  check(kProbeParameter, spheres.probe);
  // Atoms that come from no file (Python, a library caller): what exact predicates cannot
  // take. The readers' tighter bound (kMaxCoordinate) is theirs and the Python module's;
  // beyond it a surface is computed and, where doubles no longer resolve the spheres, fails
  // its check (SurfaceCheckFailed).
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    const std::string atom = "atoms: atom " + std::to_string(i + 1) + " (counting from 1)";
    for (const double x : {a.centre.x, a.centre.y, a.centre.z})
      if (!std::isfinite(x)) throw Error(atom + ": coordinate: " + coordinate_problem(x));
    if (!std::isfinite(a.radius) || a.radius < 0) throw Error(atom + ": radius: " + radius_problem(a.radius));
  }
}

ComputedAreas compute_areas(std::span<const Atom> atoms, const SphereOptions& spheres, int threads) {
  check(kThreadsParameter, threads);
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
