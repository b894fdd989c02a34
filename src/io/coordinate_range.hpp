#pragma once
// Internal: the bound every reader puts on coordinates, structures and meshes alike.
#include <cstddef>
#include <filesystem>
#include <string>

namespace molsurf::detail {

// Coordinates (and radii) must be below this in magnitude. Beyond it the spacing of
// doubles exceeds 1 angstrom, so no atom is resolved any more; such numbers are input
// errors (a units mix-up, a corrupt column), not something to compute with.
inline constexpr double kMaxCoordinate = 1e16;

// Fails with "FILE:LINE: WHAT VALUE is out of range ..." unless |value| < kMaxCoordinate,
// or "... is not a finite number" for NaN and infinity (line 0: no line; `what` then
// names the place, e.g. the atom or the vertex).
void check_coordinate_range(const std::filesystem::path& path, std::size_t line, double value,
                            const std::string& what);

}  // namespace molsurf::detail
