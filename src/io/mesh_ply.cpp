// PLY: vertices as double x y z (exact) with float normals nx ny nz, faces as
// "list uchar int vertex_indices" plus an "int tag" face property when the mesh has tags.
// Binary little-endian by default, ASCII on request (shortest round-trip text: exact).
// The reader takes any PLY a mesh tool writes: ASCII or binary of either byte order,
// any scalar types, extra properties and elements (skipped), polygons (triangulated as drawn, concave ones too).
#include <algorithm>
#include <bit>
#include <array>
#include <optional>

#include "io/atomic_file.hpp"
#include "io/mesh_formats.hpp"
#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

namespace {

// ---- writing ------------------------------------------------------------------------

template <class Unsigned>
void put_little_endian(std::string& out, Unsigned bits) {
  for (std::size_t byte = 0; byte < sizeof(Unsigned); ++byte)
    out += static_cast<char>((bits >> (8 * byte)) & 0xffu);
}

void put(std::string& out, double value) { put_little_endian(out, std::bit_cast<std::uint64_t>(value)); }
void put(std::string& out, float value) { put_little_endian(out, std::bit_cast<std::uint32_t>(value)); }
void put(std::string& out, std::int32_t value) { put_little_endian(out, static_cast<std::uint32_t>(value)); }

// ---- reading ------------------------------------------------------------------------

enum class Type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

std::optional<Type> type_from_name(std::string_view name) {
  if (name == "char" || name == "int8") return Type::int8;
  if (name == "uchar" || name == "uint8") return Type::uint8;
  if (name == "short" || name == "int16") return Type::int16;
  if (name == "ushort" || name == "uint16") return Type::uint16;
  if (name == "int" || name == "int32") return Type::int32;
  if (name == "uint" || name == "uint32") return Type::uint32;
  if (name == "float" || name == "float32") return Type::float32;
  if (name == "double" || name == "float64") return Type::float64;
  return std::nullopt;
}

std::size_t type_size(Type type) {
  switch (type) {
    case Type::int8: case Type::uint8: return 1;
    case Type::int16: case Type::uint16: return 2;
    case Type::int32: case Type::uint32: case Type::float32: return 4;
    case Type::float64: return 8;
  }
  return 0;
}

bool is_integer(Type type) { return type != Type::float32 && type != Type::float64; }

struct Property {
  std::string name;
  Type type = Type::float32;  // the item type for lists
  bool is_list = false;
  Type count_type = Type::uint8;
};

struct Element {
  std::string name;
  std::size_t count = 0;
  std::vector<Property> properties;
};

enum class Encoding { ascii, binary_little_endian, binary_big_endian };

struct Header {
  Encoding encoding = Encoding::ascii;
  std::vector<Element> elements;
  std::size_t body_offset = 0;   // first byte after "end_header\n"
  std::size_t body_line = 0;     // line number of the first body line (ASCII)
};

Header parse_header(const path& file, const std::string& bytes) {
  Header header;
  std::size_t position = 0;
  std::size_t line_number = 0;
  bool have_format = false;
  while (true) {
    const std::size_t end = bytes.find('\n', position);
    if (end == std::string::npos) fail(file, line_number + 1, "truncated header: no 'end_header'");
    std::string_view line = std::string_view(bytes).substr(position, end - position);
    position = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::vector<std::string_view> fields = split_fields(line);
    if (line_number == 1) {
      if (fields.size() != 1 || fields[0] != "ply") fail(file, 1, "not a PLY file (first line must be 'ply')");
      continue;
    }
    if (fields.empty() || fields[0] == "comment" || fields[0] == "obj_info") continue;
    if (fields[0] == "end_header") break;
    if (fields[0] == "format") {
      if (fields.size() < 2) fail(file, line_number, "format line needs an encoding");
      if (fields[1] == "ascii") header.encoding = Encoding::ascii;
      else if (fields[1] == "binary_little_endian") header.encoding = Encoding::binary_little_endian;
      else if (fields[1] == "binary_big_endian") header.encoding = Encoding::binary_big_endian;
      else fail(file, line_number, "unknown PLY format '" + std::string(fields[1].substr(0, 30)) + "'");
      have_format = true;
    } else if (fields[0] == "element") {
      if (fields.size() != 3) fail(file, line_number, "expected 'element NAME COUNT'");
      const long long count = parse_integer(fields[2], file, line_number, "element count");
      if (count < 0) fail(file, line_number, "negative element count");
      header.elements.push_back({std::string(fields[1]), static_cast<std::size_t>(count), {}});
    } else if (fields[0] == "property") {
      if (header.elements.empty()) fail(file, line_number, "property before any element");
      Property property;
      if (fields.size() == 5 && fields[1] == "list") {
        const auto count_type = type_from_name(fields[2]);
        const auto item_type = type_from_name(fields[3]);
        if (!count_type || !item_type || !is_integer(*count_type))
          fail(file, line_number, "bad list property types");
        property = {std::string(fields[4]), *item_type, true, *count_type};
      } else if (fields.size() == 3) {
        const auto type = type_from_name(fields[1]);
        if (!type) fail(file, line_number, "unknown property type '" + std::string(fields[1].substr(0, 30)) + "'");
        property = {std::string(fields[2]), *type, false, Type::uint8};
      } else {
        fail(file, line_number, "expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
      }
      header.elements.back().properties.push_back(std::move(property));
    } else {
      fail(file, line_number, "unexpected header line '" + std::string(fields[0].substr(0, 30)) + "'");
    }
  }
  if (!have_format) fail(file, line_number, "PLY header has no format line");
  header.body_offset = position;
  header.body_line = line_number + 1;
  return header;
}

std::string plural(const std::string& element) {
  if (element == "vertex") return "vertices";
  if (element == "face") return "faces";
  return "'" + element + "' elements";
}

// The body, read one scalar at a time whatever the encoding. read() returns false at
// the end of the data; a malformed ASCII value throws with its line.
class Body {
 public:
  Body(const path& file, const std::string& bytes, const Header& header)
      : file_(file), bytes_(bytes), encoding_(header.encoding), position_(header.body_offset),
        line_(header.body_line) {}

  bool read(Type type, double& value) {
    return encoding_ == Encoding::ascii ? read_text(type, value) : read_binary(type, value);
  }
  std::size_t line() const { return encoding_ == Encoding::ascii ? line_ : 0; }
  // Nothing but blanks (ASCII) or nothing at all (binary) left.
  bool at_end() {
    if (encoding_ == Encoding::ascii) skip_blanks();
    return position_ >= bytes_.size();
  }

 private:
  void skip_blanks() {
    while (position_ < bytes_.size()) {
      const char c = bytes_[position_];
      if (c == '\n') ++line_;
      if (c != ' ' && c != '\t' && c != '\r' && c != '\n') break;
      ++position_;
    }
  }

  bool read_text(Type type, double& value) {
    skip_blanks();
    if (position_ >= bytes_.size()) return false;
    const std::size_t end = bytes_.find_first_of(" \t\r\n", position_);
    const std::string_view token =
        std::string_view(bytes_).substr(position_, (end == std::string::npos ? bytes_.size() : end) - position_);
    position_ += token.size();
    value = is_integer(type) ? static_cast<double>(parse_integer(token, file_, line_, "integer property"))
                             : parse_double(token, file_, line_, "number property");
    return true;
  }

  bool read_binary(Type type, double& value) {
    const std::size_t size = type_size(type);
    if (bytes_.size() - position_ < size) return false;
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < size; ++i) {
      const std::size_t byte = encoding_ == Encoding::binary_little_endian ? i : size - 1 - i;
      bits |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes_[position_ + i])) << (8 * byte);
    }
    position_ += size;
    switch (type) {
      case Type::int8: value = static_cast<std::int8_t>(bits); break;
      case Type::uint8: value = static_cast<std::uint8_t>(bits); break;
      case Type::int16: value = static_cast<std::int16_t>(bits); break;
      case Type::uint16: value = static_cast<std::uint16_t>(bits); break;
      case Type::int32: value = static_cast<std::int32_t>(bits); break;
      case Type::uint32: value = static_cast<std::uint32_t>(bits); break;
      case Type::float32: value = std::bit_cast<float>(static_cast<std::uint32_t>(bits)); break;
      case Type::float64: value = std::bit_cast<double>(bits); break;
    }
    return true;
  }

  const path& file_;
  const std::string& bytes_;
  Encoding encoding_;
  std::size_t position_;
  std::size_t line_;
};

constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);

std::size_t find_property(const Element& element, std::initializer_list<std::string_view> names) {
  for (std::size_t i = 0; i < element.properties.size(); ++i)
    for (std::string_view name : names)
      if (element.properties[i].name == name) return i;
  return kAbsent;
}

}  // namespace

void write_ply(AtomicFileSet& files, const path& file, const Mesh& mesh, const MeshWriteOptions& options) {
  const std::vector<Vec3> normals = vertex_normals(mesh);
  std::string out = "ply\nformat ";
  out += options.ascii ? "ascii" : "binary_little_endian";
  out += " 1.0\ncomment molsurf " MOLSURF_VERSION "\n";
  out += "element vertex " + std::to_string(mesh.vertex_count()) + "\n";
  out += "property double x\nproperty double y\nproperty double z\n";
  out += "property float nx\nproperty float ny\nproperty float nz\n";
  out += "element face " + std::to_string(mesh.face_count()) + "\n";
  out += "property list uchar int vertex_indices\n";
  if (mesh.has_tags()) out += "property int tag\n";
  out += "end_header\n";
  out.reserve(out.size() + mesh.vertex_count() * (options.ascii ? 100 : 36) +
              mesh.face_count() * (options.ascii ? 30 : 17));
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const Vec3& p = mesh.vertices[v];
    const float n[3] = {static_cast<float>(normals[v].x), static_cast<float>(normals[v].y),
                        static_cast<float>(normals[v].z)};
    if (options.ascii) {
      for (double c : {p.x, p.y, p.z}) {
        append_number(out, c);
        out += ' ';
      }
      for (int i = 0; i < 3; ++i) {
        append_number(out, n[i]);
        out += i < 2 ? ' ' : '\n';
      }
    } else {
      for (double c : {p.x, p.y, p.z}) put(out, c);
      for (float c : n) put(out, c);
    }
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const Triangle& t = mesh.faces[f];
    if (options.ascii) {
      out += '3';
      for (Index v : t) out.append(1, ' ').append(std::to_string(v));
      if (mesh.has_tags()) out.append(1, ' ').append(std::to_string(mesh.face_tags[f]));
      out += '\n';
    } else {
      out += static_cast<char>(3);
      for (Index v : t) put(out, static_cast<std::int32_t>(v));
      if (mesh.has_tags()) put(out, mesh.face_tags[f]);
    }
  }
  files.add(file).write(out);
}

Mesh read_ply(const path& file) {
  const std::string bytes = read_file_bytes(file);
  const Header header = parse_header(file, bytes);
  Body body(file, bytes, header);
  Mesh mesh;
  bool have_vertices = false;
  std::vector<long long> polygon;
  for (const Element& element : header.elements) {
    const bool is_vertex = element.name == "vertex";
    const bool is_face = element.name == "face";
    std::array<std::size_t, 3> xyz{kAbsent, kAbsent, kAbsent};
    std::size_t indices = kAbsent, tag = kAbsent;
    if (is_vertex) {
      xyz = {find_property(element, {"x"}), find_property(element, {"y"}), find_property(element, {"z"})};
      for (const auto& axis : xyz)
        if (axis == kAbsent || element.properties[axis].is_list) fail(file, "vertex element needs scalar x, y and z");
      // Never trust a count from the file for an allocation larger than the file.
      mesh.vertices.reserve(std::min(element.count, bytes.size()));
      have_vertices = true;
    }
    if (is_face) {
      if (!have_vertices) fail(file, "face element before the vertex element");
      indices = find_property(element, {"vertex_indices", "vertex_index"});
      if (indices == kAbsent || !element.properties[indices].is_list)
        fail(file, "face element has no 'vertex_indices' list");
      tag = find_property(element, {"tag"});
      if (tag != kAbsent && element.properties[tag].is_list) tag = kAbsent;
      mesh.faces.reserve(std::min(element.count, bytes.size()));
    }
    // An element without properties has no bytes: its count (possibly huge) is moot.
    const std::size_t items = element.properties.empty() ? 0 : element.count;
    for (std::size_t item = 0; item < items; ++item) {
      Vec3 point;
      std::int32_t face_tag = kNoTag;
      polygon.clear();
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const Property& property = element.properties[p];
        const auto truncated = [&] {
          fail(file, body.line(), "truncated: expected " + std::to_string(element.count) + " " +
                                      plural(element.name) + ", file ends after " + std::to_string(item));
        };
        double value = 0;
        if (!property.is_list) {
          if (!body.read(property.type, value)) truncated();
          if (p == xyz[0]) point.x = value;
          else if (p == xyz[1]) point.y = value;
          else if (p == xyz[2]) point.z = value;
          else if (p == tag) {
            if (value < INT32_MIN || value > INT32_MAX || value != static_cast<std::int32_t>(value))
              fail(file, body.line(), "face " + std::to_string(item) + ": tag is not a 32-bit integer");
            face_tag = static_cast<std::int32_t>(value);
          }
          continue;
        }
        double count = 0;
        if (!body.read(property.count_type, count)) truncated();
        if (count < 0) fail(file, body.line(), "negative list length in " + element.name + " " + std::to_string(item));
        for (double i = 0; i < count; ++i) {
          if (!body.read(property.type, value)) truncated();
          if (p == indices) {
            if (value != static_cast<long long>(value))
              fail(file, body.line(), "face " + std::to_string(item) + ": vertex index is not an integer");
            polygon.push_back(static_cast<long long>(value));
          }
        }
      }
      if (is_vertex) mesh.vertices.push_back(point);
      if (is_face) {
        add_polygon(mesh, polygon, mesh.vertices.size(), file, body.line());
        if (tag != kAbsent) mesh.face_tags.resize(mesh.faces.size(), face_tag);  // every triangle of the polygon
      }
    }
  }
  // Data past the declared elements means a wrong count: refuse rather than drop it.
  if (!body.at_end()) fail(file, body.line(), "data after the declared elements (wrong counts in the header?)");
  return mesh;
}

}  // namespace molsurf::mesh_io
