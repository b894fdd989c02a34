// libFuzzer target for one mesh reader, chosen at build time by MOLSURF_FUZZ_FILE (the
// scratch file's name: its extension picks the reader). What `molsurf check FILE` does:
// read_mesh(), then check_mesh() on what was read (small meshes only, so the fuzzer stays
// fast), so the check's exact predicates also meet hostile coordinates.
// MSMS is a pair of files: the input is split at its first NUL byte into .vert and .face.
// molsurf::Error is the one allowed outcome besides a mesh: any other exception, a crash
// or a sanitizer report is a finding.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_input_file.hpp"
#include "molsurf/error.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh_check.hpp"

#ifndef MOLSURF_FUZZ_FILE
#error "define MOLSURF_FUZZ_FILE, e.g. \"input.ply\""
#endif

namespace {

constexpr std::size_t kMaxCheckedFaces = 4096;

bool is_msms(std::string_view name) { return name.ends_with(".vert"); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const molsurf::fuzz::FuzzInputFile input(MOLSURF_FUZZ_FILE);
  if (is_msms(MOLSURF_FUZZ_FILE)) {
    const std::uint8_t* split = std::find(data, data + size, std::uint8_t{0});
    molsurf::fuzz::FuzzInputFile::write(input.path(), data, static_cast<std::size_t>(split - data));
    const std::uint8_t* face = split == data + size ? split : split + 1;
    molsurf::fuzz::FuzzInputFile::write(input.sibling("input.face"), face, static_cast<std::size_t>(data + size - face));
  } else {
    molsurf::fuzz::FuzzInputFile::write(input.path(), data, size);
  }
  try {
    const molsurf::Mesh mesh = molsurf::read_mesh(input.path());
    if (mesh.face_count() <= kMaxCheckedFaces) (void)molsurf::check_mesh(mesh);
  } catch (const molsurf::Error&) {
    // a clear error is a correct answer to a broken file
  }
  return 0;
}
