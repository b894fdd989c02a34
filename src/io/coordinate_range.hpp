#pragma once
// Internal: the bound every reader puts on coordinates, structures and meshes alike
// (kMaxCoordinate and its wording: molsurf/input_checks.hpp).
#include <cstddef>
#include <filesystem>
#include <string>

namespace molsurf::detail {

// Fails with "FILE:LINE: WHAT: PROBLEM" (coordinate_problem) unless |value| < kMaxCoordinate
// (line 0: no line; `what` then names the place, e.g. the atom or the vertex).
void check_coordinate_range(const std::filesystem::path& path, std::size_t line, double value,
                            const std::string& what);

}  // namespace molsurf::detail
