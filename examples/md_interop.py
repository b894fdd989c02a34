#!/usr/bin/env python3
"""SASA along a trajectory held by MDTraj or MDAnalysis: their frames, molsurf's exact areas.

Both libraries hold a topology and frames; molsurf.areas() needs one radius per atom and the
coordinates in angstrom, shaped (frames, atoms, 3). The radii come from molsurf's own tables
(ProtOr by default): molsurf.read_structure reads the topology file with every atom kept
(hydrogens, water, hetero atoms), so its atoms are the trajectory's, in the same order.

    PYTHONPATH=build/release/python python3 examples/md_interop.py [STRUCTURE] [--engine mdtraj|mdanalysis|both]

Default: data/pdb/1j8k.cif's 20 NMR models, written as a multi-model PDB file that both libraries
read as a trajectory (a stand-in for a topology plus a DCD or XTC file). MDTraj (python3-mdtraj)
and MDAnalysis (python3-mdanalysis) are Debian packages; the example uses whichever is installed.
"""
import argparse
import pathlib
import tempfile

import numpy as np

import gemmi
import molsurf


def radii_for(topology_file):
    """molsurf's radius (A, without the probe) and element for every atom of the file, in file order."""
    st = molsurf.read_structure(topology_file, hydrogens=True, keep_water=True, hetatm=True)
    return st.radii, [e.upper() for e in st.elements]


def mdtraj_frames(path):
    import mdtraj
    traj = mdtraj.load(str(path))
    elements = [atom.element.symbol.upper() for atom in traj.topology.atoms]
    return traj.xyz.astype(np.float64) * 10, elements  # nm -> A


def mdanalysis_frames(path):
    import MDAnalysis
    universe = MDAnalysis.Universe(str(path))
    frames = np.stack([universe.atoms.positions.astype(np.float64) for _ in universe.trajectory])  # A
    return frames, [e.upper() for e in universe.atoms.elements]


ENGINES = {"mdtraj": mdtraj_frames, "mdanalysis": mdanalysis_frames}


def available(engine):
    try:
        __import__({"mdtraj": "mdtraj", "mdanalysis": "MDAnalysis"}[engine])
        return True
    except ImportError:
        return False


def main():
    root = pathlib.Path(__file__).resolve().parents[1]
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("structure", nargs="?", type=pathlib.Path, default=root / "data" / "pdb" / "1j8k.cif")
    parser.add_argument("--engine", choices=["mdtraj", "mdanalysis", "both"], default="both")
    parser.add_argument("--probe", type=float, default=1.4)
    args = parser.parse_args()

    engines = [e for e in (["mdtraj", "mdanalysis"] if args.engine == "both" else [args.engine]) if available(e)]
    if not engines:
        print("neither MDTraj nor MDAnalysis is installed (Debian: python3-mdtraj, python3-mdanalysis)")
        return
    with tempfile.TemporaryDirectory() as tmp:
        pdb = pathlib.Path(tmp) / (args.structure.name.split(".")[0] + ".pdb")
        structure = gemmi.read_structure(str(args.structure))
        structure.setup_entities()
        structure.write_pdb(str(pdb))
        radii, elements = radii_for(pdb)
        results = {}
        for engine in engines:
            # MDTraj renames hydrogens to its standard names: the atoms are matched by element.
            xyz, engine_elements = ENGINES[engine](pdb)
            if list(engine_elements) != list(elements):
                raise SystemExit(f"{engine}: its atoms are not molsurf's (read with every atom kept)")
            results[engine] = molsurf.areas(coords=xyz, radii=radii, probe=args.probe)
    first = results[engines[0]]
    print(f"{args.structure.name}: {first.frames} frames, {first.atoms} atoms (hydrogens included), "
          f"probe {args.probe} A")
    print("frame  " + "  ".join(f"{e + ' SASA (A^2)':>20}" for e in engines))
    for f in range(first.frames):
        print(f"{f:5d}  " + "  ".join(f"{results[e].area[f]:20.2f}" for e in engines))
    if len(engines) == 2:
        gap = np.max(np.abs(results["mdtraj"].area_per_atom - results["mdanalysis"].area_per_atom))
        print(f"largest per-atom difference between the two readers: {gap:.2e} A^2 (float32 coordinates)")


if __name__ == "__main__":
    main()
