#include "blocks/blocked_surface.hpp"

#include <omp.h>

#include <chrono>
#include <string>
#include <utility>

#include "blocks/block_partition.hpp"
#include "blocks/block_piece.hpp"
#include "blocks/seam.hpp"
#include "common/thread_count_scope.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/error.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/parameters.hpp"
#include "molsurf/resource_limits.hpp"
#include "surface/cleanup.hpp"

namespace molsurf::blocks {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void refuse_unsupported(const ComputeSurfaceOptions& options) {
  if (options.surface == SurfaceKind::ses)
    throw Error("--blocks computes the solvent-accessible and van der Waals surfaces; the SES is not split into blocks");
  if (options.method != SurfaceMethod::one_pass)
    throw Error("--blocks runs the one-pass union (the default --method); the pairwise union is not split into blocks");
  if (options.outer_only) throw Error("--blocks keeps the cavities: drop --outer-only");
  if (options.true_points) throw Error("--blocks does not move vertices onto the true spheres: drop --true-points");
}

}  // namespace

std::vector<std::string> piece_problems(const MeshCheck& check, std::size_t seam_edges) {
  std::vector<std::string> problems;
  if (check.boundary_edges != seam_edges)
    problems.push_back(std::to_string(check.boundary_edges) + " boundary edges where the seam has " +
                       std::to_string(seam_edges));
  const std::pair<std::size_t, const char*> counts[] = {
      {check.nonmanifold_edges, "non-manifold edges"},   {check.misoriented_edges, "misoriented edges"},
      {check.degenerate_faces, "degenerate faces"},      {check.duplicate_faces, "duplicate faces"},
      {check.intersecting_pairs, "intersecting face pairs"}, {check.contact_pairs, "touching face pairs"},
      {check.non_finite_vertices, "non-finite vertices"}};
  for (const auto& [count, what] : counts)
    if (count > 0) problems.push_back(std::to_string(count) + " " + what);
  return problems;
}

BlockedSurface compute_blocked_surface(std::span<const Atom> atoms, const ComputeSurfaceOptions& requested,
                                       const BlockedSurfaceOptions& blocked) {
  const auto start = Clock::now();
  validate(requested);
  refuse_unsupported(requested);
  if (blocked.blocks == 0) throw Error("--blocks: at least 1 block");
  ComputeSurfaceOptions options = requested;
  if (options.surface == SurfaceKind::vdw) {
    options.surface = SurfaceKind::sas;
    options.spheres.probe = 0;
  }
  check_spheres(atoms, options.spheres);
  check_sphere_resolution(atoms, options.spheres);
  check_sphere_resources(options.source, atoms, options.spheres, options.max_sphere_faces);

  BlockedSurface out;
  ComputedSurface& result = out.surface;
  result.threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  const ThreadCountScope thread_count(result.threads);
  auto report = [&](SurfaceStage stage, std::size_t done, std::size_t total) {
    throw_if_cancelled(options.cancel);
    if (options.progress) options.progress(stage, done, total);
  };

  const BlockPartition partition = partition_blocks(atoms, options.spheres, blocked.blocks);
  std::vector<Mesh> pieces;
  std::vector<std::vector<SeamPoint>> seams;
  pieces.reserve(partition.size());
  seams.reserve(partition.size());
  Quality before;
  report(SurfaceStage::union_, 0, partition.size());
  for (std::size_t b = 0; b < partition.size(); ++b) {
    auto clock = Clock::now();
    BlockStats stats;
    stats.atoms = partition.atoms[b].size();
    stats.halo_atoms = partition.halo[b].size();
    BlockPiece piece = compute_block_piece(block_atoms(atoms, partition, b), options.spheres, result.threads);
    result.seconds.union_ += seconds_since(clock);
    clock = Clock::now();
    if (options.cleanup) {
      // The seam's vertices are shared with the neighbouring pieces: frozen, both sides
      // keep them where the union put them, and the pieces still glue exactly.
      const std::vector<std::uint8_t> frozen = seam_vertices(piece.mesh);
      CleanupOptions cleanup = options.cleanup_options;
      cleanup.measure_after = false;
      const CleanupStats cleaned = improve_surface(piece.mesh, cleanup, frozen);
      if (!result.cleanup) result.cleanup = CleanupStats{};
      result.cleanup->collapses += cleaned.collapses;
      result.cleanup->flips += cleaned.flips;
      result.cleanup->moves += cleaned.moves;
      result.cleanup->refused += cleaned.refused;
      result.cleanup->area_before += cleaned.area_before;
      result.cleanup->area_after += cleaned.area_after;
      result.cleanup->short_edges_before += cleaned.short_edges_before;
      result.cleanup->short_edges_after += cleaned.short_edges_after;
    }
    result.seconds.cleanup += seconds_since(clock);
    clock = Clock::now();
    stats.seam_edges = seam_edges(piece.mesh).size();
    MeshCheckOptions check_options;
    check_options.self_intersections = options.check_self_intersections;
    const MeshCheck check = check_mesh(piece.mesh, check_options);
    if (const auto problems = piece_problems(check, stats.seam_edges); !problems.empty()) {
      std::string text = "block " + std::to_string(b) + " of " + std::to_string(partition.size()) + ": its piece has";
      for (const std::string& p : problems) text += " " + p + ";";
      throw SurfaceCheckFailed(check, std::move(piece.mesh), {text});
    }
    result.seconds.check += seconds_since(clock);
    stats.faces = piece.mesh.faces.size();
    stats.seconds = seconds_since(clock);
    if (blocked.piece_done) blocked.piece_done(b, piece.mesh);
    pieces.push_back(std::move(piece.mesh));
    seams.push_back(std::move(piece.seam));
    out.blocks.push_back(stats);
    report(SurfaceStage::union_, b + 1, partition.size());
  }

  // The seams and every pair of faces from different pieces: the glued surface's check.
  auto clock = Clock::now();
  report(SurfaceStage::check, 0, 1);
  Mesh glued = glue_pieces(pieces, seams, exact_same_point(atoms, options.spheres, partition.contained));
  pieces = {};
  seams = {};
  MeshCheckOptions check_options;
  check_options.self_intersections = options.check_self_intersections;
  result.check = check_mesh(glued, check_options);
  result.seconds.check += seconds_since(clock);
  report(SurfaceStage::check, 1, 1);
  if (!result.check.valid())
    throw SurfaceCheckFailed(std::move(result.check), std::move(glued), {"the glued blocks failed their check"});

  clock = Clock::now();
  report(SurfaceStage::measures, 0, 1);
  const bool exact = options.exact_areas;
  if (exact) result.exact = compute_areas(atoms, options.spheres).arrangement;
  result.measures = measure_surface(glued, result.check, atoms.size(), exact ? &result.exact : nullptr,
                                    &result.component_shells);
  result.seconds.measures = seconds_since(clock);
  report(SurfaceStage::measures, 1, 1);
  if (result.cleanup) result.cleanup->after = result.check.quality;
  result.quality_after = result.check.quality;
  result.quality_before = result.cleanup ? result.cleanup->before : result.quality_after;
  result.mesh = std::move(glued);
  result.method = SurfaceMethod::one_pass;
  result.seconds.total = seconds_since(start);
  return out;
}

}  // namespace molsurf::blocks
