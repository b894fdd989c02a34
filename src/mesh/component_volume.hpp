#pragma once
// The enclosed volume of each connected component, and its exact sign. Far from the
// origin a small component's volume summed about the origin is mostly rounding (a cavity of
// 1e-8 A^3 at 150 A); summed about one of its own vertices the terms scale with the
// component, and when the sum is still within its error bound of zero it is redone
// exactly in integers (every double is an integer times a power of two). The sign is what
// decides outer surface against cavity, in the check and in the reports. Linear in the
// faces, however many components need integers.
#include <vector>

#include "molsurf/mesh.hpp"

namespace molsurf {

struct ComponentVolumes {
  std::vector<double> volume;  // per component, relative to its own first vertex
  std::vector<int> sign;       // exact: +1, -1, or 0 (a flat component)
  std::size_t exact_signs = 0;  // components whose sign floating point could not settle
};

ComponentVolumes component_volumes(const Mesh& mesh, const Components& components);

}  // namespace molsurf
