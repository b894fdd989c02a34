#pragma once
// The exact arrangement of the true spheres on the boundary of their union (no triangles):
// for every sphere, the circles its neighbours cut on it, the arcs of those circles that
// bound its exposed part, the vertices where three spheres meet on the surface, and the
// exposed spherical patches; the patches joined into shells (the outer surface and each
// cavity). Areas and volumes follow analytically (Stokes' theorem on the sphere and the
// divergence theorem), to floating-point rounding. These are the result's types:
// compute_areas.hpp computes it for atoms (the algorithm: src/arrangement/).
//
// For the solvent-accessible surface the spheres are the atoms' r_vdW + probe: a vertex is
// then a probe position touching three atoms, and an arc the path of a probe rolling on
// two (what the solvent-excluded surface is built from).
//
// Combinatorial decisions (which neighbours cut a sphere, which circles cross, whether a
// point lies inside a ball) are exact: a floating-point filter, then rational arithmetic.
// Tie rules: balls are open (a point on another sphere is exposed, and a point exposed alone,
// with nothing exposed around it, is dropped); a ball inside another
// (or tangent to it from inside) is buried; of identical spheres the lowest index counts;
// tangent spheres do not cut each other; of two neighbours cutting the same circle, the
// lower index owns it. The result does not depend on the thread count.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "molsurf/vec3.hpp"

namespace molsurf {

// A point where three spheres meet on the surface (a probe touching three atoms). Of the
// two points the three spheres share, `side` names which: the sign of the orientation of
// (centre a, centre b, centre c, point) for the sorted atoms a < b < c.
struct ArrangementVertex {
  std::array<std::uint32_t, 3> spheres{};  // sorted
  int side = 1;                            // +1 or -1
  Vec3 point;                              // rounded to doubles
};

// An exposed arc on `sphere`, along the circle that `other` cuts on it, running so that the
// exposed part lies on its left (seen from outside). A whole circle has no vertices.
struct ArrangementArc {
  std::uint32_t sphere = 0, other = 0;
  std::int64_t from = -1, to = -1;  // vertex indices; -1 for a whole circle
  // Radians swept about the circle's axis, in (0, 2 pi]; 0 only for an arc joining two
  // vertices at one point where four or more spheres meet, or within rounding of one (a
  // symmetric placement with rounded coordinates).
  double angle = 0;
  std::uint32_t patch = 0;          // index into SphereArrangement::patches
};

// A connected exposed region of one sphere.
struct ArrangementPatch {
  std::uint32_t sphere = 0;
  double area = 0;
  Vec3 vector_area;  // integral of the outward normal over the patch
  std::uint32_t shell = 0;
};

// A connected component of the union's boundary: the outer surface, or a cavity (whose
// volume, the divergence integral over its boundary, is negative).
struct ArrangementShell {
  double area = 0;
  double volume = 0;   // signed: negative for a cavity
  Vec3 centroid;       // of the shell's surface (area-weighted)
  std::vector<std::uint32_t> spheres;  // the spheres with a patch on it (a cavity's lining atoms), sorted
  bool cavity() const { return std::signbit(volume); }  // -0 for a void too small to measure
};

struct ArrangementStats {
  std::size_t spheres = 0, buried = 0, duplicate = 0, circles = 0;
  // Of the whole arrangement, also when its lists are not kept (an arrangement joined from
  // blocks keeps only what the report reads: see compute_surface.hpp's ComputedSurface::exact).
  std::size_t vertices = 0, arcs = 0;
  std::size_t exact_decisions = 0;     // decisions the floating-point filter left to rational arithmetic
  std::size_t degenerate_points = 0;   // vertices on a fourth sphere (four or more spheres through a point)
};

struct SphereArrangement {
  std::vector<ArrangementVertex> vertices;
  std::vector<ArrangementArc> arcs;          // sphere by sphere
  std::vector<ArrangementPatch> patches;     // sphere by sphere
  std::vector<ArrangementShell> shells;      // the largest outer shell first, then by area
  std::vector<double> area_per_sphere;
  double area = 0, volume = 0;               // volume: of the union, cavities excluded
  ArrangementStats stats;
};

}  // namespace molsurf
