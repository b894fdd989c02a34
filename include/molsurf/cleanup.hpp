#pragma once
// The options and counts of the surface improvement (paper §2.5, compute_surface's cleanup
// stage; src/surface/cleanup.hpp): repeated unions leave slivers, removed by edge collapses,
// edge flips and small vertex moves that keep the surface valid.
#include <cstddef>

#include "molsurf/mesh.hpp"

namespace molsurf {

struct CleanupOptions {
  double min_angle_deg = 5;       // faces with a smaller angle are distorted
  int passes = 6;
  double max_area_change = 1e-3;  // relative; changes stop before exceeding it
  // Each component's volume likewise (relative, either way); 0: only kept at half its size
  // and its sign.
  double max_volume_change = 0;
  // Edges shorter than this part of the median edge are collapsed afterwards (where the
  // rules allow), whatever their faces' angles: meshers' floating-point boundary recovery
  // takes the faces around them for overlapping. 0: no such pass.
  double min_edge_fraction = 0.02;
  // And edges shorter than this (angstrom), whatever the median: for a surface whose median
  // edge is itself far below what its density asks (the SES drawn from the SAS mesh). 0: none.
  double min_edge_length = 0;
  // False: CleanupStats::after is left empty, for a caller that measures the cleaned surface
  // anyway (compute_surface's check does).
  bool measure_after = true;
};

struct CleanupStats {
  Quality before, after;
  double area_before = 0, area_after = 0;
  std::size_t collapses = 0;
  std::size_t flips = 0;
  std::size_t moves = 0;    // vertices moved (tangential smoothing around a remaining sliver)
  std::size_t refused = 0;  // distorted faces no valid change improved (once per pass)
  std::size_t short_edges_before = 0, short_edges_after = 0;  // under min_edge_fraction of the median
};

}  // namespace molsurf
