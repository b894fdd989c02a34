// libFuzzer target for one structure reader, chosen at build time by MOLSURF_FUZZ_FILE
// (the scratch file's name: its extension picks the reader, as for a user's file).
// The input goes through read_structure(), the entry point the CLI uses, so the selection
// rules and radius assignment are fuzzed with the gemmi-backed and our own readers.
// molsurf::Error is the one allowed outcome besides a structure: any other exception,
// a crash or a sanitizer report is a finding.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/error.hpp"

#ifndef MOLSURF_FUZZ_FILE
#error "define MOLSURF_FUZZ_FILE, e.g. \"input.pdb\""
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const molsurf::fuzz::FuzzInputFile input(MOLSURF_FUZZ_FILE);
  molsurf::fuzz::FuzzInputFile::write(input.path(), data, size);
  try {
    const molsurf::Structure structure = molsurf::read_structure(input.path());
    (void)structure;
  } catch (const molsurf::Error&) {
    // a clear error is a correct answer to a broken file
  }
  return 0;
}
