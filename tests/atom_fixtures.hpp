#pragma once
// An atom given only by its centre and radius (element C), for surface tests.
#include "molsurf/atoms.hpp"

namespace molsurf::testing {

inline Atom atom_at(const Vec3& c, double r) {
  Atom a;
  a.centre = c;
  a.radius = r;
  a.element = "C";
  return a;
}

}  // namespace molsurf::testing
