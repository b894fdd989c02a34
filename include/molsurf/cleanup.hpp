#pragma once
// Surface improvement (paper §2.5): repeated unions leave slivers; this removes them by
// collapsing the shortest edge of each distorted face when that keeps the surface valid.
#include <cstddef>

#include "molsurf/mesh.hpp"

namespace molsurf {

struct CleanupOptions {
  double min_angle_deg = 5;       // faces with a smaller angle are distorted
  int passes = 6;
  double max_area_change = 1e-3;  // relative; collapses stop before exceeding it
};

struct CleanupStats {
  Quality before, after;
  double area_before = 0, area_after = 0;
  std::size_t collapses = 0;
  std::size_t flips = 0;
  std::size_t refused = 0;  // collapses that would have broken validity or quality
};

// A collapse of edge uv (v merged into u) is made only if: the link condition holds (the
// mesh stays a 2-manifold); no face around v turns over or becomes degenerate (exact
// orientation against its own previous plane); the smallest angle around the edge
// improves; no moved face meets any other face beyond their shared corners (exact
// triangle-pair test against a spatial hash); and the total area stays within
// max_area_change. Where one end is on a seam (faces of different tags meet there) the
// seam vertex is kept. A face with no collapsible edge (a cap) gets its longest edge
// flipped instead, within one sphere (equal tags, nearly coplanar faces), under the same
// checks. Deterministic.
CleanupStats improve_surface(Mesh& mesh, const CleanupOptions& options = {});

}  // namespace molsurf
