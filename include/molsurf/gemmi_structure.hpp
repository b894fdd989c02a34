#pragma once
// Atoms from a structure gemmi already holds in memory: a gemmi::Structure built by a
// program, or the object behind a gemmi.Structure of gemmi's Python module (the molsurf
// Python module passes it here without writing a file). The same selection rules and
// radii as read_structure() apply, so a structure gives the same atoms as its file.
//
// Only a declaration of gemmi::Structure is needed here: gemmi's headers are slow to
// compile, and a caller that has a gemmi::Structure includes them already.
#include <filesystem>

#include "molsurf/atoms.hpp"

namespace gemmi {
struct Structure;
}

namespace molsurf {

// The chosen model's atoms, selected and given radii as `options` say (radius_set or
// radius_file; the format's own radii do not exist here). `source` names the structure in
// messages and in the report's `file`; empty: the structure's name. The report's format is
// pdb when gemmi read the structure from PDB, mmcif otherwise. Throws molsurf::Error as
// read_structure() does (no models, no atoms left after filtering, unknown model number).
Structure structure_from_gemmi(const gemmi::Structure& structure, const ReadOptions& options = {},
                               const std::filesystem::path& source = {});

}  // namespace molsurf
