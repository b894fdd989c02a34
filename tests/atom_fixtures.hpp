#pragma once
// An atom given only by its centre and radius (element C), for surface tests, and placements
// several tests share.
#include <vector>

#include "molsurf/atoms.hpp"

namespace molsurf::testing {

inline Atom atom_at(const Vec3& c, double r) {
  Atom a;
  a.centre = c;
  a.radius = r;
  a.element = "C";
  return a;
}

// A 4 x 4 x 3 lattice of atoms of radius 1.5: split into blocks, whole layers lie on the
// cutting planes.
inline std::vector<Atom> lattice_4x4x3(double spacing) {
  std::vector<Atom> atoms;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 3; ++k) atoms.push_back(atom_at({i * spacing, j * spacing, k * spacing}, 1.5));
  return atoms;
}

}  // namespace molsurf::testing
