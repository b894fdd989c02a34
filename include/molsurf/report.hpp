#pragma once
// Human-readable and JSON renderings of what molsurf read and measured.
#include <string>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/surface.hpp"

namespace molsurf {

// The structure summary: atoms kept by element, what was filtered out and why, radii.
std::string format_read_report(const ReadReport& report);
std::string format_sphere_plan(const SpherePlan& plan, const SphereOptions& options);

// `molsurf check` output: a two-column table ending in a VALID / INVALID verdict.
std::string format_mesh_check(const MeshCheck& check, const std::string& file);
std::string mesh_check_json(const MeshCheck& check, const std::string& file);

}  // namespace molsurf
