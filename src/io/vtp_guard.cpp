// Checks a .vtp file's declared sizes against its bytes before VTK reads it. VTK 9.1's XML
// reader trusts them: a damaged appended-block header (block count, block sizes) makes it
// abort, and NumberOfPoints="2000000000" in a 1 KB file makes it allocate without bound.
// What is checked, without a full XML parse (the header is small and VTK parses it after):
//  - every appended DataArray's header (raw: byte count; zlib & co: block count, block
//    size, last block size, compressed sizes) lies inside the appended data, and the
//    decompressed size is at most kMaxCompressionRatio times the compressed one (deflate
//    cannot do better than about 1032:1);
//  - the Piece's counts fit in what the file can hold: at most that many bytes of data
//    (after decompression), a point taking at least 12 bytes and a cell at least 1;
//  - every data array names a known type (VTK divides by its word size), no array's
//    components times tuples exceed the data, and points have 3 components.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/vtp_guard.hpp"
#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

using std::filesystem::path;

namespace {

constexpr std::uint64_t kMaxCompressionRatio = 1032;

// The value of attribute `name` in the tag text `tag` ("<Name a="1" b='2'>").
std::optional<std::string_view> attribute(std::string_view tag, std::string_view name) {
  for (std::size_t at = tag.find(name); at != std::string_view::npos; at = tag.find(name, at + 1)) {
    const bool starts_word = at > 0 && (tag[at - 1] == ' ' || tag[at - 1] == '\t' || tag[at - 1] == '\n' ||
                                        tag[at - 1] == '\r');
    std::size_t p = at + name.size();
    while (p < tag.size() && (tag[p] == ' ' || tag[p] == '\t' || tag[p] == '\n' || tag[p] == '\r')) ++p;
    if (!starts_word || p >= tag.size() || tag[p] != '=') continue;
    ++p;
    while (p < tag.size() && (tag[p] == ' ' || tag[p] == '\t' || tag[p] == '\n' || tag[p] == '\r')) ++p;
    if (p >= tag.size() || (tag[p] != '"' && tag[p] != '\'')) return std::nullopt;
    const std::size_t end = tag.find(tag[p], p + 1);
    if (end == std::string_view::npos) return std::nullopt;
    return tag.substr(p + 1, end - p - 1);
  }
  return std::nullopt;
}

class Guard {
 public:
  Guard(const path& file, const std::string& bytes) : file_(file), bytes_(bytes) {}

  void run() {
    // The XML part ends where the raw appended data begins ("<AppendedData ...>" then '_').
    const std::size_t appended_tag = bytes_.find("<AppendedData");
    const std::size_t xml_end = appended_tag == std::string::npos ? bytes_.size() : appended_tag;
    const std::string_view xml = std::string_view(bytes_).substr(0, xml_end);
    std::size_t data_start = std::string::npos;
    if (appended_tag != std::string::npos) {
      const std::size_t tag_end = bytes_.find('>', appended_tag);
      if (tag_end == std::string::npos) fail(file_, "truncated: <AppendedData> tag not closed");
      const std::string_view tag = std::string_view(bytes_).substr(appended_tag, tag_end - appended_tag);
      if (const auto encoding = attribute(tag, "encoding"); encoding && *encoding != "raw")
        appended_base64_ = true;
      data_start = bytes_.find('_', tag_end);
      if (data_start == std::string::npos) fail(file_, "truncated: no appended data after <AppendedData>");
      ++data_start;
    }

    check_element_names(xml);
    const std::size_t file_tag = xml.find("<VTKFile");
    if (file_tag == std::string_view::npos) fail(file_, "not a VTK XML file (no <VTKFile> element)");
    const std::string_view vtk_file = tag_at(xml, file_tag);
    header_size_ = attribute(vtk_file, "header_type").value_or("UInt32") == "UInt64" ? 8 : 4;
    big_endian_ = attribute(vtk_file, "byte_order").value_or("LittleEndian") == "BigEndian";
    compressed_ = attribute(vtk_file, "compressor").has_value();

    // Every appended array's header first: it also bounds the data the Piece can describe.
    std::uint64_t payload = xml.size();  // inline (ASCII, base64) data is at most this long
    std::vector<std::pair<std::string_view, std::uint64_t>> appended_sizes;  // tag, decompressed bytes
    for (const std::string_view tag : array_tags(xml)) {
      // VTK divides by the word size of the type: an unknown or missing type must not reach it.
      static constexpr std::string_view kTypes[] = {"Int8",  "UInt8",  "Int16",   "UInt16",  "Int32", "UInt32",
                                                    "Int64", "UInt64", "Float32", "Float64", "String", "Bit"};
      const std::string_view type = attribute(tag, "type").value_or("");
      if (std::find(std::begin(kTypes), std::end(kTypes), type) == std::end(kTypes))
        fail(file_, "data array without a known type ('" + std::string(type.substr(0, 20)) + "')");
      const std::string_view format = attribute(tag, "format").value_or("");
      if (format != "ascii" && format != "binary" && format != "appended")
        fail(file_, "data array without a known format ('" + std::string(format.substr(0, 20)) + "')");
      if (format == "binary") check_inline_binary(xml, tag);
      if (format != "appended") continue;
      if (data_start == std::string::npos) fail(file_, "appended DataArray but no <AppendedData>");
      if (appended_base64_) {
        payload += bytes_.size() - data_start;
        continue;  // base64 headers are decoded by VTK; their size is bounded by the file
      }
      const std::uint64_t offset = number(attribute(tag, "offset"), "DataArray offset");
      const std::uint64_t size = array_size(data_start, offset);
      payload += size;
      appended_sizes.push_back({tag, size});
    }

    std::uint64_t largest_count = 1;  // tuples of any array: points or cells
    std::uint64_t point_count = 0, cell_count = 0;
    for (std::size_t at = xml.find("<Piece"); at != std::string_view::npos; at = xml.find("<Piece", at + 1)) {
      const std::string_view tag = tag_at(xml, at);
      if (const auto points = attribute(tag, "NumberOfPoints"); points) {
        const std::uint64_t count = number(points, "NumberOfPoints");
        if (count > payload / 12)
          fail(file_, "NumberOfPoints=\"" + std::string(points->substr(0, 20)) +
                          "\" is more than the file's data can hold");
        largest_count = std::max(largest_count, count);
        point_count = count;
      }
      std::uint64_t cells = 0;
      for (const char* kind : {"NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"})
        if (const auto count = attribute(tag, kind); count) {
          const std::uint64_t n = number(count, kind);
          if (n > payload) fail(file_, std::string(kind) + "=\"" + std::string(count->substr(0, 20)) +
                                           "\" is more than the file's data can hold");
          cells += n;
        }
      largest_count = std::max(largest_count, cells);
      cell_count = cells;
    }

    // A numeric point or cell array holds exactly one tuple per point (cell): VTK 9.1
    // sizes its arrays by the Piece's counts and then reads what the data holds (string
    // arrays past their end). Checked for appended arrays of a single piece, whose
    // decompressed size the headers give.
    if (xml.find("<Piece") == xml.rfind("<Piece"))
      for (const auto& [tag, size] : appended_sizes) {
        const std::size_t at = static_cast<std::size_t>(tag.data() - xml.data());
        std::size_t section_at = 0;
        std::string_view section;
        for (const std::string_view name : {std::string_view("<PointData"), std::string_view("<CellData"),
                                            std::string_view("<Points"), std::string_view("<Verts"),
                                            std::string_view("<Lines"), std::string_view("<Strips"),
                                            std::string_view("<Polys"), std::string_view("<FieldData")}) {
          const std::size_t found = xml.rfind(name, at);
          if (found != std::string_view::npos && found >= section_at) {
            section_at = found;
            section = name;
          }
        }
        const bool per_point = section == "<PointData" || section == "<Points";
        if (!per_point && section != "<CellData") continue;
        const std::string_view type = attribute(tag, "type").value_or("");
        const std::size_t word = type.ends_with("64") ? 8 : type.ends_with("32") ? 4 : type.ends_with("16") ? 2 : 1;
        if (type == "String" || type == "Bit") continue;
        const std::uint64_t components =
            attribute(tag, "NumberOfComponents") ? number(attribute(tag, "NumberOfComponents"), "NumberOfComponents") : 1;
        if (size != (per_point ? point_count : cell_count) * components * word)
          fail(file_, "array '" + std::string(attribute(tag, "Name").value_or("").substr(0, 30)) + "' holds " +
                          std::to_string(size) + " bytes, not one value per " + (per_point ? "point" : "cell"));
      }

    // Each cell section holds its "connectivity" and "offsets" arrays: without one VTK 9.1
    // reads sizes from elsewhere.
    for (const std::string_view section : {std::string_view("Verts"), std::string_view("Lines"),
                                           std::string_view("Strips"), std::string_view("Polys")}) {
      const std::string open = "<" + std::string(section), close = "</" + std::string(section);
      for (std::size_t at = xml.find(open); at != std::string_view::npos; at = xml.find(open, at + 1)) {
        const std::size_t end = std::min(xml.find(close, at), xml.size());
        bool connectivity = false, offsets = false;
        for (const std::string_view tag : array_tags(xml.substr(at, end - at))) {
          const std::string_view name = attribute(tag, "Name").value_or("");
          connectivity = connectivity || name == "connectivity";
          offsets = offsets || name == "offsets";
        }
        if (!connectivity || !offsets)
          fail(file_, "<" + std::string(section) + "> lacks its 'connectivity' or 'offsets' array");
      }
    }

    // Points have 3 components; VTK refuses other counts but leaks on that path.
    for (std::size_t at = xml.find("<Points"); at != std::string_view::npos; at = xml.find("<Points", at + 1)) {
      const std::size_t array = xml.find("<DataArray", at);
      if (array == std::string_view::npos) continue;
      const std::string_view tag = tag_at(xml, array);
      if (attribute(tag, "NumberOfComponents").value_or("1") != "3")
        fail(file_, "Points array does not have 3 components");
    }

    // Every array is allocated as tuples x components before its data is read.
    for (const std::string_view tag : array_tags(xml)) {
      const std::uint64_t components =
          attribute(tag, "NumberOfComponents") ? number(attribute(tag, "NumberOfComponents"), "NumberOfComponents") : 1;
      const std::uint64_t tuples =
          attribute(tag, "NumberOfTuples") ? number(attribute(tag, "NumberOfTuples"), "NumberOfTuples") : largest_count;
      if (components > payload || (components > 0 && std::max(tuples, largest_count) > payload / components))
        fail(file_, "DataArray with " + std::to_string(components) + " components of " +
                        std::to_string(std::max(tuples, largest_count)) + " tuples is more than the file's data can hold");
    }
  }

 private:
  // Only the elements a PolyData file has: a damaged name ("<DataAr ...") makes VTK 9.1
  // look for the array elsewhere and read sizes the checks here never saw.
  void check_element_names(std::string_view xml) const {
    static constexpr std::string_view kNames[] = {
        "VTKFile",  "PolyData", "Piece",     "PointData", "CellData",     "Points", "Verts",
        "Lines",    "Strips",   "Polys",     "DataArray", "Array",        "FieldData", "AppendedData",
        "InformationKey", "Value", "Information"};
    for (std::size_t at = xml.find('<'); at != std::string_view::npos; at = xml.find('<', at + 1)) {
      std::size_t p = at + 1;
      if (p < xml.size() && (xml[p] == '/' || xml[p] == '?' || xml[p] == '!')) {
        if (xml[p] != '/') continue;  // declarations and comments
        ++p;
      }
      std::size_t end = p;
      while (end < xml.size() && (std::isalnum(static_cast<unsigned char>(xml[end])) || xml[end] == '_')) ++end;
      const std::string_view name = xml.substr(p, end - p);
      if (std::find(std::begin(kNames), std::end(kNames), name) == std::end(kNames))
        fail(file_, "unexpected XML element '<" + std::string(name.substr(0, 30)) + "'");
    }
  }

  // Inline binary: base64 text inside the element, the header its own base64 stream
  // (3 header words, then one compressed size per block, when compressed; one byte count
  // otherwise). The sizes it declares must fit in the text.
  void check_inline_binary(std::string_view xml, std::string_view tag) const {
    const std::size_t begin = static_cast<std::size_t>(tag.data() - xml.data()) + tag.size() + 1;
    const std::size_t end = std::min(xml.find('<', begin), xml.size());
    std::string text;
    for (std::size_t i = begin; i < end; ++i)
      if (xml[i] != ' ' && xml[i] != '\n' && xml[i] != '\r' && xml[i] != '\t') text += xml[i];
    const std::uint64_t limit = (text.size() + 64) * kMaxCompressionRatio;
    const std::string first = decode_base64(text, compressed_ ? 3 * header_size_ : header_size_);
    if (first.size() < (compressed_ ? 3 : 1) * header_size_) fail(file_, "truncated: inline binary array header");
    const auto word = [&](const std::string& bytes, std::size_t k) {
      std::uint64_t value = 0;
      for (std::size_t b = 0; b < header_size_; ++b)
        value = (value << 8) | static_cast<unsigned char>(bytes[k * header_size_ + (big_endian_ ? b : header_size_ - 1 - b)]);
      return value;
    };
    if (!compressed_) {
      if (word(first, 0) > text.size()) fail(file_, "inline binary array declares more bytes than it holds");
      return;
    }
    const std::uint64_t blocks = word(first, 0), block_size = word(first, 1), last_size = word(first, 2);
    if (blocks > text.size() / header_size_ || block_size > limit || last_size > block_size ||
        (blocks > 0 && block_size == 0) || (blocks == 0 && last_size != 0) ||
        (blocks > 0 && blocks - 1 > (limit - block_size) / block_size))
      fail(file_, "damaged inline binary array header");
    const std::string header = decode_base64(text, static_cast<std::size_t>((3 + blocks) * header_size_));
    if (header.size() < (3 + blocks) * header_size_) fail(file_, "truncated: inline binary array header");
    std::uint64_t compressed = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) compressed += word(header, static_cast<std::size_t>(3 + b));
    if (compressed > text.size()) fail(file_, "inline binary array declares more compressed bytes than it holds");
  }

  // The first `count` bytes of the base64 text (fewer if it ends or pads before).
  static std::string decode_base64(std::string_view text, std::size_t count) {
    std::string out;
    std::uint32_t bits = 0;
    int have = 0;
    for (const char c : text) {
      if (out.size() >= count) break;
      int v = c >= 'A' && c <= 'Z' ? c - 'A' : c >= 'a' && c <= 'z' ? c - 'a' + 26 : c >= '0' && c <= '9' ? c - '0' + 52
              : c == '+' ? 62 : c == '/' ? 63 : -1;
      if (v < 0) break;
      bits = (bits << 6) | static_cast<std::uint32_t>(v);
      have += 6;
      if (have >= 8) {
        have -= 8;
        out += static_cast<char>((bits >> have) & 0xffu);
      }
    }
    if (out.size() > count) out.resize(count);
    return out;
  }

  // The start tags of every data array: <DataArray ...> and (strings) <Array ...>.
  std::vector<std::string_view> array_tags(std::string_view xml) const {
    std::vector<std::string_view> tags;
    for (const std::string_view name : {std::string_view("<DataArray"), std::string_view("<Array")})
      for (std::size_t at = xml.find(name); at != std::string_view::npos; at = xml.find(name, at + 1)) {
        const std::size_t next = at + name.size();
        if (next < xml.size() && (xml[next] == ' ' || xml[next] == '\t' || xml[next] == '\n' || xml[next] == '\r'))
          tags.push_back(tag_at(xml, at));
      }
    return tags;
  }

  std::string_view tag_at(std::string_view xml, std::size_t at) const {
    const std::size_t end = xml.find('>', at);
    if (end == std::string_view::npos) fail(file_, "truncated XML: tag not closed");
    return xml.substr(at, end - at);
  }

  std::uint64_t number(std::optional<std::string_view> text, const char* what) const {
    std::uint64_t value = 0;
    if (!text) fail(file_, std::string(what) + " missing");
    const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), value);
    if (error != std::errc() || end != text->data() + text->size())
      fail(file_, std::string(what) + " is not a non-negative integer: '" + std::string(text->substr(0, 20)) + "'");
    return value;
  }

  std::uint64_t header_word(std::size_t at) const {
    if (at > bytes_.size() || bytes_.size() - at < header_size_)
      fail(file_, "truncated: appended data header runs past the end of the file");
    std::uint64_t value = 0;
    for (std::size_t b = 0; b < header_size_; ++b) {
      const std::size_t byte = big_endian_ ? b : header_size_ - 1 - b;
      value = (value << 8) | static_cast<unsigned char>(bytes_[at + byte]);
    }
    return value;
  }

  // The decompressed size of the array at `offset`, after checking its header.
  std::uint64_t array_size(std::size_t data_start, std::uint64_t offset) const {
    if (offset > bytes_.size() - data_start) fail(file_, "DataArray offset " + std::to_string(offset) + " is past the end of the file");
    const std::size_t at = data_start + static_cast<std::size_t>(offset);
    const std::uint64_t left = bytes_.size() - at;
    if (!compressed_) {
      const std::uint64_t size = header_word(at);
      if (size > left - header_size_) fail(file_, "truncated: appended array of " + std::to_string(size) + " bytes");
      return size;
    }
    const std::uint64_t blocks = header_word(at);
    if (left < 3 * header_size_ || blocks > left / header_size_ - 3)
      fail(file_, "damaged appended data header: " + std::to_string(blocks) + " blocks");
    const std::uint64_t block_size = header_word(at + header_size_);
    const std::uint64_t last_size = header_word(at + 2 * header_size_);
    // An empty array has no last block either: VTK would read block -1 for it.
    if ((blocks > 0 && block_size == 0) || last_size > block_size || (blocks == 0 && last_size != 0))
      fail(file_, "damaged appended data header: block size " + std::to_string(block_size) + ", last block " +
                      std::to_string(last_size));
    std::uint64_t compressed = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const std::uint64_t size = header_word(at + static_cast<std::size_t>((3 + b) * header_size_));
      if (size > left) fail(file_, "damaged appended data header: compressed block of " + std::to_string(size) + " bytes");
      compressed += size;
    }
    const std::uint64_t header = (3 + blocks) * header_size_;
    if (compressed > left - header) fail(file_, "truncated: compressed appended data runs past the end of the file");
    // VTK allocates a block of block_size even for an empty array: bound it in any case.
    const std::uint64_t limit = (compressed + 64) * kMaxCompressionRatio;
    if (block_size > limit) fail(file_, "damaged appended data header: block size " + std::to_string(block_size));
    if (blocks == 0) return 0;
    if (blocks - 1 > (limit - block_size) / block_size)
      fail(file_, "damaged appended data header: " + std::to_string(blocks) + " blocks of " +
                      std::to_string(block_size) + " bytes from " + std::to_string(compressed) + " compressed bytes");
    const std::uint64_t total = (blocks - 1) * block_size + (last_size == 0 ? block_size : last_size);
    if (total > limit)
      fail(file_, "damaged appended data header: " + std::to_string(total) + " bytes from " +
                      std::to_string(compressed) + " compressed bytes");
    return total;
  }

  const path& file_;
  const std::string& bytes_;
  std::size_t header_size_ = 4;
  bool big_endian_ = false;
  bool compressed_ = false;
  bool appended_base64_ = false;
};

}  // namespace

void check_vtp_sizes(const path& file, const std::string& bytes) { Guard(file, bytes).run(); }

}  // namespace molsurf::mesh_io
