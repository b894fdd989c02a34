#pragma once
// Vertices moved toward given targets as far as validity allows: each move an edit of the
// editing layer, kept only when no face turns by more than 60 degrees, (with a minimum
// angle) no angle of the moved faces falls below it or below what it was, and the exact
// crossing test finds nothing; a refused move is tried again halfway. What was valid
// stays valid. The SAS's true points and the SES's (surface/true_points.hpp,
// ses/ses_true_points.hpp) differ only in their targets.
#include <cstdint>
#include <span>

#include "molsurf/mesh.hpp"
#include "molsurf/true_points.hpp"

namespace molsurf {

// `target[v]` for each vertex with `has_target[v]`; `min_angle_deg` 0: no angle rule.
// Fills every field of the stats but `seconds`.
TruePointStats move_vertices_toward(Mesh& mesh, std::span<const Vec3> target, std::span<const std::uint8_t> has_target,
                                    double min_angle_deg);

}  // namespace molsurf
