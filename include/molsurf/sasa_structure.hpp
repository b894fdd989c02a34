#pragma once
// The structure with each atom's solvent-accessible area in its B-factor column and its
// radius in the occupancy column, as FreeSASA's --format=pdb writes it: a file that
// molecular viewers colour by exposure. PDB or mmCIF, written through gemmi.
#include <filesystem>
#include <span>
#include <string>

#include "molsurf/atoms.hpp"

namespace molsurf {

// The file's text for `path`'s extension (.pdb, .ent: PDB; .cif, .mmcif: mmCIF); one atom
// record per atom of `atoms`, in order, B-factor = area[i], occupancy = radius.
// Throws molsurf::Error for another extension.
std::string sasa_structure_text(const std::filesystem::path& path, std::span<const Atom> atoms,
                                std::span<const double> area);

// Whether `path` names a format sasa_structure_text writes.
bool is_sasa_structure_path(const std::filesystem::path& path);

}  // namespace molsurf
