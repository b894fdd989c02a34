#pragma once
// Where the probe goes when it rolls over the solvent-accessible surface's arcs and rests on
// its vertices: the arrangement's vertices (a probe touching three atoms) and points along
// every exposed arc (a probe touching two), no farther apart than `spacing`. The union of
// probe balls at these centres stands for the probe's sweep over arcs and vertices: exact
// at the vertices, and along an arc scalloped between neighbouring balls by about
// spacing^2 / (8 probe) (docs/ses.md).
#include <array>
#include <cstdint>
#include <vector>

#include "molsurf/sphere_arrangement.hpp"
#include "molsurf/vec3.hpp"

namespace molsurf::ses_detail {

struct ProbeCentre {
  Vec3 centre;
  // The atoms the probe touches: three at a vertex, two along an arc (the third repeats the second).
  std::array<std::uint32_t, 3> atoms{};
};

// `centres`, `radii`: the spheres the arrangement was made of (r_vdW + probe).
std::vector<ProbeCentre> probe_sweep(const SphereArrangement& arrangement, const std::vector<Vec3>& centres,
                                     const std::vector<double>& radii, double spacing);

}  // namespace molsurf::ses_detail
