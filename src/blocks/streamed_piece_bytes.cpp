// A streamed piece's kept part as bytes (streamed_piece.hpp), to travel from the process
// that made the piece to the one that joins the seams.
#include <stdexcept>

#include "blocks/piece_bytes.hpp"
#include "blocks/streamed_piece.hpp"

namespace molsurf::blocks {

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
  put_piece_numbers(out, p);
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
    get_piece_numbers(in, p);
    pieces.push_back(std::move(p));
  }
  return pieces;
}

}  // namespace molsurf::blocks
