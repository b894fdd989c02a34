#include "blocks/piece_job.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "blocks/block_piece.hpp"
#include "blocks/ses_piece.hpp"
#include "common/thread_count_scope.hpp"
#include "molsurf/parameters.hpp"
#include "molsurf/resource_limits.hpp"
#include "surface/surface_job_options.hpp"
#include "blocks/blocked_surface.hpp"
#include "blocks/seam.hpp"
#include "molsurf/error.hpp"
#include "molsurf/mesh_check.hpp"
#include "surface/cleanup.hpp"

namespace molsurf::blocks {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

BlockJob plan_block_job(std::span<const Atom> atoms, const ComputeSurfaceOptions& requested, std::size_t blocks,
                        bool streamed) {
  validate(requested);
  refuse_unsupported(requested);
  streamed = streamed && streams(requested);
  if (blocks == 0) throw Error("--blocks: at least 1 block");
  check(kBlocksParameter, static_cast<long long>(std::min<std::size_t>(blocks, 1ull << 62)));
  // Blocks beyond the atoms would be empty pieces, each a file and a pass of its own.
  if (blocks > atoms.size())
    throw Error("--blocks: " + std::to_string(blocks) + " blocks for " + std::to_string(atoms.size()) +
                (atoms.size() == 1 ? " atom" : " atoms") +
                "; at most one block per atom (under mpirun the blocks default to the process count)");
  ComputeSurfaceOptions job = requested;
  if (streamed) job.max_sphere_faces = static_cast<std::uint64_t>(kMaxFacesParameter.high);
  BlockJob out{surface_detail::surface_job_options(atoms, job), {}};
  const ThreadCountScope thread_count(out.options.threads > 0 ? out.options.threads : omp_get_max_threads());
  // The SES's pieces are drawn from their blocks' atoms and a halo as wide as the SES's
  // faces depend on (ses_piece.hpp).
  const double halo_reach =
      out.options.surface == SurfaceKind::ses ? ses_halo_reach(atoms, out.options.spheres) : 0.0;
  out.partition = partition_blocks(atoms, out.options.spheres, blocks, halo_reach);
  if (streamed)
    for (std::size_t b = 0; b < out.partition.size(); ++b)
      check_sphere_resources(out.options.source.string() + " (block " + std::to_string(b + 1) + " of " +
                                 std::to_string(out.partition.size()) + " with its halo)",
                             block_atoms(atoms, out.partition, b).atoms, out.options.spheres,
                             requested.max_sphere_faces);
  return out;
}

bool streams(const ComputeSurfaceOptions& options) { return options.surface != SurfaceKind::ses; }

void refuse_unsupported(const ComputeSurfaceOptions& options) {
  if (options.method != SurfaceMethod::one_pass)
    throw Error("--blocks runs the one-pass union (the default --method); the pairwise union is not split into blocks");
  if (options.outer_only) throw Error("--blocks keeps the cavities: drop --outer-only");
  if (options.true_points) throw Error("--blocks does not move vertices onto the true spheres: drop --true-points");
  if (options.stern_probe)
    throw Error("--blocks makes one surface: drop --stern (the Stern layer is the SAS at --probe R, in a run of its own)");
}

void add_cleanup(ComputedSurface& result, const CleanupStats& cleaned) {
  if (!result.cleanup) result.cleanup = CleanupStats{};
  result.cleanup->collapses += cleaned.collapses;
  result.cleanup->flips += cleaned.flips;
  result.cleanup->moves += cleaned.moves;
  result.cleanup->refused += cleaned.refused;
  result.cleanup->short_edges_before += cleaned.short_edges_before;
  result.cleanup->short_edges_after += cleaned.short_edges_after;
}

void add_true_points(std::optional<TruePointStats>& total, const TruePointStats& part) {
  if (!total) total = TruePointStats{};
  total->vertices += part.vertices;
  total->on_true_point += part.on_true_point;
  total->partly += part.partly;
  total->not_moved += part.not_moved;
  total->max_distance_left = std::max(total->max_distance_left, part.max_distance_left);
  total->seconds += part.seconds;
}

void combine_quality(Quality& total, const Quality& part) {
  if (part.faces == 0) return;
  if (total.faces == 0) {
    total = part;
    return;
  }
  const double n = static_cast<double>(total.faces), m = static_cast<double>(part.faces);
  total.mean_min_angle_deg = (total.mean_min_angle_deg * n + part.mean_min_angle_deg * m) / (n + m);
  total.min_angle_deg = std::min(total.min_angle_deg, part.min_angle_deg);
  total.max_aspect_ratio = std::max(total.max_aspect_ratio, part.max_aspect_ratio);
  total.below_1deg += part.below_1deg;
  total.below_5deg += part.below_5deg;
  total.faces += part.faces;
}

MeshCheckOptions check_options_of(const ComputeSurfaceOptions& options) {
  MeshCheckOptions check;
  check.self_intersections = options.check_self_intersections;
  return check;
}

PieceMessage begun_piece(const HeldBlocks& held, std::size_t b) {
  PieceMessage m;
  m.block = b;
  m.stats.atoms = held.block_size(b);
  m.stats.halo_atoms = held.halo_size(b);
  return m;
}

void check_piece(const Mesh& piece, const ComputeSurfaceOptions& options, const HeldBlocks& held, std::size_t b,
                 PieceMessage& m) {
  const auto clock = Clock::now();
  m.stats.seam_edges = seam_edges(piece).size();
  const MeshCheck check = check_mesh(piece, check_options_of(options));
  if (const auto problems = piece_problems(check, m.stats.seam_edges); !problems.empty()) {
    std::string text = "block " + std::to_string(b) + " of " + std::to_string(held.block_count()) + ": its piece has";
    for (const std::string& p : problems) text += " " + p + ";";
    throw SurfaceCheckFailed(check, piece, {text});
  }
  m.seconds_check = seconds_since(clock);
  m.stats.seconds = m.seconds_union + m.seconds_cleanup + m.seconds_check;
}

PieceMessage make_piece(const HeldBlocks& held, std::size_t b, const ComputeSurfaceOptions& options, int threads) {
  PieceMessage m = begun_piece(held, b);
  auto clock = Clock::now();
  BlockPiece piece = compute_block_piece(held.block_atoms(b), options.spheres, threads);
  m.seconds_union = seconds_since(clock);
  clock = Clock::now();
  m.before = mesh_quality(piece.mesh);
  if (options.cleanup) {
    // The seam's vertices are shared with the neighbouring pieces: frozen, both sides
    // keep them where the union put them, and the pieces still glue exactly. So are the
    // vertices near them: an edit there could cross a neighbouring piece's face, which this
    // piece cannot see (the capsid 1f2n in 4 blocks, with the seam alone frozen: 14 crossing
    // pairs); the seams' cleanup, which sees both sides, cleans that band.
    std::vector<std::uint8_t> frozen = frozen_beyond(piece.mesh, seam_vertices(piece.mesh), kPieceSeamBand);
    for (std::uint8_t& f : frozen) f = f ? 0 : 1;
    CleanupOptions cleanup = options.cleanup_options;
    cleanup.measure_after = false;
    m.cleanup = improve_surface(piece.mesh, cleanup, frozen);
  }
  m.seconds_cleanup = seconds_since(clock);
  check_piece(piece.mesh, options, held, b, m);
  m.mesh = std::move(piece.mesh);
  m.seam = std::move(piece.seam);
  return m;
}

}  // namespace molsurf::blocks
