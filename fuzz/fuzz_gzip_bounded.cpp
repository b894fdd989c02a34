// libFuzzer target for the bounded decompression of a gzipped structure: read_structure()
// under a memory limit that allows 1 MiB of text, so that the deflate ratio (up to about
// 1000:1) lets inputs of -max_len bytes cross the bound. The promise is the same as the
// other readers': a structure or one molsurf::Error, and memory bounded by the limit
// whatever the input's size fields say.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/error.hpp"
#include "molsurf/resource_limits.hpp"

#ifndef MOLSURF_FUZZ_FILE
#error "define MOLSURF_FUZZ_FILE, e.g. \"input.pdb.gz\""
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const molsurf::fuzz::FuzzInputFile input(MOLSURF_FUZZ_FILE);
  molsurf::fuzz::FuzzInputFile::write(input.path(), data, size);
  molsurf::ReadOptions options;
  options.max_memory = molsurf::kBytesPerTextByte << 20;
  try {
    const molsurf::Structure structure = molsurf::read_structure(input.path(), options);
    (void)structure;
  } catch (const molsurf::Error&) {
    // a clear error (the bound among them) is a correct answer
  }
  return 0;
}
