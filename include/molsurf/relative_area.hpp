#pragma once
// Relative solvent accessibility: a residue's area over the largest area that residue type
// shows, from Tien, Meyer, Sydykova, Spielman and Wilke, "Maximum allowed solvent
// accessibilities of residues in proteins", PLoS ONE 8 (2013) e80635: the theoretical
// maxima (Gly-X-Gly tripeptides in their most exposed allowed conformation; the default) or
// the empirical ones (the largest seen in their set of structures).
#include <optional>
#include <string_view>

namespace molsurf {

enum class MaxAreaScale { theoretical, empirical };

// The maximum area (A^2) of a standard amino acid by its three-letter name (upper case);
// none for other residues (ligands, nucleotides, water, modified residues).
std::optional<double> max_residue_area(std::string_view residue_name, MaxAreaScale scale = MaxAreaScale::theoretical);

}  // namespace molsurf
