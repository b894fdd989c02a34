#pragma once
// The reference molsurf's accuracy is measured against: area and volume of the exact
// union of balls (no triangles), per ball and in total.
//
// Each sphere is cut into z-slices of equal width (equal area, by Archimedes). On each
// slice's circle the parts inside other balls are arcs with closed-form ends, so the
// exposed length, and the divergence-theorem volume term x.n integrated along it, are
// exact; only the integral over z is a midpoint rule. Where a slice's circle grazes an
// intersection circle the exposed length has a square-root kink, so the error falls only
// about as 1/slices: ~1e-5 relative at 4000 slices on a lens (tests/test_ball_union.cpp). Cavity walls count as exposed (the solvent-accessible surface includes
// them) and the volume is that of the union, cavities excluded.
#include <cstddef>
#include <span>
#include <vector>

#include "molsurf/vec3.hpp"

namespace molsurf {

struct BallUnionMeasure {
  double area = 0, volume = 0;
  std::vector<double> area_per_ball;
};

BallUnionMeasure measure_ball_union(std::span<const Vec3> centres, std::span<const double> radii,
                                    int slices_per_ball = 2000);

}  // namespace molsurf
