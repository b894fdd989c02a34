// Legacy VTK (.vtk) reader of our own, ASCII and BINARY: DATASET POLYDATA (polygons and
// triangle strips; vertices and lines skipped) and DATASET UNSTRUCTURED_GRID (triangles,
// quads, polygons, strips; points and lines skipped), both cell layouts (4.x "n size" runs
// and 5.x OFFSETS/CONNECTIVITY). VTK 9.1's own legacy reader trusts the sizes a file
// declares: "POINTS -12" crashes it and "POINTS 2000000000" in a 1 KB file makes it
// allocate without bound. Here every count is only a promise: values are read one at a
// time from what the file holds, binary blocks are checked against the bytes left before
// anything is reserved, and nothing is allocated beyond what the file could fill.
// Attributes are walked with the same checks and skipped, except the cell array "tag"
// (FIELD array or SCALARS), which becomes the face tags.
#include <algorithm>
#include <bit>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/mesh_formats.hpp"
#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

namespace {

enum class ValueType { u8, i8, u16, i16, u32, i32, u64, i64, f32, f64, bit, string };

std::optional<ValueType> value_type(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  if (name == "unsigned_char") return ValueType::u8;
  if (name == "char" || name == "signed_char") return ValueType::i8;
  if (name == "unsigned_short") return ValueType::u16;
  if (name == "short") return ValueType::i16;
  if (name == "unsigned_int") return ValueType::u32;
  if (name == "int") return ValueType::i32;
  // VTK writes C++'s long and vtkIdType in their 64-bit forms on every platform we target.
  if (name == "unsigned_long" || name == "vtktypeuint64" || name == "unsigned_long_long") return ValueType::u64;
  if (name == "long" || name == "vtktypeint64" || name == "vtkidtype" || name == "long_long") return ValueType::i64;
  if (name == "vtktypeuint32") return ValueType::u32;
  if (name == "vtktypeint32") return ValueType::i32;
  if (name == "float") return ValueType::f32;
  if (name == "double") return ValueType::f64;
  if (name == "bit") return ValueType::bit;
  if (name == "string" || name == "utf8_string") return ValueType::string;
  return std::nullopt;
}

std::size_t binary_size(ValueType type) {
  switch (type) {
    case ValueType::u8: case ValueType::i8: return 1;
    case ValueType::u16: case ValueType::i16: return 2;
    case ValueType::u32: case ValueType::i32: case ValueType::f32: return 4;
    case ValueType::u64: case ValueType::i64: case ValueType::f64: return 8;
    case ValueType::bit: case ValueType::string: return 0;
  }
  return 0;
}

bool is_integer(ValueType type) { return type != ValueType::f32 && type != ValueType::f64; }

// The file as words (headers, ASCII values) and raw big-endian blocks (BINARY values).
class LegacyFile {
 public:
  LegacyFile(const path& file, std::string bytes) : file_(file), bytes_(std::move(bytes)) {}

  [[noreturn]] void fail_here(const std::string& problem) const { fail(file_, line_, problem); }
  const path& file() const { return file_; }
  std::size_t line() const { return line_; }
  std::size_t bytes_left() const { return bytes_.size() - position_; }
  bool binary = false;

  // The rest of the current line (without '\r'), moving to the next one.
  std::string_view rest_of_line() {
    const std::size_t end = std::min(bytes_.find('\n', position_), bytes_.size());
    std::string_view text = std::string_view(bytes_).substr(position_, end - position_);
    position_ = std::min(end + 1, bytes_.size());
    ++line_;
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    return text;
  }

  // The next blank-separated word; empty at the end of the file.
  std::string_view word() {
    skip_blanks();
    const std::size_t start = position_;
    while (position_ < bytes_.size() && !is_blank(bytes_[position_])) ++position_;
    return std::string_view(bytes_).substr(start, position_ - start);
  }
  std::string_view required_word(const char* what) {
    const std::string_view w = word();
    if (w.empty()) fail_here(std::string("truncated: expected ") + what);
    return w;
  }
  long long count(const char* what) {
    const long long value = parse_integer(required_word(what), file_, line_, what);
    if (value < 0) fail_here(std::string("negative ") + what + " " + std::to_string(value));
    return value;
  }
  // After a header line, BINARY data starts on the next line.
  void end_header_line() {
    while (position_ < bytes_.size() && bytes_[position_] != '\n') ++position_;
    if (position_ < bytes_.size()) {
      ++position_;
      ++line_;
    }
  }
  // Whether the next word is `keyword` (case-insensitive); consumes it only if so.
  bool next_is(std::string_view keyword) {
    const std::size_t position = position_, line = line_;
    const std::string_view w = word();
    if (w.size() == keyword.size() &&
        std::equal(w.begin(), w.end(), keyword.begin(), [](char a, char b) {
          return std::toupper(static_cast<unsigned char>(a)) == b;
        }))
      return true;
    position_ = position;
    line_ = line;
    return false;
  }

  // Calls on_value(double) `count` times with the next values of `type`.
  template <class OnValue>
  void values(ValueType type, long long count, const char* what, OnValue on_value) {
    if (type == ValueType::string) return strings(count, what);
    if (type == ValueType::bit) {
      if (!binary) return ascii_values(ValueType::u8, count, what, [](double) {});
      // Bits are packed 8 to a byte.
      skip_block((static_cast<unsigned long long>(count) + 7) / 8, what);
      return;
    }
    if (!binary) return ascii_values(type, count, what, on_value);
    const std::size_t size = binary_size(type);
    end_header_line();
    if (static_cast<unsigned long long>(count) > bytes_left() / size)
      fail_here("truncated: " + std::to_string(count) + " " + what + " need " + std::to_string(size) +
                " bytes each, the file has " + std::to_string(bytes_left()) + " left");
    for (long long i = 0; i < count; ++i) {
      std::uint64_t bits = 0;
      for (std::size_t b = 0; b < size; ++b) bits = (bits << 8) | static_cast<unsigned char>(bytes_[position_ + b]);
      position_ += size;
      on_value(decode(type, bits));
    }
  }

 private:
  static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }
  void skip_blanks() {
    while (position_ < bytes_.size() && is_blank(bytes_[position_])) {
      if (bytes_[position_] == '\n') ++line_;
      ++position_;
    }
  }

  static double decode(ValueType type, std::uint64_t bits) {
    switch (type) {
      case ValueType::u8: return static_cast<double>(static_cast<std::uint8_t>(bits));
      case ValueType::i8: return static_cast<double>(static_cast<std::int8_t>(bits));
      case ValueType::u16: return static_cast<double>(static_cast<std::uint16_t>(bits));
      case ValueType::i16: return static_cast<double>(static_cast<std::int16_t>(bits));
      case ValueType::u32: return static_cast<double>(static_cast<std::uint32_t>(bits));
      case ValueType::i32: return static_cast<double>(static_cast<std::int32_t>(bits));
      case ValueType::u64: return static_cast<double>(bits);
      case ValueType::i64: return static_cast<double>(static_cast<std::int64_t>(bits));
      case ValueType::f32: return std::bit_cast<float>(static_cast<std::uint32_t>(bits));
      case ValueType::f64: return std::bit_cast<double>(bits);
      case ValueType::bit: case ValueType::string: break;
    }
    return 0;
  }

  template <class OnValue>
  void ascii_values(ValueType type, long long count, const char* what, OnValue on_value) {
    for (long long i = 0; i < count; ++i) {
      const std::string_view w = word();
      if (w.empty())
        fail_here("truncated: expected " + std::to_string(count) + " " + what + ", file ends after " +
                  std::to_string(i));
      if (is_integer(type)) {
        on_value(static_cast<double>(parse_integer(w, file_, line_, what)));
      } else {
        // VTK writes non-finite values as "nan"/"inf" (a degenerate face's normal): they are
        // values, rejected only where they matter (read_mesh checks the coordinates).
        double value = 0;
        const auto [end, error] = std::from_chars(w.data(), w.data() + w.size(), value);
        if (error == std::errc::result_out_of_range) fail(file_, line_, std::string(what) + ": number out of range");
        if (error != std::errc() || end != w.data() + w.size())
          fail(file_, line_, std::string(what) + ": expected a number, found '" + std::string(w.substr(0, 30)) + "'");
        on_value(value);
      }
    }
  }

  void skip_block(unsigned long long size, const char* what) {
    end_header_line();
    if (size > bytes_left()) fail_here(std::string("truncated: ") + what);
    position_ += static_cast<std::size_t>(size);
  }

  // ASCII: one string per line. BINARY: each string after a big-endian length whose top
  // two bits say its width (11: 6 bits in 1 byte, 10: 14 bits in 2, 01: 30 in 4, 00: 62 in 8).
  void strings(long long count, const char* what) {
    end_header_line();
    for (long long i = 0; i < count; ++i) {
      if (position_ >= bytes_.size())
        fail_here("truncated: expected " + std::to_string(count) + " " + what + ", file ends after " +
                  std::to_string(i));
      if (!binary) {
        rest_of_line();
        continue;
      }
      const auto first = static_cast<unsigned char>(bytes_[position_]);
      const std::size_t width = first >= 0xc0 ? 1 : first >= 0x80 ? 2 : first >= 0x40 ? 4 : 8;
      if (width > bytes_left()) fail_here(std::string("truncated: ") + what);
      std::uint64_t length = first & (width == 8 ? 0xffu : 0x3fu);
      for (std::size_t b = 1; b < width; ++b)
        length = (length << 8) | static_cast<unsigned char>(bytes_[position_ + b]);
      position_ += width;
      if (length > bytes_left()) fail_here(std::string("truncated: ") + what);
      position_ += static_cast<std::size_t>(length);
    }
  }

  path file_;
  std::string bytes_;
  std::size_t position_ = 0;
  std::size_t line_ = 1;
};

// Cells as a flat list: for each cell its points. Filled from either on-disk layout.
struct CellList {
  std::vector<long long> offsets{0};  // cell c is connectivity[offsets[c] .. offsets[c+1])
  std::vector<long long> connectivity;
  std::size_t size() const { return offsets.size() - 1; }
};

long long as_index(LegacyFile& in, double value, const char* what) {
  if (!(value >= -9.0e15 && value <= 9.0e15) || value != std::floor(value))
    in.fail_here(std::string(what) + " is not an integer");
  return static_cast<long long>(value);
}

// "KEYWORD n size" was read: 4.x runs "k i1 .. ik" (size values in all), or 5.x
// "OFFSETS type" (n values) and "CONNECTIVITY type" (size values).
CellList read_cells(LegacyFile& in, long long n, long long size, const char* what) {
  CellList cells;
  const auto capped = [&](long long count) {
    return static_cast<std::size_t>(std::min<unsigned long long>(static_cast<unsigned long long>(count),
                                                                 in.bytes_left() / 2 + 1));
  };
  if (in.next_is("OFFSETS")) {
    const auto offset_type = value_type(std::string(in.required_word("offset type")));
    if (!offset_type || !is_integer(*offset_type) || *offset_type == ValueType::string || *offset_type == ValueType::bit)
      in.fail_here("bad OFFSETS type");
    if (n == 0) in.fail_here(std::string(what) + ": 5.x layout needs at least one offset");
    cells.offsets.clear();
    cells.offsets.reserve(capped(n));
    in.values(*offset_type, n, "offsets", [&](double v) {
      const long long offset = as_index(in, v, "offset");
      if (offset < (cells.offsets.empty() ? 0 : cells.offsets.back()) || offset > size ||
          (cells.offsets.empty() && offset != 0))
        in.fail_here(std::string(what) + ": offsets must start at 0 and rise to at most " + std::to_string(size));
      cells.offsets.push_back(offset);
    });
    if (cells.offsets.back() != size) in.fail_here(std::string(what) + ": last offset differs from the size");
    if (!in.next_is("CONNECTIVITY")) in.fail_here(std::string(what) + ": expected CONNECTIVITY after OFFSETS");
    const auto type = value_type(std::string(in.required_word("connectivity type")));
    if (!type || !is_integer(*type) || *type == ValueType::string || *type == ValueType::bit)
      in.fail_here("bad CONNECTIVITY type");
    cells.connectivity.reserve(capped(size));
    in.values(*type, size, "point indices", [&](double v) { cells.connectivity.push_back(as_index(in, v, "point index")); });
    return cells;
  }
  cells.offsets.reserve(capped(n) + 1);
  cells.connectivity.reserve(capped(size));
  long long remaining_in_cell = 0;
  in.values(ValueType::i32, size, "cell list values", [&](double v) {
    const long long value = as_index(in, v, "cell list value");
    if (remaining_in_cell > 0) {
      cells.connectivity.push_back(value);
      if (--remaining_in_cell == 0) cells.offsets.push_back(static_cast<long long>(cells.connectivity.size()));
      return;
    }
    if (static_cast<long long>(cells.size()) == n || value < 0)
      in.fail_here(std::string(what) + ": cell list is inconsistent with its size");
    if (value == 0) cells.offsets.push_back(static_cast<long long>(cells.connectivity.size()));
    remaining_in_cell = value;
  });
  if (remaining_in_cell != 0 || static_cast<long long>(cells.size()) != n)
    in.fail_here(std::string(what) + ": cell list is inconsistent with its size");
  return cells;
}

// VTK cell types we meet on surfaces: the lower-dimensional ones are skipped.
constexpr int kVertex = 1, kPolyVertex = 2, kLine = 3, kPolyLine = 4, kTriangle = 5, kTriangleStrip = 6,
              kPolygon = 7, kPixel = 8, kQuad = 9;

class LegacyMeshBuilder {
 public:
  LegacyMeshBuilder(LegacyFile& in, Mesh& mesh) : in_(in), mesh_(mesh) {}

  // One cell of `type`; records the faces it made so a cell array can tag them.
  void add(int type, std::span<const long long> points) {
    const std::size_t before = mesh_.faces.size();
    switch (type) {
      case kVertex: case kPolyVertex: case kLine: case kPolyLine: break;
      case kTriangle:
        if (points.size() != 3) in_.fail_here("triangle cell with " + std::to_string(points.size()) + " points");
        add_polygon(mesh_, points, mesh_.vertices.size(), in_.file(), in_.line());
        break;
      case kPixel: {  // corners in lexicographic order, not around the boundary
        if (points.size() != 4) in_.fail_here("pixel cell with " + std::to_string(points.size()) + " points");
        const long long quad[4] = {points[0], points[1], points[3], points[2]};
        add_polygon(mesh_, quad, mesh_.vertices.size(), in_.file(), in_.line());
        break;
      }
      case kQuad: case kPolygon:
        add_polygon(mesh_, points, mesh_.vertices.size(), in_.file(), in_.line());
        break;
      case kTriangleStrip:
        // A strip's triangle k is (k, k+1, k+2), every other one reversed to keep orientation.
        if (points.size() < 3) in_.fail_here("triangle strip with fewer than 3 points");
        for (std::size_t k = 0; k + 2 < points.size(); ++k) {
          const long long t[3] = {points[k + (k % 2)], points[k + 1 - (k % 2)], points[k + 2]};
          add_polygon(mesh_, t, mesh_.vertices.size(), in_.file(), in_.line());
        }
        break;
      default:
        in_.fail_here("cell type " + std::to_string(type) + " is not a surface cell (a mesh holds triangles, quads, "
                                                              "polygons and strips)");
    }
    first_face_.push_back(before);
  }
  void finish() { first_face_.push_back(mesh_.faces.size()); }
  std::size_t cells() const { return first_face_.empty() ? 0 : first_face_.size() - 1; }
  // Faces made by cell c.
  std::pair<std::size_t, std::size_t> faces_of(std::size_t c) const { return {first_face_[c], first_face_[c + 1]}; }

 private:
  LegacyFile& in_;
  Mesh& mesh_;
  std::vector<std::size_t> first_face_;
};

class LegacyReader {
 public:
  LegacyReader(const path& file, std::string bytes) : in_(file, std::move(bytes)), builder_(in_, mesh_) {}

  Mesh read() {
    read_header();
    std::string dataset(in_.required_word("DATASET"));
    if (!equals_upper(dataset, "DATASET")) in_.fail_here("expected DATASET, found '" + dataset.substr(0, 30) + "'");
    std::string kind(in_.required_word("dataset type"));
    std::transform(kind.begin(), kind.end(), kind.begin(), [](unsigned char c) { return std::toupper(c); });
    if (kind != "POLYDATA" && kind != "UNSTRUCTURED_GRID")
      in_.fail_here("dataset type " + kind.substr(0, 30) + " is not supported (POLYDATA or UNSTRUCTURED_GRID)");
    const bool polydata = kind == "POLYDATA";
    in_.end_header_line();

    // Polydata cells are numbered verts, lines, polys, strips whatever order they come in.
    CellList sections[4];
    bool seen[4] = {false, false, false, false};
    CellList grid_cells;
    std::vector<int> grid_types;
    bool have_cells = false;
    while (true) {
      const std::string keyword = upper(in_.word());
      if (keyword.empty()) break;
      if (keyword == "POINTS") {
        if (have_points_) in_.fail_here("second POINTS section");
        read_points();
      } else if (polydata && (keyword == "VERTICES" || keyword == "LINES" || keyword == "POLYGONS" ||
                              keyword == "TRIANGLE_STRIPS")) {
        if (have_cells) in_.fail_here(keyword + " after the attribute data");
        const int k = keyword == "VERTICES" ? 0 : keyword == "LINES" ? 1 : keyword == "POLYGONS" ? 2 : 3;
        if (seen[k]) in_.fail_here("second " + keyword + " section");
        seen[k] = true;
        const long long n = in_.count("cell count"), size = in_.count("cell list size");
        sections[k] = read_cells(in_, n, size, keyword.c_str());
      } else if (!polydata && keyword == "CELLS") {
        if (have_cells) in_.fail_here("CELLS after the attribute data");
        if (!grid_cells.connectivity.empty() || grid_cells.size() > 0) in_.fail_here("second CELLS section");
        const long long n = in_.count("cell count"), size = in_.count("cell list size");
        grid_cells = read_cells(in_, n, size, "CELLS");
      } else if (!polydata && keyword == "CELL_TYPES") {
        const long long n = in_.count("cell type count");
        if (static_cast<std::size_t>(n) != grid_cells.size())
          in_.fail_here("CELL_TYPES gives " + std::to_string(n) + " types for " + std::to_string(grid_cells.size()) +
                        " cells");
        grid_types.reserve(grid_cells.size());
        in_.values(ValueType::i32, n, "cell types", [&](double v) {
          grid_types.push_back(static_cast<int>(as_index(in_, v, "cell type")));
        });
      } else if (keyword == "CELL_DATA" || keyword == "POINT_DATA") {
        if (!have_cells) {
          build_cells(polydata, sections, grid_cells, grid_types);
          have_cells = true;
        }
        read_attributes(keyword == "CELL_DATA");
      } else if (keyword == "FIELD") {
        read_field(false, 0);
      } else if (keyword == "METADATA") {
        skip_metadata();
      } else {
        in_.fail_here("unexpected '" + keyword.substr(0, 30) + "' in legacy VTK " + kind);
      }
    }
    if (!have_points_) in_.fail_here("no POINTS section");
    if (!have_cells) build_cells(polydata, sections, grid_cells, grid_types);
    if (!mesh_.face_tags.empty() && mesh_.face_tags.size() != mesh_.faces.size())
      fail(in_.file(), "cell data 'tag' does not cover every face");
    return std::move(mesh_);
  }

 private:
  static bool equals_upper(std::string_view word, std::string_view keyword) { return upper(word) == keyword; }
  static std::string upper(std::string_view word) {
    std::string out(word);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::toupper(c); });
    return out;
  }

  void read_header() {
    const std::string version = upper(in_.rest_of_line());
    if (version.rfind("# VTK DATAFILE", 0) != 0)
      fail(in_.file(), 1, "not a legacy VTK file (first line must be '# vtk DataFile Version x.x')");
    in_.rest_of_line();  // the title: free text
    const std::vector<std::string_view> fields = split_fields(in_.rest_of_line());
    const std::string encoding = fields.empty() ? std::string() : upper(fields[0]);
    if (encoding != "ASCII" && encoding != "BINARY")
      fail(in_.file(), 3, "third line must say ASCII or BINARY");
    in_.binary = encoding == "BINARY";
  }

  void read_points() {
    const long long n = in_.count("point count");
    if (static_cast<unsigned long long>(n) > UINT32_MAX) in_.fail_here("too many points: " + std::to_string(n));
    const auto type = value_type(std::string(in_.required_word("point type")));
    if (!type || *type == ValueType::string || *type == ValueType::bit) in_.fail_here("bad POINTS type");
    mesh_.vertices.reserve(static_cast<std::size_t>(std::min<unsigned long long>(
        static_cast<unsigned long long>(n), in_.bytes_left() / 6 + 1)));
    double xyz[3];
    int axis = 0;
    in_.values(*type, 3 * n, "point coordinates", [&](double v) {
      xyz[axis++] = v;
      if (axis == 3) {
        mesh_.vertices.push_back({xyz[0], xyz[1], xyz[2]});
        axis = 0;
      }
    });
    have_points_ = true;
  }

  void build_cells(bool polydata, const CellList (&sections)[4], const CellList& grid_cells,
                   const std::vector<int>& grid_types) {
    if (polydata) {
      const int types[4] = {kPolyVertex, kPolyLine, kPolygon, kTriangleStrip};
      for (int k = 0; k < 4; ++k) add_all(sections[k], [&](std::size_t) { return types[k]; });
    } else {
      if (grid_types.size() != grid_cells.size()) in_.fail_here("CELLS without CELL_TYPES");
      add_all(grid_cells, [&](std::size_t c) { return grid_types[c]; });
    }
    builder_.finish();
  }

  template <class TypeOf>
  void add_all(const CellList& cells, TypeOf type_of) {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const auto begin = static_cast<std::size_t>(cells.offsets[c]), end = static_cast<std::size_t>(cells.offsets[c + 1]);
      builder_.add(type_of(c), std::span<const long long>(cells.connectivity).subspan(begin, end - begin));
    }
  }

  // POINT_DATA n or CELL_DATA n, then attributes until the next section keyword.
  void read_attributes(bool cell_data) {
    const long long n = in_.count("attribute count");
    const std::size_t expected = cell_data ? builder_.cells() : mesh_.vertices.size();
    if (static_cast<std::size_t>(n) != expected)
      in_.fail_here(std::string(cell_data ? "CELL_DATA" : "POINT_DATA") + " " + std::to_string(n) + " for " +
                    std::to_string(expected) + (cell_data ? " cells" : " points"));
    while (true) {
      if (in_.next_is("SCALARS")) {
        const std::string name(in_.required_word("scalars name"));
        const auto type = value_type(std::string(in_.required_word("scalars type")));
        if (!type) in_.fail_here("bad SCALARS type");
        const std::string_view rest = in_.rest_of_line();
        long long components = 1;
        if (const auto fields = split_fields(rest); !fields.empty())
          components = parse_integer(fields[0], in_.file(), in_.line() - 1, "component count");
        if (components < 1 || components > 4) in_.fail_here("SCALARS needs 1 to 4 components");
        if (!in_.next_is("LOOKUP_TABLE")) in_.fail_here("SCALARS needs a LOOKUP_TABLE line");
        in_.required_word("lookup table name");
        read_array(cell_data && name == "tag" && components == 1, *type, n * components, "scalars");
      } else if (in_.next_is("COLOR_SCALARS")) {
        in_.required_word("color scalars name");
        const long long components = in_.count("color component count");
        if (components > 4) in_.fail_here("COLOR_SCALARS needs 1 to 4 components");
        read_array(false, in_.binary ? ValueType::u8 : ValueType::f32, n * components, "colour values");
      } else if (in_.next_is("LOOKUP_TABLE")) {
        in_.required_word("lookup table name");
        const long long size = in_.count("lookup table size");
        if (size > INT32_MAX) in_.fail_here("lookup table too large");
        read_array(false, in_.binary ? ValueType::u8 : ValueType::f32, 4 * size, "lookup table values");
      } else if (in_.next_is("VECTORS") || in_.next_is("NORMALS")) {
        in_.required_word("name");
        const auto type = value_type(std::string(in_.required_word("type")));
        if (!type) in_.fail_here("bad vector type");
        read_array(false, *type, 3 * n, "vector components");
      } else if (in_.next_is("TEXTURE_COORDINATES")) {
        in_.required_word("name");
        const long long dimension = in_.count("texture dimension");
        if (dimension < 1 || dimension > 3) in_.fail_here("texture coordinates need 1 to 3 dimensions");
        const auto type = value_type(std::string(in_.required_word("type")));
        if (!type) in_.fail_here("bad texture coordinate type");
        read_array(false, *type, dimension * n, "texture coordinates");
      } else if (const bool six = in_.next_is("TENSORS6"); six || in_.next_is("TENSORS")) {
        in_.required_word("name");
        const auto type = value_type(std::string(in_.required_word("type")));
        if (!type) in_.fail_here("bad tensor type");
        read_array(false, *type, (six ? 6 : 9) * n, "tensor components");
      } else if (in_.next_is("GLOBAL_IDS") || in_.next_is("PEDIGREE_IDS")) {
        in_.required_word("name");
        const auto type = value_type(std::string(in_.required_word("type")));
        if (!type) in_.fail_here("bad id type");
        read_array(false, *type, n, "ids");
      } else if (in_.next_is("FIELD")) {
        read_field(cell_data, n);
      } else if (in_.next_is("METADATA")) {
        skip_metadata();
      } else {
        return;  // the next section (or the end)
      }
    }
  }

  // FIELD name k, then k arrays "name components tuples type" (or NULL_ARRAY).
  void read_field(bool cell_data, long long tuples_expected) {
    in_.required_word("field name");
    const long long arrays = in_.count("field array count");
    for (long long a = 0; a < arrays; ++a) {
      const std::string name(in_.required_word("field array name"));
      if (name == "NULL_ARRAY") continue;
      const long long components = in_.count("component count");
      const long long tuples = in_.count("tuple count");
      const auto type = value_type(std::string(in_.required_word("field array type")));
      if (!type) in_.fail_here("bad field array type");
      if (components == 0 || components > 1024) in_.fail_here("field array needs 1 to 1024 components");
      if (static_cast<unsigned long long>(tuples) > static_cast<unsigned long long>(INT64_MAX) / 1024)
        in_.fail_here("field array too large");
      const bool is_tag = cell_data && name == "tag" && components == 1;
      if (is_tag && tuples != tuples_expected) in_.fail_here("cell data 'tag' has the wrong number of values");
      read_array(is_tag, *type, components * tuples, "field values");
      if (in_.next_is("METADATA")) skip_metadata();
    }
  }

  void read_array(bool is_tag, ValueType type, long long count, const char* what) {
    if (!is_tag) {
      in_.values(type, count, what, [](double) {});
      return;
    }
    if (!is_integer(type) && type != ValueType::f32 && type != ValueType::f64) in_.fail_here("'tag' is not numeric");
    mesh_.face_tags.clear();
    mesh_.face_tags.reserve(mesh_.faces.size());
    std::size_t cell = 0;
    in_.values(type, count, "tags", [&](double value) {
      if (!(value >= INT32_MIN && value <= INT32_MAX) || value != std::floor(value))
        in_.fail_here("cell " + std::to_string(cell) + ": tag is not a 32-bit integer");
      const auto [first, last] = builder_.faces_of(cell++);
      mesh_.face_tags.insert(mesh_.face_tags.end(), last - first, static_cast<std::int32_t>(value));
    });
  }

  // VTK 9 writes "METADATA" blocks (component names, information keys) after arrays:
  // lines up to an empty one.
  void skip_metadata() {
    in_.end_header_line();
    while (in_.bytes_left() > 0 && !split_fields(in_.rest_of_line()).empty()) {
    }
  }

  LegacyFile in_;
  Mesh mesh_;
  LegacyMeshBuilder builder_;
  bool have_points_ = false;
};

}  // namespace

Mesh read_vtk(const path& file) { return LegacyReader(file, read_file_bytes(file)).read(); }

}  // namespace molsurf::mesh_io
