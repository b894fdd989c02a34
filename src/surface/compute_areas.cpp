#include "molsurf/compute_areas.hpp"

#include <cstdio>

#include "io/coordinate_range.hpp"

#include <chrono>
#include <cmath>
#include <string>

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
  // The readers' bounds (coordinate_range.hpp), for atoms that come from no file.
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    const std::string atom = "atom " + std::to_string(i + 1) + " (counting from 1)";
    for (const double x : {a.centre.x, a.centre.y, a.centre.z})
      detail::check_coordinate_range("atoms", 0, x, atom + ": coordinate");
    if (!std::isfinite(a.radius) || a.radius < 0 || a.radius >= detail::kMaxCoordinate)
      throw Error("atoms: " + atom + ": radius " + number(a.radius) +
                  " is not a finite number of zero or more below 1e16");
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
