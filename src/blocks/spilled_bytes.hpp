#pragma once
// Records of bytes kept in a temporary file instead of memory: what one process keeps of each
// block for the seams' join (`--blocks N` streamed) waits there while the next blocks are
// made, so that while they are made the process holds one block, not the blocks before it.
// The file lies in the temporary directory (TMPDIR, else /tmp) and loses its name as soon as
// it is made: it goes with the process, however the process ends.
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace molsurf::blocks {

class SpilledBytes {
 public:
  SpilledBytes();
  ~SpilledBytes();
  SpilledBytes(const SpilledBytes&) = delete;
  SpilledBytes& operator=(const SpilledBytes&) = delete;

  // Appends `bytes` as the next record (molsurf::Error when the disk refuses them).
  void push(std::string_view bytes);
  std::size_t size() const { return records_.size(); }
  // Record k, read back.
  std::string read(std::size_t k) const;

 private:
  int fd_ = -1;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> records_;  // offset and length of each
  std::uint64_t end_ = 0;
};

}  // namespace molsurf::blocks
