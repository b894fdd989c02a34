#pragma once
// What moving the mesh's vertices onto the true surface did (ComputeSurfaceOptions::true_points;
// the moves themselves: src/surface/true_points.hpp).
#include <cstddef>

namespace molsurf {

struct TruePointStats {
  std::size_t vertices = 0;       // with faces
  std::size_t on_true_point = 0;  // moved onto it (or there already)
  std::size_t partly = 0;         // moved halfway only
  std::size_t not_moved = 0;      // every move refused, or no true point (four or more atoms)
  double max_distance_left = 0;   // angstrom, over the vertices with a true point
  double seconds = 0;
};

}  // namespace molsurf
