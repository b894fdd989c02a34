#include "blocks/piece_bytes.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace molsurf::blocks {

namespace {

template <class T>
void put(std::string& out, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <class T>
void put_array(std::string& out, const std::vector<T>& values) {
  static_assert(std::is_trivially_copyable_v<T>);
  put(out, static_cast<std::uint64_t>(values.size()));
  if (!values.empty()) out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  bool done() const { return at_ == bytes_.size(); }

  template <class T>
  T get() {
    T value;
    take(&value, sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> get_array() {
    const auto n = get<std::uint64_t>();
    if (n > (bytes_.size() - at_) / sizeof(T)) throw std::invalid_argument("read_pieces: truncated bytes");
    std::vector<T> values(n);
    if (n > 0) take(values.data(), n * sizeof(T));
    return values;
  }

 private:
  void take(void* to, std::size_t n) {
    if (n > bytes_.size() - at_) throw std::invalid_argument("read_pieces: truncated bytes");
    std::memcpy(to, bytes_.data() + at_, n);
    at_ += n;
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
};

}  // namespace

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
  Reader in(bytes);
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
