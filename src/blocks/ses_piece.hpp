#pragma once
// One block's piece of the solvent-excluded surface. The SES of a set of atoms is drawn
// from its SAS union and arrangement (ses/solvent_excluded_surface.hpp), and every face of
// it depends only on the atoms near it: drawn from the block's atoms and a halo of every atom
// within ses_halo_reach of them, in the whole structure's order, the faces of the block's
// atoms are the whole structure's SES faces, face for face, before cleanup. So a block
// draws the SES of its atoms and halo, cleans it and moves its vertices onto the true
// patches with everything but its own atoms' faces frozen, and with them a band around
// where they meet the others' (the seam); its piece is its own atoms' faces. Neighbouring
// pieces then share their seam's vertices to the bit and are glued by position
// (glue_by_position); the seams' band is cleaned where both sides are in view.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "blocks/block_partition.hpp"
#include "blocks/held_blocks.hpp"
#include "blocks/piece_bytes.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"

namespace molsurf::blocks {

// How far beyond a block's atoms its SES halo reaches: 4 R + 6 probe, R the largest sphere
// (r + probe). A face of atom a lies within R + probe of a's centre; it is cut where the
// probe balls carve a ridge, ridges grow from faults up to 1.8 probe radii away (the three
// widening rounds), faults pair faces drawn for SAS vertices within 2 probe radii of each
// other, and every SAS vertex used must be the whole union's: its atoms and all their
// neighbours (2 R) held.
double ses_halo_reach(std::span<const Atom> atoms, const SphereOptions& spheres);

// The SES of the block's atoms and halo before cleanup (face tags: atom indices in the
// whole structure), cut to the block's own atoms' faces: the whole structure's SES faces
// of those atoms, on the same exact coordinates.
Mesh ses_piece_before_cleanup(const BlockAtoms& block, const SphereOptions& spheres, int threads);

// Block b's piece of the SES: drawn from the block's atoms and halo, cleaned (the SES's
// cleanup rules) and moved onto its true patches with the other atoms' faces and a band of
// kPieceSeamBand rings around them frozen, specks removed, cut to the block's atoms' faces
// (tags: atom indices in the whole structure), checked but for its seam
// (SurfaceCheckFailed otherwise).
PieceMessage make_ses_piece(const HeldBlocks& held, std::size_t b, const ComputeSurfaceOptions& options, int threads);

// The area of the faces with a vertex `frozen` does not flag: what a cleanup may change.
double changeable_area(const Mesh& mesh, std::span<const std::uint8_t> frozen);

// Per vertex: 1 for the vertices of faces whose atom `own` does not flag (face tags index
// `own`), and for those within `rings` edges of them; empty when every face's atom is flagged
// (one block: nothing frozen, and the cleanup runs as without blocks).
std::vector<std::uint8_t> near_other_atoms(const Mesh& mesh, std::span<const std::uint8_t> own, int rings);

}  // namespace molsurf::blocks
