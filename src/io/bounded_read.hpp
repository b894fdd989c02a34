#pragma once
// Internal: the bytes of an input file, read only when they fit. A structure read holds
// its text, and gemmi's document and structure built from it, at once (about
// kBytesPerTextByte bytes per byte of text), so the text is bounded by the memory limit
// before it is read, or, for gzip, as it is decompressed: a gzip bomb stops with one
// message at the bound instead of growing until an allocation fails. Devices, pipes and
// sockets are refused: /dev/zero has no end to bound, and a regular file's size is known
// before it is read.
#include <cstdint>
#include <filesystem>
#include <string>

namespace molsurf::detail {

// Fails unless `path` (followed through links) is a regular file: "file not found",
// "is a directory, not a file", or "is a device, pipe or socket, not a regular file".
void require_regular_file(const std::filesystem::path& path);

// The whole file, refused before it is read when it holds more than `max_text_bytes`.
std::string read_file_bytes(const std::filesystem::path& path, std::uint64_t max_text_bytes);
// The same for a text file, normalised (text_fields.hpp: no byte-order mark, no CR-only
// line ends).
std::string read_text_file(const std::filesystem::path& path, std::uint64_t max_text_bytes);

// The whole decompressed content of a gzip file (members concatenated, as gzip -d does),
// refused as soon as it passes `max_text_bytes`; normalised as read_text_file's.
std::string read_gzip_file(const std::filesystem::path& path, std::uint64_t max_text_bytes);

// The text bound for a read under a memory limit of `max_memory` bytes (0: the memory
// this process may use).
std::uint64_t max_text_bytes(std::uint64_t max_memory);

}  // namespace molsurf::detail
