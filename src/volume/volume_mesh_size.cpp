#include "volume/volume_mesh_size.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "common/size_text.hpp"
#include "molsurf/error.hpp"
#include "molsurf/resource_limits.hpp"

namespace molsurf::volume_detail {

double tetrahedra_lower_bound(const BoundingBox& box, double size) {
  const Vec3 extent = box.max - box.min;
  const double volume = extent.x * extent.y * extent.z;
  return volume / (size * size * size / (6 * std::sqrt(2.0)));
}

void check_volume_mesh_memory(const BoundingBox& box, double size, std::uint64_t max_memory) {
  const std::uint64_t limit = max_memory > 0 ? max_memory : available_memory_bytes();
  const double tetrahedra = tetrahedra_lower_bound(box, size);
  const double bytes = tetrahedra * static_cast<double>(kBytesPerTetrahedron);
  // In double: a size of 1e-6 A gives more tetrahedra than any integer holds.
  if (bytes <= static_cast<double>(limit)) return;
  const Vec3 extent = box.max - box.min;
  char text[256];
  std::snprintf(text, sizeof text,
                "volume mesh: the box (%g x %g x %g A) with tetrahedra of size %g A would hold at least %.3g "
                "tetrahedra and need at least %s of memory, more than the limit of %s; ",
                extent.x, extent.y, extent.z, size, tetrahedra,
                detail::gigabytes_text(bytes >= 1.8e19 ? std::numeric_limits<std::uint64_t>::max()
                                                       : static_cast<std::uint64_t>(bytes))
                    .c_str(),
                detail::gigabytes_text(limit).c_str());
  throw Error(std::string(text) + "raise --volume-size, lower --box-margin, or raise the limit with --max-memory");
}

}  // namespace molsurf::volume_detail
