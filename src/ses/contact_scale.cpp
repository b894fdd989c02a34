#include "ses/contact_scale.hpp"

#include <map>
#include <numbers>

#include "mesh/icosphere.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf::ses_detail {

double facet_balance(int frequency, bool area_corrected) {
  const Mesh unit = make_icosphere({0, 0, 0}, 1, {.frequency = frequency, .area_corrected = area_corrected});
  // Radially by 1 + e the area changes by about 2 e and the volume by 3 e: equal and
  // opposite errors after it when (a + 2 e) = -(v + 3 e).
  const double a = surface_area(unit) / (4 * std::numbers::pi) - 1;
  const double v = signed_volume(unit) / (4 * std::numbers::pi / 3) - 1;
  return 1 - (a + v) / 5;
}

std::vector<double> contact_scales(std::span<const Atom> atoms, const SphereOptions& spheres) {
  std::map<int, double> balance;  // by frequency: few distinct ones
  std::vector<double> out(atoms.size());
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const int frequency = sphere_frequency(atoms[i], spheres);
    auto it = balance.find(frequency);
    if (it == balance.end()) it = balance.emplace(frequency, facet_balance(frequency, spheres.area_corrected)).first;
    out[i] = atoms[i].radius / sphere_radius(atoms[i], spheres) * it->second;
  }
  return out;
}

}  // namespace molsurf::ses_detail
