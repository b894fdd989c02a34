#include <algorithm>
#include <stdexcept>

#include "molsurf/icosphere.hpp"
#include "molsurf/surface.hpp"

namespace molsurf {

double sphere_radius(const Atom& atom, const SphereOptions& options) { return atom.radius + options.probe; }

int sphere_frequency(const Atom& atom, const SphereOptions& options) {
  return options.frequency > 0 ? options.frequency
                               : frequency_for_density(sphere_radius(atom, options), options.density);
}

Mesh atom_sphere(const Atom& atom, std::int32_t tag, const SphereOptions& options) {
  return make_icosphere(atom.centre, sphere_radius(atom, options),
                        {.frequency = sphere_frequency(atom, options),
                         .area_corrected = options.area_corrected,
                         .tag = tag});
}

SpherePlan plan_spheres(std::span<const Atom> atoms, const SphereOptions& options) {
  SpherePlan plan;
  if (atoms.empty()) return plan;
  plan.min_radius = plan.max_radius = sphere_radius(atoms.front(), options);
  for (const Atom& atom : atoms) {
    const double r = sphere_radius(atom, options);
    plan.min_radius = std::min(plan.min_radius, r);
    plan.max_radius = std::max(plan.max_radius, r);
    const std::size_t n = static_cast<std::size_t>(sphere_frequency(atom, options));
    ++plan.atoms_by_frequency[static_cast<int>(n)];
    plan.faces += 20 * n * n;
    plan.vertices += 10 * n * n + 2;
  }
  return plan;
}

}  // namespace molsurf
