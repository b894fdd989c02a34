#pragma once
// Human-readable and JSON renderings of what molsurf read and measured.
#include <filesystem>
#include <string>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/surface.hpp"
#include "molsurf/volume_mesh.hpp"

namespace molsurf {

// The structure summary: atoms kept by element, what was filtered out and why, radii.
std::string format_read_report(const ReadReport& report);
std::string format_sphere_plan(const SpherePlan& plan, const SphereOptions& options);

// `molsurf check` output: a two-column table ending in a VALID / INVALID verdict.
std::string format_mesh_check(const MeshCheck& check, const std::string& file);
std::string mesh_check_json(const MeshCheck& check, const std::string& file);

// The volume mesh's lines of the surface report: its file, tetrahedra and nodes, each
// region's tetrahedra and volume, the tetrahedra's quality.
std::string format_volume_mesh_report(const VolumeMeshReport& report, const std::filesystem::path& file);

}  // namespace molsurf
