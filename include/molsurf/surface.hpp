#pragma once
// Atoms to spheres: each atom becomes an icosphere of radius r_vdW + probe.
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf {

struct SphereOptions {
  double probe = 1.4;     // angstrom; 0 gives the van der Waals surface
  double density = 2.0;   // vertices per square angstrom of each sphere (MSMS's convention)
  int frequency = 0;      // fixed icosphere frequency for every atom; 0: from density
  bool area_corrected = false;  // scale each polyhedron so its area equals the sphere's
};

double sphere_radius(const Atom& atom, const SphereOptions& options);
int sphere_frequency(const Atom& atom, const SphereOptions& options);
// The atom's icosphere, every face tagged with `tag` (the atom's index).
Mesh atom_sphere(const Atom& atom, std::int32_t tag, const SphereOptions& options);

// What the spheres will be, without building them: for summaries and memory planning.
struct SpherePlan {
  std::map<int, std::size_t> atoms_by_frequency;
  std::size_t faces = 0, vertices = 0;
  double min_radius = 0, max_radius = 0;
};
SpherePlan plan_spheres(std::span<const Atom> atoms, const SphereOptions& options);

}  // namespace molsurf
