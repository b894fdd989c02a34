#include "blocks/piece_bytes.hpp"

#include <cstdint>
#include <stdexcept>

#include "blocks/byte_stream.hpp"

namespace molsurf::blocks {

void put_mesh(std::string& out, const Mesh& mesh) {
  put_array(out, mesh.vertices);
  put_array(out, mesh.faces);
  put_array(out, mesh.face_tags);
}

Mesh get_mesh(ByteReader& in) {
  Mesh mesh;
  mesh.vertices = in.get_array<Vec3>();
  mesh.faces = in.get_array<Triangle>();
  mesh.face_tags = in.get_array<std::int32_t>();
  if (mesh.face_tags.size() != mesh.faces.size()) throw std::invalid_argument("piece bytes: one tag per face");
  for (const Triangle& t : mesh.faces)
    for (Index v : t)
      if (v >= mesh.vertices.size()) throw std::invalid_argument("piece bytes: a face with no such vertex");
  return mesh;
}

void append_piece(std::string& out, const PieceMessage& piece) {
  put(out, static_cast<std::uint64_t>(piece.block));
  put_mesh(out, piece.mesh);
  put_array(out, piece.seam);
  put_piece_numbers(out, piece);
  put(out, piece.true_points);
}

std::vector<PieceMessage> read_pieces(std::string_view bytes) {
  ByteReader in(bytes);
  std::vector<PieceMessage> pieces;
  while (!in.done()) {
    PieceMessage p;
    p.block = static_cast<std::size_t>(in.get<std::uint64_t>());
    p.mesh = get_mesh(in);
    p.seam = in.get_array<SeamPoint>();
    get_piece_numbers(in, p);
    p.true_points = in.get<TruePointStats>();
    pieces.push_back(std::move(p));
  }
  return pieces;
}

}  // namespace molsurf::blocks
