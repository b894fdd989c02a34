#include "io/coordinate_range.hpp"

#include <cmath>
#include <cstdio>

#include "molsurf/error.hpp"

namespace molsurf::detail {

void check_coordinate_range(const std::filesystem::path& path, std::size_t line, double value,
                            const std::string& what) {
  if (std::abs(value) < kMaxCoordinate) return;
  char text[40];
  std::snprintf(text, sizeof text, "%g", value);
  if (!std::isfinite(value)) fail(path, line, what + " " + text + " is not a finite number");
  fail(path, line, what + " " + text + " is out of range (its magnitude must be below 1e16 angstrom)");
}

}  // namespace molsurf::detail
