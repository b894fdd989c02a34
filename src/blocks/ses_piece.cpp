#include "blocks/ses_piece.hpp"

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "blocks/blocked_surface.hpp"
#include "blocks/piece_job.hpp"
#include "blocks/seam.hpp"
#include "mesh/topology.hpp"
#include "molsurf/error.hpp"
#include "molsurf/mesh_check.hpp"
#include "ses/ses_specks.hpp"
#include "ses/ses_true_points.hpp"
#include "ses/solvent_excluded_surface.hpp"
#include "surface/cleanup.hpp"

namespace molsurf::blocks {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The block's faces (tags turned into the whole structure's atom indices).
Mesh own_faces(const Mesh& ses, const BlockAtoms& block) {
  Mesh piece = faces_where(ses, [&](std::size_t f) { return block.in_block[static_cast<std::size_t>(ses.face_tags[f])] != 0; });
  for (std::int32_t& tag : piece.face_tags) tag = static_cast<std::int32_t>(block.global_index[static_cast<std::size_t>(tag)]);
  return piece;
}

}  // namespace

double ses_halo_reach(std::span<const Atom> atoms, const SphereOptions& spheres) {
  double largest = 0;
  for (const Atom& a : atoms) largest = std::max(largest, sphere_radius(a, spheres));
  return 4 * largest + 6 * spheres.probe;
}

std::vector<std::uint8_t> near_other_atoms(const Mesh& mesh, std::span<const std::uint8_t> own, int rings) {
  std::vector<std::uint8_t> other(mesh.vertices.size(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    if (!own[static_cast<std::size_t>(mesh.face_tags[f])])
      for (Index v : mesh.faces[f]) other[v] = 1;
  if (std::find(other.begin(), other.end(), std::uint8_t{1}) == other.end()) return {};
  std::vector<std::uint8_t> near = frozen_beyond(mesh, other, rings);
  for (std::uint8_t& n : near) n = n ? 0 : 1;
  return near;
}

double changeable_area(const Mesh& mesh, std::span<const std::uint8_t> frozen) {
  double area = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const Triangle& t = mesh.faces[f];
    if (!frozen[t[0]] || !frozen[t[1]] || !frozen[t[2]]) area += face_area(mesh, f);
  }
  return area;
}

Mesh ses_piece_before_cleanup(const BlockAtoms& block, const SphereOptions& spheres, int threads) {
  return own_faces(ses_detail::solvent_excluded_surface(block.atoms, spheres, threads).mesh, block);
}

PieceMessage make_ses_piece(const HeldBlocks& held, std::size_t b, const ComputeSurfaceOptions& options, int threads) {
  PieceMessage m = begun_piece(held, b);
  auto clock = Clock::now();
  const BlockAtoms block = held.block_atoms(b);
  ses_detail::ExcludedSurface ses = ses_detail::solvent_excluded_surface(block.atoms, options.spheres, threads);
  Mesh& mesh = ses.mesh;
  m.seconds_union = seconds_since(clock);
  clock = Clock::now();
  double own_area = 0;
  {
    const Mesh own = own_faces(mesh, block);
    m.before = mesh_quality(own);
    own_area = surface_area(own);
  }
  // The other atoms' faces are the neighbouring pieces' (drawn the same there) or beyond the
  // halo's reach (drawn differently): frozen, with a band of the block's own next to them,
  // so the seam's vertices stay where the drawing put them on both sides and no edit here
  // crosses a face the neighbour keeps; the seams' cleanup cleans the band.
  if (options.cleanup) {
    CleanupOptions cleanup = ses_detail::ses_cleanup_options(options.cleanup_options, options.spheres.density);
    cleanup.measure_after = false;
    // The budgets are shares of the whole, by area: the SES's cleanup spends all of its area
    // budget (one process's changes crambin's area by the 0.1 % it allows), so each piece
    // gets the share of the faces it may change, and the seams' cleanup the rest.
    const std::vector<std::uint8_t> frozen = near_other_atoms(mesh, block.in_block, kPieceSeamBand);
    const double area = surface_area(mesh);
    const double share = frozen.empty() || !(area > 0) ? 1.0 : std::min(1.0, changeable_area(mesh, frozen) / area);
    cleanup.max_area_change *= share;
    cleanup.max_volume_change *= share;
    m.cleanup = improve_surface(mesh, cleanup, frozen);
    // The counts of the piece's own faces: only they changed.
    m.cleanup.area_after = own_area + (m.cleanup.area_after - m.cleanup.area_before);
    m.cleanup.area_before = own_area;
  }
  m.true_points = ses_detail::move_to_ses_points(mesh, block.atoms, options.spheres.probe, ses.arrangement,
                                                 ses_detail::ses_max_true_point_move(options.spheres.density),
                                                 near_other_atoms(mesh, block.in_block, kPieceSeamBand));
  // A speck is a whole component, a few tenths of an angstrom across: both blocks whose
  // atoms it touches hold all of it, and both remove it.
  ses_detail::remove_specks(mesh, block.atoms, options.spheres.probe);
  Mesh piece = own_faces(mesh, block);
  mesh = {};
  m.seconds_cleanup = seconds_since(clock);
  check_piece(piece, options, held, b, m);
  m.mesh = std::move(piece);
  return m;
}

}  // namespace molsurf::blocks
