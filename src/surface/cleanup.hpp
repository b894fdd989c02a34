#pragma once
// Surface improvement (paper §2.5), compute_surface's cleanup stage: the slivers that the
// union leaves removed by edits that keep the surface valid (the options and counts:
// include/molsurf/cleanup.hpp).
#include <cstdint>
#include <span>

#include "molsurf/cleanup.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf {

// Each pass takes the distorted faces, worst first, and makes the best valid change
// around each: collapse of a short edge (to either end or to its midpoint), flip of an
// edge, merge of a cluster of vertices much closer to each other than to the rest (edge
// by edge), widening of a neck (a loop of three short edges that is not a face, where two
// spheres barely overlap: it grows about its centre, corner by corner), or, last, a move
// of one corner toward the centre of its neighbours in the tangent plane (a seam vertex
// only along its seam). Every change must keep the mesh a 2-manifold (link condition; a
// flip's new edge must not exist), must turn no face over or make it degenerate (exact
// collinearity; no normal may turn by more than 60 degrees; no edge of a changed face may
// fold its two faces within 1 degree of each other unless the faces replaced had a sharper
// edge: exactly valid, such a fold looks like overlapping faces to floating-point
// consumers such as meshers), must make the worst angle
// among the faces it touches better (a cluster merge or a neck widening is judged as a
// whole), must keep the total area within max_area_change (and each component's volume
// within max_volume_change, when that is set), and no
// face it changes may meet any other face beyond their shared corners (exact
// triangle-pair test against a spatial hash). Seams (where faces of different tags, i.e.
// different spheres, meet) stay where they are when that does as well: among changes
// that reach min_angle_deg, those that keep them (a seam vertex merging into a vertex
// on the same seams, a flip within one sphere) come first. A flip needs the two faces
// within 26 degrees of coplanar, 20 across a seam. Last, edges shorter than
// min_edge_fraction of the median edge are collapsed, shortest first, by the same rules,
// except that the worst angle need only not get worse than it was or than min_angle_deg.
// The edits of a pass run in parallel, region by region (cells of a coarse grid far enough
// apart that no two edits made at once touch or read the same faces), each region's
// faces worst first; the result does not depend on the thread count.
CleanupStats improve_surface(Mesh& mesh, const CleanupOptions& options = {});
// The same with `frozen[v]` (one flag per vertex) for the vertices no edit may move or merge
// away: where the mesh joins faces beyond it (a spatial block's seam, src/blocks/).
CleanupStats improve_surface(Mesh& mesh, const CleanupOptions& options, std::span<const std::uint8_t> frozen);

}  // namespace molsurf
