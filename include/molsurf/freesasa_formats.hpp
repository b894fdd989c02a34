#pragma once
// FreeSASA's text outputs, for the scripts that already parse them (`--format rsa|seq|res`):
// the same layout, filled with molsurf's per-atom areas.
#include <optional>
#include <span>
#include <string>

#include "molsurf/atoms.hpp"
#include "molsurf/relative_area.hpp"

namespace molsurf {

// What the header lines of an RSA file say about the run.
struct RsaHeader {
  std::string source;  // the structure file
  std::string radii;   // the radius set or table
  double probe = 1.4;
  MaxAreaScale scale = MaxAreaScale::theoretical;
};

// NACCESS's .rsa layout as FreeSASA writes it: one RES line per residue with the absolute
// area of all atoms, the side chain, the main chain, the apolar and the polar atoms, each
// with a relative value; then one CHAIN line per chain and a TOTAL line. The all-atom
// relative value is the area over Tien et al. 2013's maximum (relative_area.hpp); the class
// columns' relative values, which need a reference area per class, and any value for a
// residue without a maximum, are N/A.
std::string rsa_text(std::span<const Atom> atoms, std::span<const double> atom_area, const RsaHeader& header);

// FreeSASA's `seq` format: one line per residue (chain, number, name, area).
std::string residue_sequence_text(std::span<const Atom> atoms, std::span<const double> atom_area,
                                  const std::string& source);

// FreeSASA's `res` format: the area summed per residue type, the twenty amino acids always
// listed, then any other type present, in alphabetical order.
std::string residue_type_text(std::span<const Atom> atoms, std::span<const double> atom_area,
                              const std::string& source);

}  // namespace molsurf
