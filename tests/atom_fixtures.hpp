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

// A row of four atoms 1.5 A apart, a copy of atom 2 (index 4) and an atom inside atom 2's
// ball (index 5): split into two blocks, the copy falls in the other block.
inline std::vector<Atom> row_with_copies() {
  std::vector<Atom> atoms;
  for (int i = 0; i < 4; ++i) atoms.push_back(atom_at({1.5 * i, 0, 0}, 1.5));
  atoms.push_back(atom_at({3.0, 0, 0}, 1.5));
  atoms.push_back(atom_at({3.0, 0, 0}, 1.0));
  return atoms;
}

}  // namespace molsurf::testing
