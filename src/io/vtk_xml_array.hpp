#pragma once
// Internal: the values of one <DataArray> of a VTK XML file, in every encoding VTK writes
// (ascii; base64 "binary"; appended raw or base64; uncompressed or zlib blocks; UInt32 or
// UInt64 headers; either byte order). Every declared size is checked against the bytes
// present before it is used, and nothing is allocated beyond what the data holds (zlib
// blocks: at most kMaxCompressionRatio times their compressed size).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "io/vtk_xml.hpp"

namespace molsurf::mesh_io {

// How a file encodes its binary data: from <VTKFile> and <AppendedData>.
struct VtkXmlEncoding {
  std::size_t header_size = 4;  // UInt32 or UInt64 size words
  bool big_endian = false;
  bool zlib = false;
  bool has_appended = false;
  std::string_view appended;    // the appended data, if any
  bool appended_base64 = false;
};

class VtkXmlArrays {
 public:
  VtkXmlArrays(const std::filesystem::path& file, const VtkXmlEncoding& encoding) : file_(file), encoding_(encoding) {}

  // Exactly `count` values (any count when nullopt); errors name the array and its line.
  std::vector<double> reals(const XmlElement& array, std::optional<std::uint64_t> count);
  // The same for integer types only (indices, offsets).
  std::vector<std::int64_t> integers(const XmlElement& array, std::optional<std::uint64_t> count);

 private:
  template <class Value>
  std::vector<Value> values(const XmlElement& array, std::optional<std::uint64_t> count);

  const std::filesystem::path& file_;
  VtkXmlEncoding encoding_;
  // Appended bytes used so far: arrays that share bytes would let a small file describe
  // unbounded data, so together they may use no more than the appended data holds.
  std::uint64_t appended_used_ = 0;
};

}  // namespace molsurf::mesh_io
