#pragma once
// Shape measures of one tetrahedron, for the volume mesh's report.
#include <array>

#include "molsurf/mesh.hpp"

namespace molsurf::volume_detail {

struct TetrahedronShape {
  double volume = 0;            // absolute
  double min_dihedral_deg = 0;  // smallest of the six dihedral angles
  double radius_ratio = 0;      // 3 x inradius / circumradius: 1 regular, 0 flat
};

TetrahedronShape tetrahedron_shape(const std::array<Vec3, 4>& p);

}  // namespace molsurf::volume_detail
