#include "blocks/blocked_ses.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <memory>
#include <utility>

#include "blocks/piece_job.hpp"
#include "blocks/seam.hpp"
#include "blocks/ses_piece.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/ses_measures.hpp"
#include "molsurf/surface_measures.hpp"
#include "ses/ses_specks.hpp"
#include "ses/ses_true_points.hpp"
#include "ses/solvent_excluded_surface.hpp"
#include "surface/cleanup.hpp"

namespace molsurf::blocks {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

using Position = std::array<double, 3>;

// The positions of the flagged vertices, sorted: the cleanup renumbers vertices but never
// moves a frozen one, so after it they are found again by where they are.
std::vector<Position> flagged_positions(const Mesh& mesh, std::span<const std::uint8_t> flag) {
  std::vector<Position> out;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (flag[v]) out.push_back({mesh.vertices[v].x, mesh.vertices[v].y, mesh.vertices[v].z});
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::uint8_t> at_positions(const Mesh& mesh, const std::vector<Position>& positions) {
  std::vector<std::uint8_t> out(mesh.vertices.size(), 0);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    out[v] = std::binary_search(positions.begin(), positions.end(),
                                Position{mesh.vertices[v].x, mesh.vertices[v].y, mesh.vertices[v].z});
  return out;
}

}  // namespace

bool finish_blocked_ses(std::span<const Atom> atoms, const ComputeSurfaceOptions& options, std::vector<Mesh> pieces,
                        double area_change, ComputedSurface& result, std::string& why) {
  auto clock = Clock::now();
  std::vector<std::uint8_t> glued_seam;
  Mesh mesh = glue_by_position(pieces, &glued_seam);
  pieces = {};
  if (const std::size_t open = seam_edges(mesh).size(); open > 0) {
    why = std::to_string(open) + " edges of the pieces' seams found no neighbouring piece";
    return false;
  }
  // The band the pieces left alone (kPieceSeamBand rings on each side) and two rings more:
  // cleaned and moved onto the true patches here, everything else frozen.
  const std::vector<std::uint8_t> frozen = frozen_beyond(mesh, glued_seam, kSeamCleanupBand);
  const std::vector<Position> frozen_at = flagged_positions(mesh, frozen);
  if (options.cleanup) {
    CleanupOptions cleanup = ses_detail::ses_cleanup_options(options.cleanup_options, options.spheres.density);
    cleanup.measure_after = false;
    // The budgets' share the band gets: what the pieces left of the area budget (each had
    // the share of the faces it could change, and spent it), since the band's short edges
    // are the uncleaned SES's, dense, and one process spends its budget by their count; and
    // at least the band's share by area, so that its slivers go where the pieces left little.
    const double band = changeable_area(mesh, frozen);
    const double area = surface_area(mesh), budget = cleanup.max_area_change * area;
    const double left =
        budget > 0 ? std::clamp(std::max((budget - std::abs(area_change)) / budget, band / area), 0.0, 1.0) : 1.0;
    cleanup.max_area_change *= left;
    cleanup.max_volume_change *= left;
    const CleanupStats seams = improve_surface(mesh, cleanup, frozen);
    add_cleanup(result, seams);
    area_change += seams.area_after - seams.area_before;
  }
  result.seconds.cleanup += seconds_since(clock);

  clock = Clock::now();
  auto arrangement = std::make_shared<const SphereArrangement>(compute_areas(atoms, options.spheres).arrangement);
  result.seconds.measures += seconds_since(clock);
  clock = Clock::now();
  add_true_points(result.true_points,
                  ses_detail::move_to_ses_points(mesh, atoms, options.spheres.probe, *arrangement,
                                                 ses_detail::ses_max_true_point_move(options.spheres.density),
                                                 at_positions(mesh, frozen_at)));
  if (const std::size_t specks = ses_detail::remove_specks(mesh, atoms, options.spheres.probe))
    result.notes.push_back(std::to_string(specks) +
                           " component(s) of the drawn SES too small to hold an atom or a probe removed (docs/ses.md)");
  result.seconds.cleanup += seconds_since(clock);

  clock = Clock::now();
  result.check = check_mesh(mesh, check_options_of(options));
  result.seconds.check += seconds_since(clock);
  if (!result.check.valid()) {
    why = "the glued surface failed its check";
    for (const std::string& defect : result.check.defects()) why += "; " + defect;
    return false;
  }

  clock = Clock::now();
  if (options.exact_areas) result.ses_patches = measure_ses(atoms, options.spheres.probe, *arrangement);
  result.measures = measure_surface(mesh, result.check, atoms.size());
  result.seconds.measures += seconds_since(clock);
  result.ses_arrangement = std::move(arrangement);
  if (result.cleanup) {
    result.cleanup->after = result.check.quality;
    // The cleanups' own change (the true points' moves after them are counted apart).
    result.cleanup->area_after = result.cleanup->area_before + area_change;
  }
  result.quality_after = result.check.quality;
  result.mesh = std::move(mesh);
  result.method = SurfaceMethod::one_pass;
  return true;
}

}  // namespace molsurf::blocks
