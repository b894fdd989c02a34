// VTK XML PolyData (.vtp) reader of our own. VTK 9.1's XML reader trusts the sizes a file
// declares (counts, block headers, string arrays): fuzzing found reads past its buffers,
// divisions by zero and unbounded allocations. Here the elements are parsed by
// vtk_xml.cpp and each array's data decoded by vtk_xml_array.cpp, where every size is
// checked against the bytes present.
// Read: every Piece's Points, Polys and Strips (strips become triangles), and the cell
// array "tag" (numeric, one component) as face tags. Verts and Lines only count, because
// cell data runs over verts, lines, polys, strips in that order. Other arrays are skipped
// without being decoded. Compressors other than zlib (LZ4, LZMA) are refused by name.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "io/mesh_formats.hpp"
#include "io/vtk_xml.hpp"
#include "io/vtk_xml_array.hpp"
#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

namespace {

const XmlElement* child(const XmlDocument& document, const XmlElement& parent, std::string_view name) {
  for (const std::size_t c : parent.children)
    if (document.elements[c].name == name) return &document.elements[c];
  return nullptr;
}

// A data array of `section` by name, or (empty name) its first one.
const XmlElement* array_of(const XmlDocument& document, const XmlElement& section, std::string_view name) {
  for (const std::size_t c : section.children) {
    const XmlElement& element = document.elements[c];
    if (element.name != "DataArray" && element.name != "Array") continue;
    if (name.empty() || element.attribute("Name") == name) return &element;
  }
  return nullptr;
}

std::uint64_t count_attribute(const std::filesystem::path& file, const XmlElement& element, std::string_view key) {
  const std::string_view text = element.attribute(key).value_or("0");
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size())
    fail(file, element.line, std::string(key) + "=\"" + std::string(text.substr(0, 24)) + "\" is not a count");
  return value;
}

std::uint64_t components(const std::filesystem::path& file, const XmlElement& array) {
  return array.attribute("NumberOfComponents") ? count_attribute(file, array, "NumberOfComponents") : 1;
}

class PieceReader {
 public:
  PieceReader(const std::filesystem::path& file, const XmlDocument& document, VtkXmlArrays& arrays)
      : file_(file), document_(document), arrays_(arrays) {}

  Mesh read(const XmlElement& piece) {
    const std::uint64_t points = count_attribute(file_, piece, "NumberOfPoints");
    const std::uint64_t verts = count_attribute(file_, piece, "NumberOfVerts");
    const std::uint64_t lines = count_attribute(file_, piece, "NumberOfLines");
    const std::uint64_t strips = count_attribute(file_, piece, "NumberOfStrips");
    const std::uint64_t polys = count_attribute(file_, piece, "NumberOfPolys");
    constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max() / 4;
    if (points > kMax || verts > kMax || lines > kMax || strips > kMax || polys > kMax)
      fail(file_, piece.line, "Piece: a count beyond any file's size");

    Mesh mesh;
    if (points > 0) {
      const XmlElement* section = child(document_, piece, "Points");
      const XmlElement* array = section ? array_of(document_, *section, "") : nullptr;
      if (array == nullptr) fail(file_, piece.line, "Piece of " + std::to_string(points) + " points has no <Points> array");
      if (components(file_, *array) != 3) fail(file_, array->line, "the Points array does not have 3 components");
      const std::vector<double> xyz = arrays_.reals(*array, 3 * points);
      mesh.vertices.reserve(xyz.size() / 3);
      for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) mesh.vertices.push_back({xyz[i], xyz[i + 1], xyz[i + 2]});
    }

    const std::vector<std::int32_t> tags = cell_tags(piece, verts + lines + polys + strips);
    const auto tag_of = [&](std::uint64_t cell) { return tags.empty() ? kNoTag : tags[static_cast<std::size_t>(cell)]; };
    std::vector<long long> polygon;
    for_each_cell(piece, "Polys", polys, [&](std::span<const std::int64_t> ids, std::uint64_t cell, std::size_t line) {
      polygon.assign(ids.begin(), ids.end());
      add_face(mesh, polygon, tag_of(verts + lines + cell), line);
    });
    // A strip's triangle k is (k, k+1, k+2), every other one reversed to keep orientation.
    for_each_cell(piece, "Strips", strips, [&](std::span<const std::int64_t> ids, std::uint64_t cell, std::size_t line) {
      if (ids.size() < 3) fail(file_, line, "triangle strip " + std::to_string(cell) + " has fewer than 3 points");
      for (std::size_t k = 0; k + 2 < ids.size(); ++k) {
        if (k % 2 == 0) polygon = {ids[k], ids[k + 1], ids[k + 2]};
        else polygon = {ids[k + 1], ids[k], ids[k + 2]};
        add_face(mesh, polygon, tag_of(verts + lines + polys + cell), line);
      }
    });
    if (!has_tags_) mesh.face_tags.clear();
    return mesh;
  }

 private:
  void add_face(Mesh& mesh, const std::vector<long long>& polygon, std::int32_t tag, std::size_t line) {
    add_polygon(mesh, polygon, mesh.vertices.size(), file_, line);
    mesh.face_tags.resize(mesh.faces.size(), tag);
  }

  // The cell array "tag", one integer per cell; empty when the piece has none. A "tag"
  // of strings or of several components is some other program's array, not ours.
  std::vector<std::int32_t> cell_tags(const XmlElement& piece, std::uint64_t cells) {
    has_tags_ = false;
    const XmlElement* section = child(document_, piece, "CellData");
    const XmlElement* array = section ? array_of(document_, *section, "tag") : nullptr;
    if (array == nullptr || array->attribute("type") == "String" || components(file_, *array) != 1) return {};
    // Sized from the values read, which match the file, never from the declared count.
    const std::vector<double> values = arrays_.reals(*array, cells);
    std::vector<std::int32_t> tags;
    tags.reserve(values.size());
    for (const double value : values) {
      if (!(value >= std::numeric_limits<std::int32_t>::min() && value <= std::numeric_limits<std::int32_t>::max()) ||
          value != std::floor(value))
        fail(file_, array->line, "cell " + std::to_string(tags.size()) + ": tag is not a 32-bit integer");
      tags.push_back(static_cast<std::int32_t>(value));
    }
    has_tags_ = true;
    return tags;
  }

  // Calls on_cell(ids, cell, line) for each of the `count` cells of `name` ("Polys", "Strips").
  template <class OnCell>
  void for_each_cell(const XmlElement& piece, const char* name, std::uint64_t count, OnCell on_cell) {
    if (count == 0) return;
    const XmlElement* section = child(document_, piece, name);
    if (section == nullptr)
      fail(file_, piece.line, "Piece of " + std::to_string(count) + " " + name + " has no <" + name + "> element");
    const XmlElement* connectivity = array_of(document_, *section, "connectivity");
    const XmlElement* offsets = array_of(document_, *section, "offsets");
    if (connectivity == nullptr || offsets == nullptr)
      fail(file_, section->line, std::string("<") + name + "> lacks its 'connectivity' or 'offsets' array");
    // offsets[i] is where cell i ends in connectivity.
    const std::vector<std::int64_t> ends = arrays_.integers(*offsets, count);
    const std::vector<std::int64_t> ids = arrays_.integers(*connectivity, std::nullopt);
    std::int64_t start = 0;
    for (std::size_t cell = 0; cell < ends.size(); ++cell) {
      if (ends[cell] < start || static_cast<std::uint64_t>(ends[cell]) > ids.size())
        fail(file_, offsets->line, std::string(name) + " offset " + std::to_string(cell) + " is " +
                                       std::to_string(ends[cell]) + ": outside " + std::to_string(start) + ".." +
                                       std::to_string(ids.size()));
      on_cell(std::span<const std::int64_t>(ids).subspan(static_cast<std::size_t>(start),
                                                         static_cast<std::size_t>(ends[cell] - start)),
              cell, connectivity->line);
      start = ends[cell];
    }
    if (static_cast<std::uint64_t>(start) != ids.size())
      fail(file_, offsets->line, std::string(name) + " offsets end at " + std::to_string(start) + " but 'connectivity' holds " +
                                     std::to_string(ids.size()) + " values");
  }

  const std::filesystem::path& file_;
  const XmlDocument& document_;
  VtkXmlArrays& arrays_;
  bool has_tags_ = false;
};

}  // namespace

Mesh read_vtp(const path& file) {
  const std::string bytes = read_file_bytes(file);
  const XmlDocument document = parse_vtk_xml(file, bytes);
  const XmlElement& root = document.elements[0];
  if (root.name != "VTKFile")
    fail(file, root.line, "not a VTK XML file: the root element is <" + std::string(root.name.substr(0, 24)) + ">");
  const std::string_view type = root.attribute("type").value_or("");
  if (type != "PolyData")
    fail(file, root.line, "a VTK XML file of type '" + std::string(type.substr(0, 24)) + "', not PolyData");

  VtkXmlEncoding encoding;
  const std::string_view header_type = root.attribute("header_type").value_or("UInt32");
  if (header_type != "UInt32" && header_type != "UInt64")
    fail(file, root.line, "header_type '" + std::string(header_type.substr(0, 24)) + "' is not UInt32 or UInt64");
  encoding.header_size = header_type == "UInt64" ? 8 : 4;
  const std::string_view byte_order = root.attribute("byte_order").value_or("LittleEndian");
  if (byte_order != "LittleEndian" && byte_order != "BigEndian")
    fail(file, root.line, "byte_order '" + std::string(byte_order.substr(0, 24)) + "' is not LittleEndian or BigEndian");
  encoding.big_endian = byte_order == "BigEndian";
  if (const auto compressor = root.attribute("compressor")) {
    if (*compressor != "vtkZLibDataCompressor")
      fail(file, root.line, "compressor '" + std::string(compressor->substr(0, 24)) +
                                "' is not supported: molsurf reads zlib-compressed and uncompressed .vtp files");
    encoding.zlib = true;
  }
  encoding.has_appended = document.has_appended;
  encoding.appended = document.appended;
  if (document.appended_encoding && *document.appended_encoding != "raw" && *document.appended_encoding != "base64")
    fail(file, "<AppendedData> encoding '" + document.appended_encoding->substr(0, 24) + "' is not raw or base64");
  encoding.appended_base64 = document.appended_encoding == "base64";

  const XmlElement* polydata = child(document, root, "PolyData");
  if (polydata == nullptr) fail(file, root.line, "<VTKFile> has no <PolyData> element");
  VtkXmlArrays arrays(file, encoding);
  PieceReader reader(file, document, arrays);
  Mesh mesh;
  for (const std::size_t c : polydata->children)
    if (document.elements[c].name == "Piece") mesh.append(reader.read(document.elements[c]));
  return mesh;
}

}  // namespace molsurf::mesh_io
