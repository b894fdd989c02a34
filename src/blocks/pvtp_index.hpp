#pragma once
// A surface in pieces on disk: each block's piece NAME_K.vtp beside NAME.pvtp, the index
// with which ParaView (VTK's XML parallel reader) opens the pieces as one surface; when the
// pieces were streamed, the seams' faces as one more piece, NAME_seams.vtp.
#include <cstddef>
#include <filesystem>
#include <string>

namespace molsurf::blocks {

// Block `block`'s piece of the surface indexed by `index` (NAME.pvtp): NAME_K.vtp beside it.
std::filesystem::path piece_path(const std::filesystem::path& index, std::size_t block);

// The seams' piece of the surface indexed by `index`: NAME_seams.vtp beside it.
std::filesystem::path seams_path(const std::filesystem::path& index);

// The index's text for `pieces` block pieces (and the seams' piece after them, `with_seams`)
// written as molsurf writes a surface's .vtp (points, normals, each face's atom: tag,
// serial, residue, chain), named relative to the index.
std::string pvtp_index(const std::filesystem::path& index, std::size_t pieces, bool with_seams = false);

}  // namespace molsurf::blocks
