#include "molsurf/compute_surface.hpp"

#include "molsurf/compute_areas.hpp"
#include "molsurf/parameters.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <stdexcept>
#include <utility>

#include "common/thread_count_scope.hpp"
#include "ses/solvent_excluded_surface.hpp"
#include "surface/cleanup.hpp"
#include "surface/one_pass/one_pass_union.hpp"
#include "surface/solvent_accessible_surface.hpp"
#include "surface/surface_job_options.hpp"
#include "ses/ses_specks.hpp"
#include "ses/ses_true_points.hpp"
#include "surface/true_points.hpp"

namespace molsurf {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string check_failure_message(const MeshCheck& check) {
  std::string message =
      "the computed surface failed its check (a molsurf bug; please report it with the input file and options):";
  for (const std::string& defect : check.defects()) message += "\n  - " + defect;
  return message;
}

// One method's surface, cleaned and checked: what compute_surface keeps or retries.
struct Attempt {
  Mesh mesh;
  SurfaceMethod method = SurfaceMethod::one_pass;
  // A one-pass union that is not closed is neither cleaned nor checked: why (empty: it is closed).
  std::string open;
  MeshCheck check;
  std::optional<CleanupStats> cleanup;
  std::optional<TruePointStats> true_points;
  std::shared_ptr<const SphereArrangement> ses_arrangement;  // the SES's r + probe spheres
};

class Pipeline {
 public:
  Pipeline(std::span<const Atom> atoms, const ComputeSurfaceOptions& options, int threads,
           ComputeSurfaceTimings& seconds, std::vector<std::string>& notes)
      : atoms_(atoms), options_(options), threads_(threads), seconds_(seconds), notes_(notes) {}

  Attempt run(SurfaceMethod method) const {
    Attempt attempt;
    auto clock = std::chrono::steady_clock::now();
    report(SurfaceStage::union_, 0, 1);
    SphereUnionOptions surface_options;
    surface_options.spheres = options_.spheres;
    surface_options.method = method;
    surface_options.threads = threads_;
    surface_options.cancel = options_.cancel;
    if (options_.progress)
      surface_options.progress = [this](std::size_t done, std::size_t total) {
        options_.progress(SurfaceStage::union_, done, total);
      };
    // A surface that cannot fit is refused before its memory is spent: the estimate is
    // sampled only when the spheres could make one that large (two output faces for every
    // sphere face is far above any protein's union: 2btv at probe 0, density 4, has 0.65).
    const std::uint64_t max_memory = options_.max_memory > 0 ? options_.max_memory : available_memory_bytes();
    surface_options.estimate_size_above = max_memory / (2 * kBytesPerSurfaceFace);
    surface_options.check_size = [this, max_memory](const SurfaceSizeEstimate& estimate) {
      check_surface_memory(options_.source, estimate, max_memory);
    };
    if (options_.surface == SurfaceKind::ses) {
      ses_detail::ExcludedSurface ses = ses_detail::solvent_excluded_surface(atoms_, options_.spheres, threads_);
      attempt.method = SurfaceMethod::one_pass;
      attempt.mesh = options_.outer_only ? outer_surface_only(ses.mesh) : std::move(ses.mesh);
      attempt.ses_arrangement = std::make_shared<const SphereArrangement>(std::move(ses.arrangement));
    } else {
      SphereUnion sas = method == SurfaceMethod::pairwise ? pairwise_union(surface_options)
                                                            : solvent_accessible_surface(atoms_, surface_options);
      attempt.method = sas.method;
      if (sas.one_pass.open_edges > 0) {
        attempt.open = surface_detail::open_union_message(sas.one_pass.open_edges);
        seconds_.union_ += seconds_since(clock);
        return attempt;
      }
      attempt.mesh = options_.outer_only ? outer_surface_only(sas.mesh) : std::move(sas.mesh);
    }
    seconds_.union_ += seconds_since(clock);
    report(SurfaceStage::union_, 1, 1);

    if (options_.cleanup) {
      clock = std::chrono::steady_clock::now();
      report(SurfaceStage::cleanup, 0, 1);
      // The check measures the cleaned surface's quality: not twice.
      CleanupOptions cleanup_options = options_.cleanup_options;
      cleanup_options.measure_after = false;
      // The SES's own rules (short edges, volume budget: ses_detail::ses_cleanup_options).
      if (options_.surface == SurfaceKind::ses)
        cleanup_options = ses_detail::ses_cleanup_options(cleanup_options, options_.spheres.density);
      attempt.cleanup = improve_surface(attempt.mesh, cleanup_options);
      seconds_.cleanup += seconds_since(clock);
      report(SurfaceStage::cleanup, 1, 1);
    }
    if (options_.surface == SurfaceKind::ses) {
      // The SES's vertices onto its true patches: the facets' roughness put 0.9 % on
      // crambin's area at density 2, on the true patches it is 0.1 % (docs/ses.md).
      clock = std::chrono::steady_clock::now();
      attempt.true_points =
          ses_detail::move_to_ses_points(attempt.mesh, atoms_, options_.spheres.probe, *attempt.ses_arrangement,
                                         ses_detail::ses_max_true_point_move(options_.spheres.density));
      if (const std::size_t specks = ses_detail::remove_specks(attempt.mesh, atoms_, options_.spheres.probe))
        notes_.push_back(std::to_string(specks) +
                         " component(s) of the drawn SES too small to hold an atom or a probe removed (docs/ses.md)");
      seconds_.cleanup += seconds_since(clock);
    } else if (options_.true_points) {  // counted with the cleanup: both edit the mesh
      clock = std::chrono::steady_clock::now();
      attempt.true_points = move_to_true_points(attempt.mesh, atoms_, options_.spheres);
      seconds_.cleanup += seconds_since(clock);
    }

    clock = std::chrono::steady_clock::now();
    report(SurfaceStage::check, 0, 1);
    MeshCheckOptions check_options;
    check_options.self_intersections = options_.check_self_intersections;
    attempt.check = check_mesh(attempt.mesh, check_options);
    if (attempt.cleanup) attempt.cleanup->after = attempt.check.quality;
    seconds_.check += seconds_since(clock);
    report(SurfaceStage::check, 1, 1);
    return attempt;
  }

  // The pairwise union could stop on exactly symmetric placements (an operand that touches
  // itself where a face of the other passes; none of the long degenerate battery does:
  // docs/boolean.md, "Rounding and its repair"). That is a limit of the reference method,
  // said as such, not an internal error.
  SphereUnion pairwise_union(const SphereUnionOptions& surface_options) const {
    try {
      return solvent_accessible_surface(atoms_, surface_options);
    } catch (const std::invalid_argument&) {
      throw;  // a caller's mistake, not the engine's limit
    } catch (const std::logic_error& stop) {
      throw Error(options_.source.string() + ": the pairwise union cannot join these spheres (" + stop.what() +
                  "): they meet in an exactly symmetric configuration it does not handle; the one-pass method "
                  "(the default) does");
    }
  }

  void report(SurfaceStage stage, std::size_t done, std::size_t total) const {
    throw_if_cancelled(options_.cancel);
    if (options_.progress) options_.progress(stage, done, total);
  }

 private:
  std::span<const Atom> atoms_;
  const ComputeSurfaceOptions& options_;
  int threads_;
  ComputeSurfaceTimings& seconds_;
  std::vector<std::string>& notes_;
};

}  // namespace

const char* surface_kind_name(SurfaceKind kind) {
  const auto index = static_cast<std::size_t>(kind);
  return index < std::size(kSurfaceKindNames) ? kSurfaceKindNames[index].data() : "?";
}

const char* surface_stage_name(SurfaceStage stage) {
  switch (stage) {
    case SurfaceStage::union_: return "union";
    case SurfaceStage::cleanup: return "cleanup";
    case SurfaceStage::check: return "check";
    case SurfaceStage::measures: return "measures";
  }
  return "?";
}

SurfaceCheckFailed::SurfaceCheckFailed(MeshCheck check, Mesh mesh, std::vector<std::string> notes)
    : Error(check_failure_message(check)),
      failure_(std::make_shared<const Failure>(Failure{std::move(check), std::move(mesh), std::move(notes)})) {}

SurfaceMeasures measure_surface(const Mesh& mesh, const MeshCheck& check, std::size_t atom_count,
                                const SphereArrangement* exact, std::vector<std::int64_t>* component_shells) {
  SurfaceMeasures m;
  m.faces = mesh.face_count();
  m.vertices = mesh.vertex_count();
  m.area = check.area;
  if (exact && component_shells) {
    MeshComponentsAndShells both = measure_components_and_shells(mesh, *exact);
    m.components = std::move(both.components);
    *component_shells = std::move(both.shells);
  } else {
    m.components = measure_components(mesh);
  }
  m.volume = enclosed_volume(m.components);  // as the streamed blocks add theirs
  m.quality = check.quality;
  m.atom_area = area_per_atom(mesh, atom_count);
  return m;
}

void check_sphere_resolution(std::span<const Atom> atoms, const SphereOptions& spheres) {
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    const double r = sphere_radius(a, spheres);
    const double reach = std::max({std::fabs(a.centre.x), std::fabs(a.centre.y), std::fabs(a.centre.z)});
    if (r > 0 && r < std::ldexp(reach, -30)) {
      char text[320];
      std::snprintf(text, sizeof text,
                    "atom %zu: its sphere's radius %.3g A is too small for its position (a coordinate of %.3g A): "
                    "under 1e-9 of the coordinates, the icosphere's corners round together; move the structure "
                    "near the origin, or use --areas-only (exact at any scale)",
                    i, r, reach);
      throw Error(text);
    }
  }
}

ComputedSurface compute_surface(std::span<const Atom> atoms, const ComputeSurfaceOptions& requested) {
  const auto start = std::chrono::steady_clock::now();
  const ComputeSurfaceOptions options = surface_detail::surface_job_options(atoms, requested);
  ComputedSurface result;
  result.threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  // Every stage's parallel loops (union, cleanup, check) use the same team size.
  const ThreadCountScope thread_count(result.threads);
  const Pipeline pipeline(atoms, options, result.threads, result.seconds, result.notes);

  // The one place that falls back to the pairwise union (the reference method): for a
  // one-pass union that is not closed (never seen: a bug), and for a one-pass surface that
  // fails its check (rounded to doubles it can fail where the pairwise one, which repairs
  // rounding between merges, does not).
  Attempt attempt = pipeline.run(options.method);
  if (attempt.method == SurfaceMethod::one_pass && options.surface == SurfaceKind::sas &&
      (!attempt.open.empty() || !attempt.check.valid())) {
    result.notes.push_back(!attempt.open.empty() ? attempt.open + ": the pairwise union was used"
                                                 : "the one-pass surface failed its check; using the pairwise union");
    attempt = pipeline.run(SurfaceMethod::pairwise);
  }
  // The promise is a valid surface or none.
  if (!attempt.check.valid())
    throw SurfaceCheckFailed(std::move(attempt.check), std::move(attempt.mesh), std::move(result.notes));

  const auto clock = std::chrono::steady_clock::now();
  pipeline.report(SurfaceStage::measures, 0, 1);
  const bool exact = options.exact_areas && options.surface == SurfaceKind::sas;
  if (exact) result.exact = compute_areas(atoms, options.spheres).arrangement;
  if (options.exact_areas && options.surface == SurfaceKind::ses && attempt.ses_arrangement)
    result.ses_patches = measure_ses(atoms, options.spheres.probe, *attempt.ses_arrangement, options.outer_only);
  throw_if_cancelled(options.cancel);
  result.measures = measure_surface(attempt.mesh, attempt.check, atoms.size(), exact ? &result.exact : nullptr,
                                    &result.component_shells);
  result.seconds.measures = seconds_since(clock);
  pipeline.report(SurfaceStage::measures, 1, 1);

  result.mesh = std::move(attempt.mesh);
  result.method = attempt.method;
  result.check = std::move(attempt.check);
  result.cleanup = attempt.cleanup;
  result.true_points = attempt.true_points;
  result.ses_arrangement = std::move(attempt.ses_arrangement);
  if (requested.stern_probe) {
    ComputeSurfaceOptions stern = requested;
    stern.surface = SurfaceKind::sas;
    stern.spheres.probe = *requested.stern_probe;
    stern.stern_probe.reset();
    stern.true_points = false;
    stern.progress = nullptr;  // one progress display, the surface's
    result.stern = std::make_shared<const ComputedSurface>(compute_surface(atoms, stern));
  }
  result.quality_after = result.check.quality;
  result.quality_before = result.cleanup ? result.cleanup->before : result.quality_after;
  result.seconds.total = seconds_since(start);
  return result;
}

}  // namespace molsurf
