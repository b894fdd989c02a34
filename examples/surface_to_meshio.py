#!/usr/bin/env python3
"""A molecular surface handed to a boundary-element code as arrays, through meshio.

The surface's vertices (angstrom) and faces go into a meshio.Mesh as they are; each triangle
carries the atom it lies on (1-based, as gmsh wants positive tags) as its physical group, so a
solver can assign per-atom boundary data. The mesh is written as a gmsh 2.2 .msh file.

    PYTHONPATH=build/release/python python3 examples/surface_to_meshio.py [STRUCTURE [OUT.msh]]

Defaults: data/pdb/1crn.pdb, writing 1crn.msh in the current directory.
"""
import pathlib
import sys

import meshio
import numpy as np

import molsurf


def main(argv):
    root = pathlib.Path(__file__).resolve().parents[1]
    path = pathlib.Path(argv[1]) if len(argv) > 1 else root / "data" / "pdb" / "1crn.pdb"
    out = argv[2] if len(argv) > 2 else path.name.split(".")[0] + ".msh"

    surface = molsurf.surface(path)  # closed, 2-manifold, outward: what a BEM solver needs
    atom = surface.atom_of_face.astype(np.int32) + 1
    mesh = meshio.Mesh(points=surface.vertices, cells=[("triangle", surface.faces)],
                       cell_data={"gmsh:physical": [atom], "gmsh:geometrical": [atom]})
    meshio.write(out, mesh, file_format="gmsh22", binary=False)
    # facet_*: the triangles' own measures (what the solver integrates over); area, volume: the
    # true spheres', exact.
    print(f"{path.name}: {len(surface.vertices)} vertices, {len(surface.faces)} triangles, "
          f"area {surface.facet_area:.2f} Å², volume {surface.facet_volume:.2f} Å³ "
          f"(true spheres: {surface.area:.2f} Å², {surface.volume:.2f} Å³)")
    print(f"written: {out}")


if __name__ == "__main__":
    main(sys.argv)
