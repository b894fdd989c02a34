#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include "common/size_text.hpp"
#include "mesh/icosphere.hpp"
#include "molsurf/error.hpp"
#include "molsurf/resource_limits.hpp"
#include "molsurf/surface.hpp"

namespace molsurf {

double sphere_radius(const Atom& atom, const SphereOptions& options) { return atom.radius + options.probe; }

double density_radius(const Atom& atom, const SphereOptions& options) {
  return std::max(sphere_radius(atom, options), options.min_density_radius);
}

int sphere_frequency(const Atom& atom, const SphereOptions& options) {
  return options.frequency > 0 ? options.frequency
                               : frequency_for_density(density_radius(atom, options), options.density);
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

namespace {

using detail::count_text;
using detail::gigabytes_text;

constexpr double kSaturated = 1.8e19;  // just below 2^64

// 20 n^2 faces of the icosphere of an atom of radius `radius` (without the probe), in
// double so that no frequency overflows.
double sphere_faces(double radius, const SphereOptions& options) {
  Atom atom;
  atom.radius = radius;
  double n = options.frequency;
  if (options.frequency <= 0) {
    const double r = density_radius(atom, options);
    const double target = options.density * 4 * std::numbers::pi * r * r;
    n = std::sqrt(std::max(0.0, target - 2) / 10);
    // Within int range frequency_for_density decides exactly (it rounds to the nearest).
    if (n < 1e6) n = sphere_frequency(atom, options);
  }
  return 20 * std::max(1.0, n) * std::max(1.0, n);
}

std::uint64_t saturate(double value) {
  return value >= kSaturated || !std::isfinite(value) ? std::numeric_limits<std::uint64_t>::max()
                                                      : static_cast<std::uint64_t>(value);
}

// All spheres' faces, and the largest's, from `count` radii (without the probe).
template <class RadiusOf>
ResourceEstimate estimate_from_radii(std::size_t count, RadiusOf&& radius_of, const SphereOptions& options) {
  double total = 0, largest = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const double faces = sphere_faces(radius_of(i), options);
    total += faces;
    largest = std::max(largest, faces);
  }
  return {saturate(total), saturate(largest), saturate(total * static_cast<double>(kBytesPerSphereFace))};
}

std::string describe(const Atom& atom, std::size_t index) {
  std::string text = "atom " + std::to_string(index + 1);
  if (atom.serial != 0) text += " (serial " + std::to_string(atom.serial);
  else text += " (";
  if (!atom.residue_name.empty() || !atom.atom_name.empty()) {
    text += atom.serial != 0 ? ", " : "";
    text += atom.atom_name;
    if (!atom.residue_name.empty())
      text += " of " + atom.residue_name + " " + std::to_string(atom.residue_number) +
              (atom.chain.empty() ? "" : " chain " + atom.chain);
  }
  text += ")";
  if (text.ends_with(" ()")) text.resize(text.size() - 3);
  return text;
}

}  // namespace

ResourceEstimate estimate_resources(std::span<const Atom> atoms, const SphereOptions& options) {
  return estimate_from_radii(atoms.size(), [&](std::size_t i) { return atoms[i].radius; }, options);
}

void check_sphere_resources(const std::filesystem::path& input, std::span<const Atom> atoms,
                            const SphereOptions& options, std::uint64_t max_faces) {
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const double r = sphere_radius(atoms[i], options);
    if (r >= kMinSphereRadius && std::isfinite(r)) continue;
    char radius[32];
    std::snprintf(radius, sizeof radius, "%g", atoms[i].radius);
    if (r > 0 && std::isfinite(r))
      fail(input, describe(atoms[i], i) + " has radius " + radius + ": its sphere (radius + probe) is below " +
                      "1e-06 A, too small to triangulate; give it a radius of at least 1e-06 A");
    fail(input, describe(atoms[i], i) + " has radius " + radius +
                    (options.probe == 0 ? ", and with --probe 0 its sphere is a point, which has no surface; "
                                          "give it a positive radius or use a probe radius above 0"
                                        : ": its sphere radius (radius + probe) must be positive and finite"));
  }
  check_sphere_faces(input, estimate_resources(atoms, options), options, max_faces);
}

ResourceEstimate estimate_resources(std::span<const double> radii, const SphereOptions& options) {
  return estimate_from_radii(radii.size(), [&](std::size_t i) { return radii[i]; }, options);
}

void check_sphere_faces(const std::filesystem::path& input, const ResourceEstimate& estimate,
                        const SphereOptions& options, std::uint64_t max_faces) {
  char settings[96];
  std::snprintf(settings, sizeof settings, "--density %g and --probe %g", options.density, options.probe);
  const std::string how = options.frequency > 0 ? "--frequency " + std::to_string(options.frequency) : settings;
  if (estimate.largest_sphere > kMaxFacesPerSphere)
    fail(input, "one sphere would have " + count_text(estimate.largest_sphere) + " faces with " + how +
                    ", more than the finest sphere allowed (" + count_text(kMaxFacesPerSphere) +
                    " faces, --frequency 200); lower --density, or check the radii and --probe");
  if (estimate.sphere_faces > max_faces)
    fail(input, "the spheres would have " + count_text(estimate.sphere_faces) + " faces before the union with " +
                    how + " (about " + gigabytes_text(estimate.bytes) + " of memory), more than the limit of " +
                    count_text(max_faces) + "; lower --density or use --frequency, or raise the limit with --max-faces");
}

std::uint64_t available_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  std::uint64_t bytes = pages > 0 && page_size > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size)
                                                    : std::numeric_limits<std::uint64_t>::max();
  // A container's limit ("max" when there is none) is what the kernel enforces.
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");
  unsigned long long limit = 0;
  if (cgroup >> limit && limit > 0) bytes = std::min<std::uint64_t>(bytes, limit);
  return bytes;
}

void check_surface_memory(const std::filesystem::path& input, const SurfaceSizeEstimate& estimate,
                          std::uint64_t max_bytes) {
  if (estimate.bytes <= max_bytes) return;
  fail(input, "the surface would have about " + count_text(estimate.faces) + " faces before cleanup (estimated from " +
                  std::to_string(estimate.sampled_atoms) + " of " + std::to_string(estimate.atoms) +
                  " atoms) and need about " + gigabytes_text(estimate.bytes) + " of memory, more than the limit of " +
                  gigabytes_text(max_bytes) + "; lower --density, or raise the limit with --max-memory");
}

}  // namespace molsurf
