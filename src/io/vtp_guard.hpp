#pragma once
// Internal: the size checks a .vtp file must pass before VTK's XML reader sees it
// (vtp_guard.cpp says which and why).
#include <filesystem>
#include <string>

namespace molsurf::mesh_io {

// Throws molsurf::Error ("FILE: problem") when a declared size does not fit the file.
void check_vtp_sizes(const std::filesystem::path& file, const std::string& bytes);

}  // namespace molsurf::mesh_io
