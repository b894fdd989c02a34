#pragma once
// The whole surface job in one call: atoms -> spheres -> union -> cleanup -> check ->
// measures. Every rule of the pipeline lives here, so the command line and any other
// front end (a Python module) get the same surface from the same atoms:
//  - the order: union, then (optionally) the cavities dropped, then cleanup, then check;
//  - a one-pass surface that fails its check is recomputed by the pairwise union (the
//    reference, which repairs rounding between merges), with a note;
//  - a surface that still fails is never returned: the call throws SurfaceCheckFailed.
// Writing files is not part of it (io.hpp, written_check.hpp, output_files.hpp).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/cancel.hpp"
#include "molsurf/cleanup.hpp"
#include "molsurf/error.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/resource_limits.hpp"
#include "molsurf/ses_measures.hpp"
#include "molsurf/sphere_arrangement.hpp"
#include "molsurf/surface.hpp"
#include "molsurf/surface_report.hpp"
#include "molsurf/true_points.hpp"

namespace molsurf {

// The stages of compute_surface, in the order they run.
enum class SurfaceStage { union_, cleanup, check, measures };
const char* surface_stage_name(SurfaceStage stage);  // "union", "cleanup", "check", "measures"

// Which surface of the atoms: the solvent-accessible surface (the probe centre's surface:
// spheres of r_vdW + probe), the solvent-excluded (molecular) surface (where the rolling
// probe touches the atoms), or the van der Waals surface (spheres of r_vdW; the SAS at probe 0).
enum class SurfaceKind { sas, ses, vdw };
inline constexpr std::string_view kSurfaceKindNames[] = {"sas", "ses", "vdw"};  // in the enum's order
const char* surface_kind_name(SurfaceKind kind);  // "sas", "ses", "vdw"

// PyGBe's Stern layer: the atoms' radii grown by 2 A (its generateStern.py) before meshing.
inline constexpr double kDefaultSternProbe = 2.0;

struct ComputeSurfaceOptions {
  SphereOptions spheres;
  // With ses, spheres.probe is the rolling probe's radius (above 0); with vdw it is ignored.
  SurfaceKind surface = SurfaceKind::sas;
  SurfaceMethod method = SurfaceMethod::one_pass;
  int threads = 0;  // for every stage; 0: all cores. The result does not depend on it.
  bool outer_only = false;  // drop the cavities (components of negative volume) before cleanup
  bool cleanup = true;      // improve_surface (paper §2.5)
  CleanupOptions cleanup_options;
  // The exact self-intersection test (the check's expensive part). Without it, closed,
  // manifold, oriented, outward and non-degenerate are still required.
  bool check_self_intersections = true;
  // Also the exact arrangement of the true spheres (compute_areas.hpp): exact areas and
  // volumes per atom, shell and in total, beside the facets' own. For the SES: its area and
  // volume from the arrangement's patches instead (ComputedSurface::ses_patches).
  bool exact_areas = true;
  // After cleanup, move the vertices onto the true spheres, circles and triple points where
  // validity allows (true_points.hpp).
  bool true_points = false;
  // Refuse, before any sphere is built, spheres with more faces than this in all
  // (check_sphere_resources); `source` names the input in that message.
  std::uint64_t max_sphere_faces = kDefaultMaxSphereFaces;
  // Refuse, before the one-pass union, a surface whose estimated memory
  // (check_surface_memory) is above this many bytes. 0: the memory this process may use
  // (available_memory_bytes); the maximum of std::uint64_t: no limit.
  std::uint64_t max_memory = 0;
  std::filesystem::path source = "atoms";
  // Also the Stern layer of the same atoms: their solvent-accessible surface at this probe
  // (the union of the r + stern_probe spheres; the ion-exclusion layer a BEM solver such as
  // PyGBe takes as its second surface: kDefaultSternProbe), made with the same density,
  // cleanup, check and outer_only. Absent: none.
  std::optional<double> stern_probe;
  // Called as the work advances with (stage, done, total), from one thread at a time but
  // not always the caller's (the pairwise union reports from its worker threads). The
  // union reports (atoms trimmed, atoms) or (merges done, merges); every stage also
  // reports (0, 1) when it starts and (1, 1) when it ends. May be empty.
  std::function<void(SurfaceStage, std::size_t, std::size_t)> progress;
  // Set from another thread to stop the call with Cancelled (cancel.hpp): read inside the
  // union's loops and at every stage boundary. May be null.
  const CancelFlag* cancel = nullptr;
};

struct ComputeSurfaceTimings {  // wall seconds, summed over both methods after a fallback
  double union_ = 0;  // spheres and their union (and dropping the cavities, with outer_only)
  double cleanup = 0;
  double check = 0;
  double measures = 0;
  double total = 0;  // the whole call
};

// What users study on a surface: the numbers of a SurfaceReport, plus each atom's area.
struct SurfaceMeasures {
  std::size_t faces = 0, vertices = 0;
  double area = 0, volume = 0;                 // volume: inside the outer surface, minus cavities
  std::vector<ComponentMeasure> components;    // the largest outer surface first (measure_components)
  Quality quality;
  std::vector<double> atom_area;               // one per atom: the area of the faces tagged with it
};

// The measures of `mesh`, whose check_mesh result is `check` (area, volume and quality
// come from there). For a surface as a lossy file holds it (written_check.hpp), too. With
// `exact` and `component_shells`, the components are matched to its shells in the same pass
// (shells_of_components).
SurfaceMeasures measure_surface(const Mesh& mesh, const MeshCheck& check, std::size_t atom_count,
                                const SphereArrangement* exact = nullptr,
                                std::vector<std::int64_t>* component_shells = nullptr);

struct ComputedSurface {
  Mesh mesh;  // passed its check; face tags are atom indices
  SurfaceMethod method = SurfaceMethod::one_pass;  // the method that made `mesh`
  // Why the requested method's surface was replaced (the fallback), one line each; empty
  // when it was not.
  std::vector<std::string> notes;
  MeshCheck check;                       // of `mesh`: valid
  std::optional<CleanupStats> cleanup;   // absent when cleanup is off
  std::optional<TruePointStats> true_points;  // with ComputeSurfaceOptions::true_points; always for the SES
  Quality quality_before;                // of the union, before cleanup
  Quality quality_after;                 // of `mesh` (equal to quality_before without cleanup)
  SurfaceMeasures measures;  // the facets'
  // The true spheres' arrangement (with exact_areas; empty otherwise): sphere i is atom i.
  // From streamed blocks (`--blocks N -o NAME.pvtp`, mpirun) it is joined from the blocks'
  // own arrangements and keeps only what the reports read: the per-sphere areas, the
  // shells, the stats (with the vertex and arc counts), and one patch per sphere and shell
  // (its area; no vector area); no vertex or arc lists.
  SphereArrangement exact;
  // The shell of `exact` each of measures.components follows (shells_of_components).
  std::vector<std::int64_t> component_shells;
  // The solvent-excluded surface only (null otherwise): the arrangement of the atoms' r + probe
  // spheres it was built from, where the probe's centre rolls. Its files' MSMS patch types,
  // closest atoms and normals come from it (patch_types.hpp).
  std::shared_ptr<const SphereArrangement> ses_arrangement;
  // The solvent-excluded surface with exact_areas: its area and volume from the arrangement's
  // patches (ses_measures.hpp), with outer_only as the mesh. Absent otherwise.
  std::optional<SesMeasures> ses_patches;
  // With ComputeSurfaceOptions::stern_probe: the Stern layer, computed as the SAS at that probe
  // is (its own checked mesh, measures and exact arrangement). Null otherwise.
  std::shared_ptr<const ComputedSurface> stern;
  ComputeSurfaceTimings seconds;
  int threads = 1;  // used for every stage
};

// A surface that failed its check with both methods: a molsurf bug (never seen on the
// test corpus), or coordinates beyond what doubles can resolve at this sphere size. The
// message lists the defects; the surface itself is kept for a bug report.
class SurfaceCheckFailed : public Error {
 public:
  SurfaceCheckFailed(MeshCheck check, Mesh mesh, std::vector<std::string> notes);
  const MeshCheck& check() const { return failure_->check; }
  const Mesh& mesh() const { return failure_->mesh; }
  const std::vector<std::string>& notes() const { return failure_->notes; }

 private:
  struct Failure {
    MeshCheck check;
    Mesh mesh;
    std::vector<std::string> notes;
  };
  std::shared_ptr<const Failure> failure_;  // shared: exceptions are copied
};

// The solvent-accessible surface of `atoms` (radius + probe each), cleaned, checked and
// measured. No atoms give an empty mesh. Throws molsurf::Error when the spheres exceed
// max_sphere_faces (or cannot be built), SurfaceCheckFailed as above.
ComputedSurface compute_surface(std::span<const Atom> atoms, const ComputeSurfaceOptions& options = {});

// Throws molsurf::Error for a sphere (radius + probe) above 0 but under 2^-30 of its
// centre's largest coordinate: its icosphere's corners would round together. compute_surface
// checks it first; the exact areas (compute_areas) have no such limit.
void check_sphere_resolution(std::span<const Atom> atoms, const SphereOptions& spheres);

}  // namespace molsurf
