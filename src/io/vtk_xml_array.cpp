// Decodes VTK XML data arrays. Layout of binary data, as VTK 9 writes and reads it:
//  - uncompressed: one size word (the byte count), then the bytes;
//  - zlib: three words (block count, block size, size of the last block or 0 when it is
//    full), one compressed size per block, then the blocks, each its own zlib stream;
//  - "binary" (inline) and appended base64: the same bytes in base64. A compressed array's
//    header is encoded apart from its blocks, so its last quantum may be padded; the
//    decoder therefore lets a padded quantum end one stream and the next begin.
// Size words are UInt32 or UInt64 in the file's byte order.
#include "io/vtk_xml_array.hpp"

#include <zlib.h>

#include <charconv>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

#include "molsurf/error.hpp"

namespace molsurf::mesh_io {

namespace {

// Deflate cannot compress better than about 1032:1: a block declaring more is damaged,
// and this bounds what a small file can make us allocate.
constexpr std::uint64_t kMaxCompressionRatio = 1032;

enum class Kind { i8, u8, i16, u16, i32, u32, i64, u64, f32, f64 };
struct ValueType {
  Kind kind;
  std::size_t size;
  bool real;
};

std::optional<ValueType> value_type(std::string_view name) {
  static constexpr std::pair<std::string_view, ValueType> kTypes[] = {
      {"Int8", {Kind::i8, 1, false}},     {"UInt8", {Kind::u8, 1, false}},   {"Int16", {Kind::i16, 2, false}},
      {"UInt16", {Kind::u16, 2, false}},  {"Int32", {Kind::i32, 4, false}},  {"UInt32", {Kind::u32, 4, false}},
      {"Int64", {Kind::i64, 8, false}},   {"UInt64", {Kind::u64, 8, false}}, {"Float32", {Kind::f32, 4, true}},
      {"Float64", {Kind::f64, 8, true}}};
  for (const auto& [type_name, type] : kTypes)
    if (type_name == name) return type;
  return std::nullopt;
}

std::string shown(std::string_view text) {
  std::string out;
  for (const char c : text.substr(0, 24)) out += c >= 0x20 && c < 0x7f ? c : '?';
  return "'" + out + (text.size() > 24 ? "...'" : "'");
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

// The bytes of an array: raw, or base64 text decoded as it is read.
class ByteCursor {
 public:
  ByteCursor(std::string_view source, bool base64) : source_(source), base64_(base64) {}

  // Appends the next `n` bytes to `out`; false when the data ends (or stops being base64) first.
  bool take(std::uint64_t n, std::string& out) {
    if (!base64_) {
      if (n > source_.size() - position_) return false;
      out.append(source_.substr(position_, static_cast<std::size_t>(n)));
      position_ += static_cast<std::size_t>(n);
      return true;
    }
    if (n > most_left()) return false;
    for (; n > 0; --n) {
      if (pending_at_ == pending_count_ && !next_quantum()) return false;
      out += pending_[pending_at_++];
    }
    return true;
  }
  // At least as many bytes as could still come.
  std::uint64_t most_left() const {
    const std::uint64_t left = source_.size() - position_;
    return base64_ ? left / 4 * 3 + 3 : left;
  }
  std::size_t consumed() const { return position_; }

 private:
  bool next_quantum() {
    int values[4];
    int padding = 0;
    for (int k = 0; k < 4; ++k) {
      while (position_ < source_.size() && is_space(source_[position_])) ++position_;
      if (position_ >= source_.size()) return false;
      const char c = source_[position_++];
      if (c == '=' && k >= 2) {
        ++padding;
        values[k] = 0;
        continue;
      }
      if (padding > 0 || (values[k] = base64_value(c)) < 0) return false;
    }
    const std::uint32_t bits = static_cast<std::uint32_t>(values[0]) << 18 | static_cast<std::uint32_t>(values[1]) << 12 |
                               static_cast<std::uint32_t>(values[2]) << 6 | static_cast<std::uint32_t>(values[3]);
    pending_[0] = static_cast<char>(bits >> 16);
    pending_[1] = static_cast<char>(bits >> 8 & 0xff);
    pending_[2] = static_cast<char>(bits & 0xff);
    pending_count_ = static_cast<std::size_t>(3 - padding);
    pending_at_ = 0;
    return true;
  }

  std::string_view source_;
  bool base64_;
  std::size_t position_ = 0;
  char pending_[3] = {};
  std::size_t pending_count_ = 0, pending_at_ = 0;
};

std::uint64_t unsigned_at(const char* bytes, std::size_t size, bool big_endian) {
  std::uint64_t value = 0;
  for (std::size_t b = 0; b < size; ++b)
    value = value << 8 | static_cast<unsigned char>(bytes[big_endian ? b : size - 1 - b]);
  return value;
}

// Raises the errors of one <DataArray>: each names the file, the array's line and its Name.
class ArrayFailure {
 public:
  ArrayFailure(const std::filesystem::path& file, const XmlElement& array)
      : file_(file), line_(array.line), name_(shown(array.attribute("Name").value_or(""))) {}
  [[noreturn]] void operator()(const std::string& problem) const {
    fail(file_, line_, "DataArray " + name_ + ": " + problem);
  }

 private:
  const std::filesystem::path& file_;
  std::size_t line_;
  std::string name_;
};

// The array must hold exactly `count` values (any number when nullopt).
void check_value_count(std::optional<std::uint64_t> count, std::uint64_t values, const ArrayFailure& fail_here) {
  if (count && values != *count)
    fail_here("holds " + std::to_string(values) + " values; the Piece's counts need " + std::to_string(*count));
}

// An ascii array: words of text. VTK writes non-finite values as "nan" or "inf", which
// read_mesh refuses where they matter (coordinates).
template <class Value>
std::vector<Value> ascii_values(std::string_view text, ValueType type, std::optional<std::uint64_t> count,
                                const ArrayFailure& fail_here) {
  std::vector<Value> out;
  out.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(count.value_or(0), text.size() / 2 + 1)));
  for (std::size_t at = 0; at < text.size();) {
    while (at < text.size() && is_space(text[at])) ++at;
    if (at == text.size()) break;
    std::size_t end = at;
    while (end < text.size() && !is_space(text[end])) ++end;
    std::string_view word = text.substr(at, end - at);
    at = end;
    if (count && out.size() == *count) fail_here("holds more values than the " + std::to_string(*count) + " the Piece's counts need");
    if (word.size() > 1 && word.front() == '+') word.remove_prefix(1);
    const char* word_end = word.data() + word.size();
    std::from_chars_result parsed{};
    if (type.real) {
      double value = 0;
      parsed = std::from_chars(word.data(), word_end, value);
      out.push_back(static_cast<Value>(value));
    } else if (type.kind == Kind::u64) {
      std::uint64_t value = 0;
      parsed = std::from_chars(word.data(), word_end, value);
      if (parsed.ec == std::errc() && value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
        parsed.ec = std::errc::result_out_of_range;
      out.push_back(static_cast<Value>(value));
    } else {
      std::int64_t value = 0;
      parsed = std::from_chars(word.data(), word_end, value);
      out.push_back(static_cast<Value>(value));
    }
    if (parsed.ec == std::errc::result_out_of_range)
      fail_here("value " + std::to_string(out.size()) + " is out of range: " + shown(word));
    if (parsed.ec != std::errc() || parsed.ptr != word_end)
      fail_here("value " + std::to_string(out.size()) + ": expected a number, found " + shown(word));
  }
  check_value_count(count, out.size(), fail_here);
  return out;
}

// Where a binary array's bytes are: inline base64 ("binary"), or in <AppendedData> from
// the array's offset on.
struct BinarySource {
  std::string_view bytes;
  bool base64 = true;
};

BinarySource binary_source(const XmlElement& array, std::string_view format, const VtkXmlEncoding& encoding,
                           const ArrayFailure& fail_here) {
  if (format == "binary") return {array.text, true};
  if (format != "appended") fail_here("format " + shown(format) + " is not ascii, binary or appended");
  if (!encoding.has_appended) fail_here("format 'appended' but the file has no <AppendedData>");
  const std::string_view offset_text = array.attribute("offset").value_or("");
  std::uint64_t offset = 0;
  const auto [end, error] = std::from_chars(offset_text.data(), offset_text.data() + offset_text.size(), offset);
  if (error != std::errc() || end != offset_text.data() + offset_text.size())
    fail_here("offset " + shown(offset_text) + " is not a non-negative integer");
  if (offset > encoding.appended.size())
    fail_here("offset " + std::to_string(offset) + " is past the end of the appended data (" +
              std::to_string(encoding.appended.size()) + " bytes)");
  return {encoding.appended.substr(static_cast<std::size_t>(offset)), encoding.appended_base64};
}

// The data bytes of a binary array: its header of size words, then the bytes, raw or as
// zlib blocks. Every declared size is checked against what the caller expects and what
// the file holds before anything is allocated for it.
class BinaryArrayReader {
 public:
  BinaryArrayReader(ByteCursor& cursor, const VtkXmlEncoding& encoding, ValueType type, std::string_view type_name,
                    std::optional<std::uint64_t> count, const ArrayFailure& fail_here)
      : cursor_(cursor),
        encoding_(encoding),
        type_(type),
        type_name_(type_name),
        count_(count),
        fail_here_(fail_here) {}

  std::string data() { return encoding_.zlib ? inflated_blocks() : raw_bytes(); }

 private:
  std::uint64_t next_word(const char* what) {
    header_.clear();
    if (!cursor_.take(encoding_.header_size, header_))
      fail_here_(std::string("truncated: the data ends in its header (") + what + ")");
    return unsigned_at(header_.data(), encoding_.header_size, encoding_.big_endian);
  }

  // Checked before any data is read: the declared size must be what the caller expects.
  void check_size(std::uint64_t bytes) const {
    if (bytes % type_.size != 0)
      fail_here_("holds " + std::to_string(bytes) + " bytes, not a whole number of " + std::string(type_name_) +
                 " values");
    check_value_count(count_, bytes / type_.size, fail_here_);
  }

  std::string raw_bytes() {
    std::string data;
    const std::uint64_t size = next_word("byte count");
    check_size(size);
    if (!cursor_.take(size, data))
      fail_here_("truncated: declares " + std::to_string(size) + " bytes, the file holds fewer");
    return data;
  }

  std::string inflated_blocks() {
    const std::size_t word = encoding_.header_size;
    const std::uint64_t blocks = next_word("block count");
    const std::uint64_t block_size = next_word("block size");
    const std::uint64_t last_size = next_word("last block size");
    if ((blocks > 0 && block_size == 0) || last_size > block_size || (blocks == 0 && last_size != 0))
      fail_here_("damaged header: " + std::to_string(blocks) + " blocks of " + std::to_string(block_size) +
                 " bytes, the last of " + std::to_string(last_size));
    if (blocks > cursor_.most_left() / word)
      fail_here_("damaged header: " + std::to_string(blocks) + " blocks, more than the file holds");
    std::vector<std::uint64_t> compressed(static_cast<std::size_t>(blocks));
    for (std::uint64_t& size : compressed) size = next_word("compressed block sizes");
    if (blocks > 0 && blocks - 1 > (std::numeric_limits<std::uint64_t>::max() - block_size) / block_size)
      fail_here_("damaged header: " + std::to_string(blocks) + " blocks of " + std::to_string(block_size) + " bytes");
    check_size(blocks == 0 ? 0 : (blocks - 1) * block_size + (last_size == 0 ? block_size : last_size));
    std::string data, block;
    for (std::size_t b = 0; b < compressed.size(); ++b) {
      const std::uint64_t size = b + 1 == compressed.size() && last_size != 0 ? last_size : block_size;
      if (compressed[b] > cursor_.most_left())
        fail_here_("truncated: block " + std::to_string(b) + " declares " + std::to_string(compressed[b]) +
                   " compressed bytes, the file holds fewer");
      if (size / kMaxCompressionRatio > compressed[b] + 64)
        fail_here_("damaged header: block " + std::to_string(b) + " of " + std::to_string(size) + " bytes from " +
                   std::to_string(compressed[b]) + " compressed bytes");
      block.clear();
      if (!cursor_.take(compressed[b], block)) fail_here_("truncated: block " + std::to_string(b) + " ends early");
      const std::size_t start = data.size();
      data.resize(start + static_cast<std::size_t>(size));
      uLongf produced = static_cast<uLongf>(size);
      const int result = uncompress(reinterpret_cast<Bytef*>(data.data() + start), &produced,
                                    reinterpret_cast<const Bytef*>(block.data()), static_cast<uLong>(block.size()));
      if (result != Z_OK || produced != size)
        fail_here_("corrupt zlib data in block " + std::to_string(b) + " (" +
                   (result == Z_OK ? "it holds " + std::to_string(produced) + " bytes, not " + std::to_string(size)
                                   : std::string(zError(result))) + ")");
    }
    return data;
  }

  ByteCursor& cursor_;
  const VtkXmlEncoding& encoding_;
  ValueType type_;
  std::string_view type_name_;
  std::optional<std::uint64_t> count_;
  const ArrayFailure& fail_here_;
  std::string header_;  // the size word being read
};

// The values of a binary array from its decoded bytes, in the file's byte order.
template <class Value>
std::vector<Value> binary_values(std::string_view data, ValueType type, bool big_endian,
                                 const ArrayFailure& fail_here) {
  std::vector<Value> out;
  const std::size_t n = data.size() / type.size;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const char* at = data.data() + i * type.size;
    const std::uint64_t bits = unsigned_at(at, type.size, big_endian);
    Value value{};
    switch (type.kind) {
      case Kind::i8: value = static_cast<Value>(static_cast<std::int8_t>(bits)); break;
      case Kind::u8: value = static_cast<Value>(static_cast<std::uint8_t>(bits)); break;
      case Kind::i16: value = static_cast<Value>(static_cast<std::int16_t>(bits)); break;
      case Kind::u16: value = static_cast<Value>(static_cast<std::uint16_t>(bits)); break;
      case Kind::i32: value = static_cast<Value>(static_cast<std::int32_t>(bits)); break;
      case Kind::u32: value = static_cast<Value>(static_cast<std::uint32_t>(bits)); break;
      case Kind::i64: value = static_cast<Value>(static_cast<std::int64_t>(bits)); break;
      case Kind::u64:
        if (bits > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()) && std::is_integral_v<Value>)
          fail_here("value " + std::to_string(i + 1) + " is out of range: " + std::to_string(bits));
        value = static_cast<Value>(bits);
        break;
      case Kind::f32: {
        float f;
        const auto raw = static_cast<std::uint32_t>(bits);
        std::memcpy(&f, &raw, sizeof f);
        value = static_cast<Value>(f);
        break;
      }
      case Kind::f64: {
        double d;
        std::memcpy(&d, &bits, sizeof d);
        value = static_cast<Value>(d);
        break;
      }
    }
    out.push_back(value);
  }
  return out;
}

}  // namespace

std::vector<double> VtkXmlArrays::reals(const XmlElement& array, std::optional<std::uint64_t> count) {
  return values<double>(array, count);
}

std::vector<std::int64_t> VtkXmlArrays::integers(const XmlElement& array, std::optional<std::uint64_t> count) {
  return values<std::int64_t>(array, count);
}

template <class Value>
std::vector<Value> VtkXmlArrays::values(const XmlElement& array, std::optional<std::uint64_t> count) {
  const ArrayFailure fail_here(file_, array);
  const std::string_view type_name = array.attribute("type").value_or("");
  const std::optional<ValueType> type = value_type(type_name);
  if (!type) fail_here("type " + shown(type_name) + " is not a numeric type");
  if (std::is_integral_v<Value> && type->real) fail_here("type " + std::string(type_name) + " is not an integer type");

  const std::string_view format = array.attribute("format").value_or("");
  if (format == "ascii") return ascii_values<Value>(array.text, *type, count, fail_here);
  const BinarySource source = binary_source(array, format, encoding_, fail_here);
  ByteCursor cursor(source.bytes, source.base64);
  const std::string data = BinaryArrayReader(cursor, encoding_, *type, type_name, count, fail_here).data();
  if (format == "appended") {
    appended_used_ += cursor.consumed();
    if (appended_used_ > encoding_.appended.size())
      fail_here("appended arrays overlap: together they use more than the " +
                std::to_string(encoding_.appended.size()) + " bytes of appended data");
  }
  return binary_values<Value>(data, *type, encoding_.big_endian, fail_here);
}

}  // namespace molsurf::mesh_io
