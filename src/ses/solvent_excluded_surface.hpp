#pragma once
// The solvent-excluded (molecular) surface: the boundary of the points a probe ball rolling
// over the van der Waals spheres cannot reach. Its solid is the solvent-accessible solid
// eroded by the probe: the SAS solid minus the probe's sweep over the SAS boundary. The
// sweep has three families (vertices, arcs, faces); here
//   core   = SAS solid minus the sweep over the faces, built directly (excluded_core.hpp);
//   sweep  = the union of probe balls at the arrangement's vertices and along its arcs
//            (probe_sweep.hpp), joined by the one-pass union of balls;
//   SES    = core minus sweep, by the exact Boolean difference.
// Both operands are closed, manifold and free of self-intersections, and every decision
// of the union and the difference is exact: the result is a valid surface by construction.
#include <cstddef>
#include <span>

#include "molsurf/atoms.hpp"
#include "molsurf/cleanup.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/sphere_arrangement.hpp"
#include "molsurf/surface.hpp"

namespace molsurf::ses_detail {

struct ExcludedSurfaceStats {
  std::size_t sas_faces = 0, rolled_faces = 0, core_faces = 0, probes = 0, sweep_faces = 0;
  std::size_t singular_faces = 0;  // rolled faces crossing or touching another (the SES's singularities)
  std::size_t pinched_vertices = 0, ridge_vertices = 0;
  int attempts = 0;  // SAS meshes tried: the cleaned one, then (if the engine stopped) the union's own
  double seconds_sas = 0, seconds_arrangement = 0, seconds_core = 0, seconds_sweep = 0, seconds_difference = 0;
};

struct ExcludedSurface {
  Mesh mesh;  // face tags: atom index (the nearest atom the probe touched, for sweep faces)
  SphereArrangement arrangement;  // of the SAS spheres (r_vdW + probe)
  ExcludedSurfaceStats stats;
};

// spheres.probe > 0 and every atom's radius > 0 (throws molsurf::Error otherwise).
ExcludedSurface solvent_excluded_surface(std::span<const Atom> atoms, const SphereOptions& spheres, int threads);

// The spacing of probe centres along an arc at this density (vertices per square angstrom).
double probe_spacing(double density);
// The longest segment of a meridian arc at this density (0.35 / sqrt(density) A: half the
// 0.7 it was, which halved crambin's area error at density 2 once the cleanup coarsens the
// result to the density asked; docs/ses.md, "Density").
double arc_spacing(double density);
// Edges of the SES shorter than this are collapsed by its cleanup (0.8 / sqrt(density)
// angstrom: 0.57 A at density 2, where an even mesh's edge is 0.76 A). The toroidal and
// reentrant vertices go back onto the true surface after it (ses_true_points.hpp), so the
// collapses cost little accuracy, and the mesh has about the vertices per A^2 asked.
double ses_min_edge_length(double density);
// Before a last attempt, the SAS's edges shorter than this are collapsed (0.3 / sqrt(density)).
double sas_min_edge_length(double density);
// The cleanup the SES gets, from the caller's: the SES drawn from the SAS mesh carries every
// short seam edge of it into its strips (50 to 80 faces per A^2 at density 2), so edges
// under ses_min_edge_length are collapsed too (1crn keeps 9 264 of 190 000 faces); and
// each component's volume may change by at most 0.1 % either way, since collapses across
// the sharp ridges where overlapping probes meet cut the ridges off (four atoms whose
// reentrant patches overlap lost 0.7 % of their volume).
CleanupOptions ses_cleanup_options(CleanupOptions options, double density);

}  // namespace molsurf::ses_detail
