#pragma once
// A block's piece split for the streamed job (streamed_surface.hpp): the faces the seams'
// cleanup cannot change are written at once, and only what the join needs is kept: the seam
// band (every face within kBandRings rings of the seam: the seams' cleanup changes only
// faces with a vertex within kSeamCleanupBand rings, and a flip of an edge of such a face
// reaches one ring further), the written faces that a face of another block or of the band
// could come near (the border, for the check), and the written faces' summary (area, volume,
// per-atom areas, quality, and the connected parts with the vertices by which they join
// the band).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "blocks/piece_bytes.hpp"
#include "blocks/held_blocks.hpp"
#include "blocks/piece_job.hpp"
#include "blocks/seam.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"

namespace molsurf::blocks {

inline constexpr int kBandRings = kSeamCleanupBand + 1;

// How far a face's vertex may lie outside its atom's sphere (angstrom) for the border to
// hold every face that another block's face can reach. Every face is measured against it.
// The polyhedra's area correction moves faces by hundredths of an angstrom, but a face the
// cleanup flips or collapses across a seam keeps its atom and reaches into its neighbour's
// sphere by up to an edge (a capsid face lay 0.565 A out at density 2): half an angstrom
// and one and a half times the edge length the density asks for (1.1 / sqrt(density) A).
double border_reach(const SphereOptions& spheres);

// The box of an atom's sphere (radius + probe), grown by `reach` on every side.
BoundingBox sphere_box(const Atom& atom, const SphereOptions& spheres, double reach);

struct AtomArea {
  std::uint32_t atom = 0;
  double area = 0;
};

// One connected part of a piece's written faces.
struct WrittenPart {
  std::uint64_t faces = 0;
  double area = 0, volume = 0;       // volume: by the divergence theorem about the job's origin
  std::vector<std::uint32_t> atoms;  // of its faces, increasing, once each
  std::vector<Vec3> joints;          // its vertices that band faces share (exact coordinates)
};

// What a piece leaves for the join once its written faces are on disk.
struct StreamedPiece {
  std::size_t block = 0;
  Mesh band;                    // the seam band, on its own vertices; tags: atoms
  std::vector<SeamPoint> seam;  // the seam's points, for the glue
  Mesh border;                  // written faces near other blocks' or the band's atoms
  // Directed edges of band and border faces whose reverse is a written face outside the
  // border: where the check of band and border together finds its only boundary.
  std::uint64_t border_open_edges = 0;
  // The written faces: counts (vertices: those no band face has), area, volume about the
  // origin, quality, how far a face's vertex lies outside its atom's sphere, per-atom areas.
  std::uint64_t faces = 0, vertices = 0;
  double area = 0, volume = 0, stray = 0;
  Quality quality;
  std::vector<AtomArea> atom_area;
  std::vector<WrittenPart> parts;
  // The piece's own job, and its block's exact areas (with exact_areas; empty otherwise).
  BlockStats stats;
  Quality before;
  CleanupStats cleanup;
  double seconds_union = 0, seconds_cleanup = 0, seconds_check = 0;
  arrangement::ArrangementPart exact;
  double seconds_exact = 0;
};

struct SplitPiece {
  Mesh written;  // to its file now
  StreamedPiece kept;
};

// `piece` (checked but for its seam) split as above. `held`: the atoms this process holds
// (the whole structure, or its share: the border is cut against the held atoms, which hold
// every atom whose grown ball a face that check_seams accepts can meet); `origin`: the point
// every piece's volume is taken about (volume_origin).
SplitPiece split_piece(PieceMessage&& piece, const HeldAtoms& held, const SphereOptions& spheres, const Vec3& origin);

// The point every piece's volume is taken about: the atoms' box centre, the same on every
// process (small coordinates about it lose little to cancellation).
Vec3 volume_origin(std::span<const Atom> atoms);

// The kept part as bytes (streamed_piece_bytes.cpp), appended to `out`; and the pieces
// `bytes` holds (std::invalid_argument for bytes append_streamed_piece did not write).
void append_streamed_piece(std::string& out, const StreamedPiece& piece);
std::vector<StreamedPiece> read_streamed_pieces(std::string_view bytes);

// Six times the signed volume of the tetrahedron from `origin` to face f.
double six_volume_about(const Mesh& mesh, std::size_t face, const Vec3& origin);
// How far face f's farthest vertex lies outside its atom's sphere (0 inside; infinite when its
// atom is not held).
double stray_of(const Mesh& mesh, std::size_t face, const HeldAtoms& held, const SphereOptions& spheres);

}  // namespace molsurf::blocks
