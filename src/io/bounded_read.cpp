#include "io/bounded_read.hpp"

#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <system_error>

#include "common/size_text.hpp"
#include "io/text_fields.hpp"
#include "molsurf/error.hpp"
#include "molsurf/resource_limits.hpp"

namespace molsurf::detail {

namespace {

[[noreturn]] void fail_too_large(const std::filesystem::path& path, const std::string& what,
                                 std::uint64_t max_text_bytes) {
  const std::uint64_t memory = max_text_bytes > UINT64_MAX / kBytesPerTextByte ? UINT64_MAX
                                                                                 : max_text_bytes * kBytesPerTextByte;
  fail(path, what + " of text; a structure read may hold " + gigabytes_text(max_text_bytes) +
                 " under the memory limit of " + gigabytes_text(memory) + " (about " +
                 std::to_string(kBytesPerTextByte) +
                 " bytes of memory per byte of text): a gzip bomb or a damaged file? raise the limit with --max-memory");
}

}  // namespace

void require_regular_file(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (status.type() == std::filesystem::file_type::not_found) fail(path, "file not found");
  if (status.type() == std::filesystem::file_type::directory) fail(path, "is a directory, not a file");
  // Unknown status (a permission error on the way) is left to the open, which says why.
  if (!ec && status.type() != std::filesystem::file_type::regular)
    fail(path, "cannot read: it is a device, pipe or socket, not a regular file; give a file");
}

std::uint64_t max_text_bytes(std::uint64_t max_memory) {
  return (max_memory > 0 ? max_memory : available_memory_bytes()) / kBytesPerTextByte;
}

std::string read_text_file(const std::filesystem::path& path, std::uint64_t max_text_bytes) {
  std::string text = read_file_bytes(path, max_text_bytes);
  text::normalize_text(text);
  return text;
}

std::string read_file_bytes(const std::filesystem::path& path, std::uint64_t max_text_bytes) {
  require_regular_file(path);
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open file") + (errno ? std::string(": ") + std::strerror(errno) : ""));
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > max_text_bytes) fail_too_large(path, "the file holds " + gigabytes_text(size), max_text_bytes);
  std::string text(ec ? 0 : size, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad() || static_cast<std::size_t>(in.gcount()) != text.size()) fail(path, "read error");
  return text;
}

// Our own loop rather than gemmi's: gemmi sizes its buffer from the gzip trailer, which
// a truncated file does not have (and a hostile one can set to anything).
std::string read_gzip_file(const std::filesystem::path& path, std::uint64_t max_text_bytes) {
  const std::string compressed = read_file_bytes(path, max_text_bytes);
  std::string text;
  z_stream stream{};
  if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK) fail(path, "cannot start gzip decompression");
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
  stream.avail_in = static_cast<uInt>(std::min<std::size_t>(compressed.size(), UINT32_MAX));
  std::size_t fed = stream.avail_in;
  char chunk[1 << 16];
  int status = Z_OK;
  while (true) {
    stream.next_out = reinterpret_cast<Bytef*>(chunk);
    stream.avail_out = sizeof chunk;
    status = inflate(&stream, Z_NO_FLUSH);
    const std::size_t produced = sizeof chunk - stream.avail_out;
    if (text.size() + produced > max_text_bytes) {
      inflateEnd(&stream);
      fail_too_large(path, "decompressed, the file holds more than " + gigabytes_text(text.size()),
                     max_text_bytes);
    }
    text.append(chunk, produced);
    if (stream.avail_in == 0 && fed < compressed.size()) {
      const std::size_t more = std::min<std::size_t>(compressed.size() - fed, UINT32_MAX);
      stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data() + fed));
      stream.avail_in = static_cast<uInt>(more);
      fed += more;
    }
    if (status == Z_STREAM_END) {
      // Another gzip member may follow; trailing zero padding is allowed as gzip allows it.
      const std::size_t used = fed - stream.avail_in;
      const bool more_members = used < compressed.size() && compressed[used] == '\x1f';
      if (!more_members) break;
      inflateReset(&stream);
      continue;
    }
    if (status != Z_OK) break;  // with fresh output space, Z_BUF_ERROR means the input ran out
  }
  inflateEnd(&stream);
  if (status == Z_STREAM_END) {
    text::normalize_text(text);
    return text;
  }
  if (status == Z_BUF_ERROR)
    fail(path, "truncated gzip file: the compressed data ends early (after " + std::to_string(text.size()) +
                   " bytes of text); download it again");
  fail(path, "corrupt gzip data (" + std::string(stream.msg ? stream.msg : "zlib error " + std::to_string(status)) +
                 ")");
}

}  // namespace molsurf::detail
