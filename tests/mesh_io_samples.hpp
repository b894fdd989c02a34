#pragma once
// Meshes and atoms the mesh I/O tests write and read back (test_mesh_io, test_mesh_vtp).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/icosphere.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/mesh.hpp"

namespace molsurf::testing {

// A closed sphere made of several atoms' patches: tag = face index mod 3.
inline Mesh tagged_sphere() {
  Mesh mesh = make_icosphere({1.1, -2.3, 0.7}, 1.7, IcosphereOptions{.frequency = 4, .tag = 0});
  for (std::size_t f = 0; f < mesh.face_count(); ++f) mesh.face_tags[f] = static_cast<std::int32_t>(f % 3);
  return mesh;
}

// Three atoms with serials, residues and chains (one chain name of two letters).
inline std::vector<Atom> three_atoms() {
  std::vector<Atom> atoms(3);
  const char* residues[] = {"ALA", "GLY", "HEM"};
  const char* chains[] = {"A", "B", "AB"};
  for (int i = 0; i < 3; ++i) {
    atoms[i].centre = {1.1 + 0.1 * i, -2.3, 0.7};
    atoms[i].radius = 1.5 + 0.1 * i;
    atoms[i].serial = 100 + i;
    atoms[i].residue_number = 7 * (i + 1);
    atoms[i].residue_name = residues[i];
    atoms[i].chain = chains[i];
  }
  return atoms;
}

}  // namespace molsurf::testing
