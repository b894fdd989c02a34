#pragma once
// What users study on a surface: area and volume per component (outer surface and
// cavities), per atom and per residue.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/sphere_arrangement.hpp"

namespace molsurf {

struct ComponentMeasure {
  std::size_t faces = 0;
  double area = 0;
  double volume = 0;  // signed: negative for a cavity (its faces point into it)
  bool cavity() const { return volume < 0; }
};

// Components by shared vertices; the largest outer surface first, then by area.
std::vector<ComponentMeasure> measure_components(const Mesh& mesh);

// The volume the components enclose: the outer surfaces' less the cavities', each measured
// about its own vertex, where rounding stays in proportion to the component (the whole
// mesh's signed volume about its box centre loses 1e-3 of two crambins 1e6 A apart).
double enclosed_volume(std::span<const ComponentMeasure> components);

// Each of the mesh's components (in measure_components' order) matched to the shell of the
// arrangement it follows: the shell that most of its area's atoms line, each face voting
// with its area for its atom's shell when the atom lines one shell only; -1 when no face
// votes.
std::vector<std::int64_t> shells_of_components(const Mesh& mesh, const SphereArrangement& arrangement);

// The same for components given by the atoms of their faces (each list in any order, with
// repeats; sorted and made unique here), in the order given: for a surface measured in
// parts (the streamed blocks, whose components are joined from pieces).
std::vector<std::int64_t> shells_of_atom_sets(std::span<std::vector<std::uint32_t>> atoms_of,
                                              const SphereArrangement& arrangement);

// Both at once (the components found and measured once).
struct MeshComponentsAndShells {
  std::vector<ComponentMeasure> components;
  std::vector<std::int64_t> shells;
};
MeshComponentsAndShells measure_components_and_shells(const Mesh& mesh, const SphereArrangement& arrangement);

// The mesh without its cavities (components of negative volume).
Mesh outer_surface_only(const Mesh& mesh);

// Area of the faces tagged with each atom (faces tagged outside [0, atom_count) are ignored).
std::vector<double> area_per_atom(const Mesh& mesh, std::size_t atom_count);

// One residue's share of the surface: the summed area of its atoms.
struct ResidueArea {
  std::string chain;
  std::string residue_name;
  std::int64_t residue_number = 0;  // mmCIF allows any integer; no wrap at 32 bits
  char insertion_code = ' ';
  std::size_t atoms = 0;  // atoms of the structure in this residue (buried ones too)
  double area = 0;        // square angstrom
};

// Residues (same chain, number, insertion code and name) in order of first appearance,
// with the summed `atom_area` of their atoms (one value per atom, as area_per_atom gives).
std::vector<ResidueArea> area_per_residue(std::span<const Atom> atoms, std::span<const double> atom_area);

// One chain's share of the surface.
struct ChainArea {
  std::string chain;
  std::size_t atoms = 0, residues = 0;
  double area = 0;  // square angstrom
};

// Chains in order of first appearance, with the summed `atom_area` of their atoms.
std::vector<ChainArea> area_per_chain(std::span<const Atom> atoms, std::span<const double> atom_area);

}  // namespace molsurf
