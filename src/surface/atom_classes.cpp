#include "molsurf/atom_classes.hpp"

#include <stdexcept>

#include "molsurf/relative_area.hpp"

namespace molsurf {

bool is_polar(const Atom& atom) {
  if (atom.polarity != Polarity::by_element) return atom.polarity == Polarity::polar;
  return atom.element == "N" || atom.element == "O";
}

bool is_amino_acid(const Atom& atom) { return max_residue_area(atom.residue_name).has_value(); }

bool is_main_chain(const Atom& atom) {
  const std::string& n = atom.atom_name;
  return is_amino_acid(atom) && (n == "N" || n == "CA" || n == "C" || n == "O" || n == "OXT");
}

ClassAreas class_areas(std::span<const Atom> atoms, std::span<const double> atom_area) {
  if (atoms.size() != atom_area.size()) throw std::invalid_argument("class_areas: one area per atom");
  ClassAreas c;
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    (is_polar(atoms[i]) ? c.polar : c.apolar) += atom_area[i];
    if (is_amino_acid(atoms[i])) (is_main_chain(atoms[i]) ? c.main_chain : c.side_chain) += atom_area[i];
  }
  return c;
}

}  // namespace molsurf
