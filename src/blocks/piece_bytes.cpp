#include "blocks/piece_bytes.hpp"

#include <cstdint>
#include <stdexcept>

#include "blocks/byte_stream.hpp"

namespace molsurf::blocks {

void append_piece(std::string& out, const PieceMessage& piece) {
  put(out, static_cast<std::uint64_t>(piece.block));
  put_array(out, piece.mesh.vertices);
  put_array(out, piece.mesh.faces);
  put_array(out, piece.mesh.face_tags);
  put_array(out, piece.seam);
  put(out, piece.stats);
  put(out, piece.before);
  put(out, piece.cleanup);
  put(out, piece.seconds_union);
  put(out, piece.seconds_cleanup);
  put(out, piece.seconds_check);
}

std::vector<PieceMessage> read_pieces(std::string_view bytes) {
  ByteReader in(bytes);
  std::vector<PieceMessage> pieces;
  while (!in.done()) {
    PieceMessage p;
    p.block = static_cast<std::size_t>(in.get<std::uint64_t>());
    p.mesh.vertices = in.get_array<Vec3>();
    p.mesh.faces = in.get_array<Triangle>();
    p.mesh.face_tags = in.get_array<std::int32_t>();
    p.seam = in.get_array<SeamPoint>();
    p.stats = in.get<BlockStats>();
    p.before = in.get<Quality>();
    p.cleanup = in.get<CleanupStats>();
    p.seconds_union = in.get<double>();
    p.seconds_cleanup = in.get<double>();
    p.seconds_check = in.get<double>();
    for (const Triangle& t : p.mesh.faces)
      for (Index v : t)
        if (v >= p.mesh.vertices.size()) throw std::invalid_argument("read_pieces: a face with no such vertex");
    pieces.push_back(std::move(p));
  }
  return pieces;
}

}  // namespace molsurf::blocks
