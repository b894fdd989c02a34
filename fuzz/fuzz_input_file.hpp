#pragma once
// molsurf's readers take paths (the format follows the extension, and gemmi opens
// files itself), so each fuzz input is written to a scratch file first. One per
// process: libFuzzer runs inputs one after another in a process, and `-jobs`/`-fork`
// workers are separate processes with their own pid.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

namespace molsurf::fuzz {

class FuzzInputFile {
 public:
  // `name` is the file name to use, e.g. "input.pdb.gz" or "input.vert".
  explicit FuzzInputFile(std::string_view name)
      : directory_(std::filesystem::temp_directory_path() / ("molsurf-fuzz-" + std::to_string(::getpid()))),
        path_(directory_ / name) {
    std::filesystem::create_directories(directory_);
  }
  FuzzInputFile(const FuzzInputFile&) = delete;
  FuzzInputFile& operator=(const FuzzInputFile&) = delete;
  ~FuzzInputFile() {
    std::error_code ignored;
    std::filesystem::remove_all(directory_, ignored);
  }

  const std::filesystem::path& path() const { return path_; }
  // A sibling in the same scratch directory (MSMS's .face beside the .vert).
  std::filesystem::path sibling(std::string_view name) const { return directory_ / name; }

  static void write(const std::filesystem::path& file, const std::uint8_t* data, std::size_t size) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }

 private:
  std::filesystem::path directory_;
  std::filesystem::path path_;
};

}  // namespace molsurf::fuzz
