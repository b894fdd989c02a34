#include "molsurf/compute_areas.hpp"

#include <cstdio>

#include <chrono>
#include <cmath>
#include <string>

#include "arrangement/sphere_arrangement.hpp"
#include "molsurf/error.hpp"

#include "molsurf/surface_measures.hpp"

namespace molsurf {

void check_spheres(std::span<const Atom> atoms, const SphereOptions& spheres) {
  auto number = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return std::string(text);
  };
  if (!std::isfinite(spheres.probe) || spheres.probe < 0)
    throw Error("probe radius " + number(spheres.probe) + ": not a finite number of zero or more");
  // Atoms that come from no file (Python, a library caller): what exact predicates cannot
  // take. The readers' tighter bound (coordinate_range.hpp) is theirs and the Python
  // module's; beyond it a surface is computed and, where doubles no longer resolve the
  // spheres, fails its check (SurfaceCheckFailed).
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    const std::string atom = "atoms: atom " + std::to_string(i + 1) + " (counting from 1)";
    for (const double x : {a.centre.x, a.centre.y, a.centre.z})
      if (!std::isfinite(x)) throw Error(atom + ": coordinate " + number(x) + " is not a finite number");
    if (!std::isfinite(a.radius) || a.radius < 0)
      throw Error(atom + ": radius " + number(a.radius) + " is not a finite number of zero or more");
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
