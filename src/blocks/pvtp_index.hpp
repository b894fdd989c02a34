#pragma once
// A surface in pieces on disk: each block's piece NAME_K.vtp beside NAME.pvtp, the index
// with which ParaView (VTK's XML parallel reader) opens the pieces as one surface.
#include <cstddef>
#include <filesystem>
#include <string>

namespace molsurf::blocks {

// Block `block`'s piece of the surface indexed by `index` (NAME.pvtp): NAME_K.vtp beside it.
std::filesystem::path piece_path(const std::filesystem::path& index, std::size_t block);

// The index's text for `pieces` pieces written as molsurf writes a surface's .vtp (points,
// normals, each face's atom: tag, serial, residue, chain), named relative to the index.
std::string pvtp_index(const std::filesystem::path& index, std::size_t pieces);

}  // namespace molsurf::blocks
