#pragma once
// Every block's piece on the first process, whether one process makes them all or several
// share them (process r makes blocks r, r + size, ...). The glued and the streamed jobs
// differ only in what a piece holds and how it travels as bytes; this is where the blocks are
// dealt out and the answers gathered and sorted, once for both.
#include <algorithm>
#include <cstddef>
#include <exception>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "blocks/block_exchange.hpp"
#include "blocks/spilled_bytes.hpp"
#include "molsurf/error.hpp"

namespace molsurf::blocks {

// `make(b)` makes block b's piece, `append(bytes, piece)` writes it as bytes and `read(bytes)`
// reads back what append wrote; `made(done)` is told after each block made here. Returns the
// pieces in block order on the first process (or on a process alone), nothing on the others.
// A piece that failed on any process throws molsurf::Error on the first, naming the process.
// With `on_disk`, a process alone keeps each piece as bytes in a temporary file until every
// block is made, so that it never holds one block's work and the pieces before it at once.
template <class Piece, class Make, class Append, class Read, class Made>
std::optional<std::vector<Piece>> pieces_of_all_blocks(std::size_t blocks, BlockExchange* exchange, Make&& make,
                                                       Append&& append, Read&& read, Made&& made,
                                                       bool on_disk = false) {
  std::vector<Piece> pieces;
  if (exchange == nullptr || exchange->size() <= 1) {
    if (!on_disk) {
      for (std::size_t b = 0; b < blocks; ++b) {
        pieces.push_back(make(b));
        made(b + 1);
      }
      return pieces;
    }
    SpilledBytes disk;
    for (std::size_t b = 0; b < blocks; ++b) {
      std::string bytes;
      append(bytes, make(b));
      disk.push(bytes);
      made(b + 1);
    }
    for (std::size_t b = 0; b < blocks; ++b)
      for (Piece& p : read(disk.read(b))) pieces.push_back(std::move(p));
    return pieces;
  }
  // What a process sends: "P" and its pieces, or "E" and what went wrong.
  std::string bytes = "P";
  try {
    for (std::size_t b = static_cast<std::size_t>(exchange->rank()); b < blocks;
         b += static_cast<std::size_t>(exchange->size()))
      append(bytes, make(b));
  } catch (const std::exception& e) {
    bytes = std::string("E") + e.what();
  }
  std::vector<std::string> gathered = exchange->gather(bytes);
  bytes = std::string{};
  if (exchange->rank() != 0) return std::nullopt;
  for (std::size_t k = 0; k < gathered.size(); ++k) {
    const std::string_view b = gathered[k];
    if (b.empty() || b[0] != 'P')
      throw Error("process " + std::to_string(k) + " of " + std::to_string(gathered.size()) + ": " +
                  std::string(b.empty() ? "no answer" : b.substr(1)));
    for (Piece& p : read(b.substr(1))) pieces.push_back(std::move(p));
    // Each process's bytes go once read: the pieces and all their bytes never add up.
    gathered[k] = std::string{};
  }
  std::sort(pieces.begin(), pieces.end(), [](const Piece& x, const Piece& y) { return x.block < y.block; });
  made(blocks);
  return pieces;
}

}  // namespace molsurf::blocks
