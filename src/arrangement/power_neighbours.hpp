#pragma once
// Which spheres can bound each other's exposed part: the neighbours in the power diagram
// (the weighted Voronoi diagram whose cells are {x : |x - c_i|^2 - r_i^2 is least}). A
// point of sphere i is exposed iff it lies in i's power cell, and that cell is the
// intersection of the half-spaces of its facets alone, so the caps of i's power
// neighbours decide its exposed part; any other ball covers only what those already do.
// About 14 neighbours per atom at probe 1.4 where some 44 balls overlap each one.
//
// The regular triangulation (CGAL, exact predicates) gives the neighbours. Its weights
// are r^2 rounded to doubles: a neighbour whose shared face is smaller than what that
// rounding moves (faces of 1e-8 A and below, in nearly degenerate placements) may be
// missed; exactly degenerate placements (four or more spheres through a point) lose only
// faces of zero area, which cover nothing.
#include <cstdint>
#include <span>
#include <vector>

#include "molsurf/vec3.hpp"

namespace molsurf::arrangement {

struct PowerNeighbours {
  std::vector<std::uint32_t> offset;     // sphere i's neighbours: list[offset[i] .. offset[i + 1])
  std::vector<std::uint32_t> list;       // sorted per sphere
  std::vector<char> hidden;              // an empty power cell: nothing of the sphere is exposed
};

// Only spheres with include[i] take part (the others get no neighbours and are hidden).
PowerNeighbours power_neighbours(std::span<const Vec3> centres, std::span<const double> radii,
                                 std::span<const char> include);

}  // namespace molsurf::arrangement
