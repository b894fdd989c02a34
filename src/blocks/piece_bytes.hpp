#pragma once
// A block's piece as bytes, to travel from the process that computed it to the one that
// glues the pieces (block_exchange.hpp): its mesh (vertices, faces, atom tags) and its seam
// points, every number as its exact bytes (the glue compares coordinates exactly).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "arrangement/arrangement_part.hpp"
#include "blocks/block_areas.hpp"
#include "blocks/byte_stream.hpp"
#include "blocks/seam.hpp"
#include "molsurf/cleanup.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/true_points.hpp"

namespace molsurf::blocks {

// A piece's numbers as the report sums them.
struct BlockStats {
  std::size_t atoms = 0, halo_atoms = 0, faces = 0, seam_edges = 0;
  double seconds = 0;  // union, cleanup and check of the piece
};

struct PieceMessage {
  std::size_t block = 0;
  Mesh mesh;
  std::vector<SeamPoint> seam;
  BlockStats stats;
  Quality before;         // of the piece before its cleanup
  CleanupStats cleanup;   // its cleanup's counts
  double seconds_union = 0, seconds_cleanup = 0, seconds_check = 0;
  arrangement::ArrangementPart exact;  // the block's exact areas (block_areas.hpp; empty without)
  double seconds_exact = 0;
  TruePointStats true_points;  // the SES's piece: its vertices moved onto the true patches
};

// A mesh's vertices, faces and atom tags; get_mesh throws std::invalid_argument for a face
// with no such vertex or a tag count that is not the face count.
void put_mesh(std::string& out, const Mesh& mesh);
Mesh get_mesh(ByteReader& in);

// What every piece carries after its meshes, glued or streamed: its counts, its quality
// before cleanup, its cleanup's counts, its times and its block's exact areas.
template <class Piece>
void put_piece_numbers(std::string& out, const Piece& p) {
  put(out, p.stats);
  put(out, p.before);
  put(out, p.cleanup);
  put(out, p.seconds_union);
  put(out, p.seconds_cleanup);
  put(out, p.seconds_check);
  put_arrangement_part(out, p.exact);
  put(out, p.seconds_exact);
}
template <class Piece>
void get_piece_numbers(ByteReader& in, Piece& p) {
  p.stats = in.get<BlockStats>();
  p.before = in.get<Quality>();
  p.cleanup = in.get<CleanupStats>();
  p.seconds_union = in.get<double>();
  p.seconds_cleanup = in.get<double>();
  p.seconds_check = in.get<double>();
  p.exact = get_arrangement_part(in);
  p.seconds_exact = in.get<double>();
}

// Appends `piece` to `out`.
void append_piece(std::string& out, const PieceMessage& piece);
// The pieces `bytes` holds, one after another; std::invalid_argument for bytes that
// append_piece did not write.
std::vector<PieceMessage> read_pieces(std::string_view bytes);

}  // namespace molsurf::blocks
