#pragma once
// Areas by atom class, as FreeSASA reports them: polar against apolar, as the radius table
// classes the atom (the built-in protor set as FreeSASA's: carbon apolar, the rest polar; a
// FreeSASA configuration's types), or by element where it gives no class (nitrogen and
// oxygen polar); and, for the twenty amino acids, main chain (N, CA, C, O, OXT) against
// side chain.
#include <span>

#include "molsurf/atoms.hpp"

namespace molsurf {

struct ClassAreas {
  double polar = 0, apolar = 0;          // every atom is one or the other
  double main_chain = 0, side_chain = 0;  // amino-acid atoms only
};

bool is_polar(const Atom& atom);
bool is_main_chain(const Atom& atom);  // of an amino acid
bool is_amino_acid(const Atom& atom);

ClassAreas class_areas(std::span<const Atom> atoms, std::span<const double> atom_area);

}  // namespace molsurf
