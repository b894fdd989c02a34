// consumer STRUCTURE MESH: the solvent-accessible surface of STRUCTURE written to MESH;
// prints the version, the exact area and the mesh's face count.
#include <cstdio>

#include "molsurf/atoms.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/io.hpp"

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  const molsurf::Structure structure = molsurf::read_structure(argv[1]);
  const molsurf::ComputedSurface surface = molsurf::compute_surface(structure.atoms);
  molsurf::write_mesh(argv[2], surface.mesh);
  std::printf("%s %.17g %zu\n", MOLSURF_VERSION, surface.exact.area, surface.mesh.faces.size());
}
