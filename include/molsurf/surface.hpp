#pragma once
// Atoms to spheres: each atom becomes an icosphere of radius r_vdW + probe; how the spheres
// are joined (the union itself is src/surface/solvent_accessible_surface.hpp).
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf {

struct SphereOptions {
  double probe = 1.4;     // angstrom; 0 gives the van der Waals surface
  double density = 2.0;   // vertices per square angstrom of each sphere (MSMS's convention)
  int frequency = 0;      // fixed icosphere frequency for every atom; 0: from density
  // Scale each polyhedron so its area equals the sphere's. On by default: with it, area and
  // volume of the union are within 0.5 % of the exact union of balls at density 2
  // (docs/accuracy.md); inscribed polyhedra lose about 1 % of the volume.
  bool area_corrected = true;
  // Spheres smaller than this (angstrom) get the frequency of a sphere of this radius. The
  // faceting error of the union depends on the frequency, not on the radius, and the density
  // alone gives van der Waals spheres (probe 0, r 1.4-1.9 A) frequency 2-3: area +0.9 % and
  // volume -0.9 % off the exact union. With 2.5 A every sphere has at least frequency 4 at
  // density 2 (docs/accuracy.md); at probe 1.4 every sphere is larger, so nothing changes.
  // 0: the density alone.
  double min_density_radius = 2.5;
};

double sphere_radius(const Atom& atom, const SphereOptions& options);
// The radius the density is applied to: max(sphere_radius, min_density_radius).
double density_radius(const Atom& atom, const SphereOptions& options);
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

// How the spheres are joined. Both give the same surface up to its triangulation (area and
// volume agree to rounding; tests/test_surface_methods.cpp).
enum class SurfaceMethod {
  one_pass,  // every atom's faces trimmed by its neighbours, all atoms in parallel (default)
  pairwise,  // hierarchical pairwise union along a k-d tree (the paper's formulation; reference)
};
inline constexpr std::string_view kSurfaceMethodNames[] = {"one-pass", "pairwise"};  // in the enum's order
const char* surface_method_name(SurfaceMethod method);

// The union's size before it is computed, from a sample of atoms trimmed on their own
// (the one-pass method; ComputeSurfaceOptions::max_memory). bytes: the whole job's peak memory,
// faces x kBytesPerSurfaceFace (resource_limits.hpp).
struct SurfaceSizeEstimate {
  std::uint64_t faces = 0;  // of the union before cleanup, extrapolated from the sample
  std::uint64_t bytes = 0;
  std::size_t sampled_atoms = 0;
  std::size_t atoms = 0;
};

}  // namespace molsurf
