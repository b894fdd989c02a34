// A streamed piece's kept part as bytes (streamed_piece.hpp), to travel from the process
// that made the piece to the one that joins the seams.
#include <stdexcept>

#include "blocks/byte_stream.hpp"
#include "blocks/streamed_piece.hpp"

namespace molsurf::blocks {

namespace {

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

}  // namespace

void append_streamed_piece(std::string& out, const StreamedPiece& p) {
  put(out, static_cast<std::uint64_t>(p.block));
  put_mesh(out, p.band);
  put_array(out, p.seam);
  put_mesh(out, p.border);
  put(out, p.border_open_edges);
  put(out, p.faces);
  put(out, p.vertices);
  put(out, p.area);
  put(out, p.volume);
  put(out, p.stray);
  put(out, p.quality);
  put_array(out, p.atom_area);
  put(out, static_cast<std::uint64_t>(p.parts.size()));
  for (const WrittenPart& part : p.parts) {
    put(out, part.faces);
    put(out, part.area);
    put(out, part.volume);
    put_array(out, part.atoms);
    put_array(out, part.joints);
  }
  put(out, p.stats);
  put(out, p.before);
  put(out, p.cleanup);
  put(out, p.seconds_union);
  put(out, p.seconds_cleanup);
  put(out, p.seconds_check);
}

std::vector<StreamedPiece> read_streamed_pieces(std::string_view bytes) {
  ByteReader in(bytes);
  std::vector<StreamedPiece> pieces;
  while (!in.done()) {
    StreamedPiece p;
    p.block = static_cast<std::size_t>(in.get<std::uint64_t>());
    p.band = get_mesh(in);
    p.seam = in.get_array<SeamPoint>();
    p.border = get_mesh(in);
    p.border_open_edges = in.get<std::uint64_t>();
    p.faces = in.get<std::uint64_t>();
    p.vertices = in.get<std::uint64_t>();
    p.area = in.get<double>();
    p.volume = in.get<double>();
    p.stray = in.get<double>();
    p.quality = in.get<Quality>();
    p.atom_area = in.get_array<AtomArea>();
    const auto parts = in.get<std::uint64_t>();
    for (std::uint64_t k = 0; k < parts; ++k) {
      WrittenPart part;
      part.faces = in.get<std::uint64_t>();
      part.area = in.get<double>();
      part.volume = in.get<double>();
      part.atoms = in.get_array<std::uint32_t>();
      part.joints = in.get_array<Vec3>();
      p.parts.push_back(std::move(part));
    }
    p.stats = in.get<BlockStats>();
    p.before = in.get<Quality>();
    p.cleanup = in.get<CleanupStats>();
    p.seconds_union = in.get<double>();
    p.seconds_cleanup = in.get<double>();
    p.seconds_check = in.get<double>();
    pieces.push_back(std::move(p));
  }
  return pieces;
}

}  // namespace molsurf::blocks
