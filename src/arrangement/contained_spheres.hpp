#pragma once
// Spheres that add nothing to a union of balls because another ball holds them: the
// smaller of concentric spheres, and copies. Dropping them before the union keeps a pile
// of atoms at one centre from costing the square of its size (every one of them would be
// every other's neighbour). The one-pass union, the pairwise union and the arrangement all
// take the same decision from the same doubles (r_vdW + probe as the union uses it), so
// their surfaces and areas agree.
#include <cstdint>
#include <span>
#include <vector>

#include "molsurf/vec3.hpp"

namespace molsurf::arrangement {

// container[i] == i when no other sphere's closed ball holds sphere i's (exactly:
// |c_i - c_j| + r_i <= r_j, ball_in_ball); otherwise a sphere whose closed ball holds it
// and which is itself held by none. Of identical spheres the lowest index is the one
// kept. O(n log n) for any number of spheres at one centre: a sphere is compared only with
// the kept spheres near it, a few per cell of a grid per power of two of radius.
std::vector<std::uint32_t> sphere_containers(std::span<const Vec3> centres, std::span<const double> radii);

}  // namespace molsurf::arrangement
