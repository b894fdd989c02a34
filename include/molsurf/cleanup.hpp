#pragma once
// Surface improvement (paper §2.5): repeated unions leave slivers; this removes them by
// edge collapses, edge flips and small vertex moves that keep the surface valid.
#include <cstddef>

#include "molsurf/mesh.hpp"

namespace molsurf {

struct CleanupOptions {
  double min_angle_deg = 5;       // faces with a smaller angle are distorted
  int passes = 6;
  double max_area_change = 1e-3;  // relative; changes stop before exceeding it
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
// whole), must keep the total area within max_area_change, and no
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

}  // namespace molsurf
