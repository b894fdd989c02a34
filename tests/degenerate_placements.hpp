#pragma once
// Random small sets of atoms drawn from the placements where exact geometry is hardest:
// atoms on grids whose spacing equals the radius or twice it (every sphere tangent to its
// neighbours), on a 0.1 A grid, on the vertices of an icosahedron around an atom, exact
// duplicates, equal radii everywhere. Seeded: a family and a seed give the same atoms on
// every machine.
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "atom_fixtures.hpp"
#include "molsurf/atoms.hpp"

namespace molsurf::testing {

struct DegeneratePlacement {
  std::vector<Atom> atoms;
  std::string family;
};

enum class PlacementFamily { lattice, fine_grid, icosahedral_shell, duplicates, tangent_pairs };
inline constexpr PlacementFamily kAllPlacementFamilies[] = {
    PlacementFamily::lattice, PlacementFamily::fine_grid, PlacementFamily::icosahedral_shell,
    PlacementFamily::duplicates, PlacementFamily::tangent_pairs};

inline DegeneratePlacement degenerate_placement(PlacementFamily family, std::uint32_t seed) {
  std::mt19937 random(seed);
  auto pick = [&](int n) { return static_cast<int>(random() % static_cast<std::uint32_t>(n)); };
  const double radii[] = {1.0, 1.5, 1.7, 1.88};
  const double r = radii[pick(4)];
  DegeneratePlacement out;
  auto add = [&](const Vec3& c, double radius) { out.atoms.push_back(atom_at(c, radius)); };
  switch (family) {
    case PlacementFamily::lattice: {  // a lattice: spacing = radius (deep overlaps) or 2 radius (tangent spheres)
      const double spacing = pick(2) ? r : 2 * r;
      out.family = spacing == r ? "lattice at the radius" : "tangent lattice";
      const int n = 2 + pick(2);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          for (int k = 0; k < 2; ++k)
            if (pick(4) != 0) add({i * spacing, j * spacing, k * spacing}, r);
      break;
    }
    case PlacementFamily::fine_grid: {  // a few atoms on a 0.1 A grid in one plane, equal radii
      out.family = "0.1 A grid";
      const int n = 2 + pick(4);
      for (int i = 0; i < n; ++i) add({0.1 * (pick(31) - 15), 0.1 * (pick(31) - 15), 0}, r);
      break;
    }
    case PlacementFamily::icosahedral_shell: {  // atoms on an icosahedron's vertices around a centre atom
      out.family = "icosahedral shell";
      const double phi = (1 + std::sqrt(5.0)) / 2, d = r * (0.5 + 0.25 * pick(5));
      const double scale = d / std::sqrt(1 + phi * phi);
      add({0, 0, 0}, r);
      const std::array<Vec3, 12> ico = {Vec3{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                                        {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                                        {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
      for (const Vec3& v : ico)
        if (pick(3) != 0) add(v * scale, r);
      break;
    }
    case PlacementFamily::duplicates: {  // duplicates and exact copies shifted along one axis by the radius
      out.family = "duplicates";
      const int n = 2 + pick(3);
      for (int i = 0; i < n; ++i) add({pick(2) * r, 0, 0}, r);
      add({0, pick(2) * r, 0}, r);
      break;
    }
    case PlacementFamily::tangent_pairs: {  // pairs touching exactly along the axes and diagonals
      out.family = "tangent pairs";
      add({0, 0, 0}, r);
      add({2 * r, 0, 0}, r);
      if (pick(2)) add({0, 2 * r, 0}, r);
      if (pick(2)) add({r, r, 0}, r);
      break;
    }
  }
  if (out.atoms.empty()) add({0, 0, 0}, r);
  return out;
}

}  // namespace molsurf::testing
