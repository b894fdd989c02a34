#include "blocks/blocked_surface.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <string>
#include <utility>

#include "blocks/block_areas.hpp"
#include "blocks/block_partition.hpp"
#include "blocks/block_share.hpp"
#include "blocks/held_blocks.hpp"
#include "blocks/block_piece.hpp"
#include "blocks/piece_bytes.hpp"
#include "blocks/pieces_of_all_blocks.hpp"
#include "blocks/piece_job.hpp"
#include "blocks/seam.hpp"
#include "blocks/streamed_piece.hpp"
#include "blocks/streamed_surface.hpp"
#include "common/thread_count_scope.hpp"
#include "mesh/topology.hpp"
#include "molsurf/error.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/parameters.hpp"
#include "molsurf/resource_limits.hpp"
#include "surface/cleanup.hpp"
#include "blocks/blocked_ses.hpp"
#include "blocks/ses_piece.hpp"
#include "surface/surface_job_options.hpp"

namespace molsurf::blocks {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The faces of `mesh` whose atom lies in block `block`, on their own vertices.
Mesh faces_of_block(const Mesh& mesh, std::span<const std::uint32_t> block_of, std::size_t block) {
  return faces_where(mesh, [&](std::size_t f) { return block_of[static_cast<std::size_t>(mesh.face_tags[f])] == block; });
}

// The pieces as written: the checked surface's faces, block by block (a face's block is its
// atom's; the seams' cleanup kept every face's atom, and so does the SES's every step).
void hand_out_pieces(const Mesh& surface, const BlockPartition& partition, const BlockedSurfaceOptions& blocked,
                     std::vector<BlockStats>& stats) {
  for (std::size_t b = 0; b < partition.size(); ++b) {
    const Mesh piece = faces_of_block(surface, partition.block_of, b);
    stats[b].faces = piece.faces.size();
    if (blocked.piece_done) blocked.piece_done(b, piece);
  }
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
  const bool streamed = blocked.streamed && streams(requested);
  const BlockShare* share = blocked.share;
  if (share == nullptr && blocked.exchange != nullptr && blocked.exchange->size() > 1)
    throw std::logic_error("compute_blocked_surface: the processes of an exchange need their shares (share_blocks)");
  // The first process (or one alone) holds the whole structure: checked and cut into blocks
  // here, or by share_blocks already. The others hold only their share, checked there.
  std::optional<BlockJob> planned;
  ComputeSurfaceOptions options;
  const BlockPartition* whole_partition = nullptr;
  if (share == nullptr) {
    planned = plan_block_job(atoms, requested, blocked.blocks, blocked.streamed);
    options = planned->options;
    whole_partition = &planned->partition;
  } else {
    validate(requested);
    refuse_unsupported(requested);
    ComputeSurfaceOptions job = requested;
    if (streamed) job.max_sphere_faces = static_cast<std::uint64_t>(kMaxFacesParameter.high);
    if (share->partition) {
      options = surface_detail::surface_job_options(atoms, job);
      whole_partition = &*share->partition;
    } else {
      options = surface_detail::surface_job_options(share->atoms, job);
    }
  }
  const HeldBlocks held = whole_partition ? HeldBlocks(atoms, *whole_partition) : HeldBlocks(*share);

  BlockedSurface out;
  ComputedSurface& result = out.surface;
  result.threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  const ThreadCountScope thread_count(result.threads);
  auto report = [&](SurfaceStage stage, std::size_t done, std::size_t total) {
    throw_if_cancelled(options.cancel);
    if (options.progress) options.progress(stage, done, total);
  };

  if (streamed) {
    ComputeSurfaceOptions streamed_options = options;
    streamed_options.threads = result.threads;
    const Vec3 origin = whole_partition ? volume_origin(atoms) : share->origin;
    return compute_streamed_surface(whole_partition ? atoms : std::span<const Atom>{}, whole_partition, held, origin,
                                    streamed_options, blocked);
  }
  const bool ses = options.surface == SurfaceKind::ses;
  const std::size_t block_count = held.block_count();
  report(SurfaceStage::union_, 0, block_count);
  std::optional<std::vector<PieceMessage>> made = pieces_of_all_blocks<PieceMessage>(
      block_count, blocked.exchange,
      [&](std::size_t b) {
        if (ses) return make_ses_piece(held, b, options, result.threads);
        PieceMessage piece = make_piece(held, b, options, result.threads);
        if (options.exact_areas) {
          const auto clock = Clock::now();
          piece.exact = block_arrangement(held.block_atoms(b), options.spheres, result.threads);
          piece.seconds_exact = seconds_since(clock);
        }
        return piece;
      },
      append_piece,
      [](std::string_view bytes) { return read_pieces(bytes); },
      [&](std::size_t done) { report(SurfaceStage::union_, done, block_count); });
  if (!made) {
    out.root = false;
    return out;
  }
  if (whole_partition == nullptr)
    throw std::logic_error("compute_blocked_surface: the first process without the whole structure");
  const BlockPartition& partition = *whole_partition;
  std::vector<PieceMessage>& messages = *made;
  if (messages.size() != partition.size()) throw std::logic_error("compute_blocked_surface: a block without its piece");
  std::vector<Mesh> pieces;
  std::vector<std::vector<SeamPoint>> seams;
  std::vector<arrangement::ArrangementPart> parts;
  double seconds_exact = 0;
  pieces.reserve(partition.size());
  seams.reserve(partition.size());
  Quality before;
  double area_change = 0;  // by the SES pieces' cleanups
  for (PieceMessage& m : messages) {
    add_piece_totals(result, before, m, options.cleanup);
    if (ses) {
      add_true_points(result.true_points, m.true_points);
      area_change += m.cleanup.area_after - m.cleanup.area_before;
    }
    out.blocks.push_back(m.stats);
    pieces.push_back(std::move(m.mesh));
    seams.push_back(std::move(m.seam));
    parts.push_back(std::move(m.exact));
    seconds_exact += m.seconds_exact;
  }
  messages = {};
  if (ses) {
    report(SurfaceStage::check, 0, 1);
    std::string why;
    if (!finish_blocked_ses(atoms, options, std::move(pieces), area_change, result, why)) {
      // Never seen: a block whose SES took another path than the whole structure's (its
      // attempts or ridges decided on what lies beyond its halo). Valid or nothing.
      ComputeSurfaceOptions whole = options;
      whole.progress = nullptr;
      whole.threads = result.threads;
      std::vector<std::string> notes = std::move(result.notes);
      result = compute_surface(atoms, whole);
      notes.push_back("the SES's pieces did not join (" + why + "): drawn from the whole structure at once");
      result.notes.insert(result.notes.begin(), notes.begin(), notes.end());
    } else {
      if (result.cleanup) result.cleanup->before = before;
      result.quality_before = before;
    }
    report(SurfaceStage::check, 1, 1);
    hand_out_pieces(result.mesh, partition, blocked, out.blocks);
    result.seconds.total = seconds_since(start);
    return out;
  }

  // The seams and every pair of faces from different pieces: the glued surface's check.
  auto clock = Clock::now();
  report(SurfaceStage::check, 0, 1);
  std::vector<std::uint8_t> glued_seam;
  Mesh glued =
      glue_pieces(pieces, seams, exact_same_point(atoms, options.spheres, partition.contained), &glued_seam);
  pieces = {};
  seams = {};
  if (options.cleanup) {
    // The seams' own cleanup: their slivers, which no piece could touch, with the faces of
    // both sides in view; everything but a band two rings wider than the pieces left frozen.
    clock = Clock::now();
    const std::vector<std::uint8_t> frozen = frozen_beyond(glued, glued_seam, kSeamCleanupBand);
    CleanupOptions cleanup = options.cleanup_options;
    cleanup.measure_after = false;
    add_cleanup(result, improve_surface(glued, cleanup, frozen));
    result.seconds.cleanup += seconds_since(clock);
    clock = Clock::now();
  }
  result.check = check_mesh(glued, check_options_of(options));
  result.seconds.check += seconds_since(clock);
  report(SurfaceStage::check, 1, 1);
  if (!result.check.valid())
    throw SurfaceCheckFailed(std::move(result.check), std::move(glued), {"the glued blocks failed their check"});

  clock = Clock::now();
  report(SurfaceStage::measures, 0, 1);
  const bool exact = options.exact_areas;
  if (exact) result.exact = joined_block_areas(atoms, options.spheres, parts);
  parts = {};
  result.measures = measure_surface(glued, result.check, atoms.size(), exact ? &result.exact : nullptr,
                                    &result.component_shells);
  result.seconds.measures = seconds_since(clock) + seconds_exact;
  report(SurfaceStage::measures, 1, 1);
  if (result.cleanup) {
    result.cleanup->after = result.check.quality;
    result.cleanup->area_after = result.check.area;
  }
  result.quality_after = result.check.quality;
  if (result.cleanup) result.cleanup->before = before;
  result.quality_before = before;
  hand_out_pieces(glued, partition, blocked, out.blocks);
  result.mesh = std::move(glued);
  result.method = SurfaceMethod::one_pass;
  result.seconds.total = seconds_since(start);
  return out;
}

}  // namespace molsurf::blocks
